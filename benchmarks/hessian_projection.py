#!/usr/bin/python3
"""Newton iterations and CPU time of 'solver/Hessian projection'.

Runs each implicit scene below twice on one thread, with
'Hessian projection = always' (the projected Newton of BFEMP Section 5:
every local Hessian projected onto the PSD cone) and 'when indefinite' (the
exact Hessian where CHOLMOD finds it positive definite, the projected one
otherwise), and records per run: the CPU time, the Newton iterations, the
iterations that used the projected Hessian, and the largest difference of
any body's final centre of mass between the two runs (both runs converge to
the same Newton tolerance, so that difference should be of its order).

  /usr/bin/python3 benchmarks/hessian_projection.py [--build build] [--quick]
                   [--output file]

writes benchmarks/results/hessian_projection.json (see doc/performance.md).
--quick runs the two smallest scenes only (the ctest smoke run). The run
fails if the two settings end more than TOLERANCE apart in any centre of
mass of a scene that is not chaotic.
"""

import argparse
import csv
import json
import os
import platform
import resource
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXPERIMENTS = os.path.join(ROOT, "prm", "experiments")

# (name, prm, end time or None for the prm's own, whether the final centres
# of mass must agree). The colliding rings are chaotic at this resolution
# (doc/experiments/rings.md): round-off-level changes of the Newton iterates
# move the rings by centimetres, so their difference is reported only.
SCENES = [
    ("demo_implicit", os.path.join(ROOT, "prm", "demo_implicit.prm"), None,
     True),
    ("slope_reduced",
     os.path.join(EXPERIMENTS, "6_4_slope", "slope_reduced.prm"), None, True),
    ("hertz_reduced",
     os.path.join(EXPERIMENTS, "6_3_hertz", "hertz_reduced.prm"), None, True),
    ("rings_reduced",
     os.path.join(EXPERIMENTS, "6_1_rings", "rings_reduced.prm"), None,
     False),
    ("sine_wave_bfemp_reduced",
     os.path.join(EXPERIMENTS, "6_2_sine_wave",
                  "sine_wave_bfemp_reduced.prm"), None, True),
    ("refinement_N20_ppc4",
     os.path.join(EXPERIMENTS, "6_5_refinement", "refinement_N20_ppc4.prm"),
     None, True),
    ("buckling_reduced",
     os.path.join(EXPERIMENTS, "6_6_buckling", "buckling_reduced.prm"), 3.0,
     True),
    ("twist_reduced_mu0_5",
     os.path.join(EXPERIMENTS, "6_7_twist", "twist_reduced_mu0_5.prm"), 1.3,
     True),
]
QUICK = ("demo_implicit", "slope_reduced")
# [m] Both settings stop at the scenes' Newton tolerances (eps_d dt is at
# most 1e-6 m per step here); a larger end difference means the two Hessians
# led to different solutions.
TOLERANCE = 1e-5


def write_prm(folder, name, scene, end_time, projection):
    path = os.path.join(folder, name + ".prm")
    with open(path, "w") as prm:
        prm.write(f"include {scene}\n"
                  f"subsection run\n  set name = {name}\n"
                  f"  set quiet = true\n  set threads = 1\n")
        if end_time is not None:
            prm.write(f"  set end time = {end_time!r}\n")
        prm.write("end\n"
                  f"subsection output\n  set directory = {folder}\n"
                  f"  set write particles = false\n"
                  f"  set write grid = false\nend\n"
                  f"subsection solver\n"
                  f"  set Hessian projection = {projection}\nend\n")
    return path


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def centres_of_mass(path):
    """{column: value} of every body's centre-of-mass coordinate, last row."""
    last = rows(path)[-1]
    return {k: float(v) for k, v in last.items() if "_com_" in k
            and "velocity" not in k}


def run(binary, folder, name, scene, end_time, projection):
    label = f"{name}_{projection.replace(' ', '_')}"
    prm = write_prm(folder, label, scene, end_time, projection)
    env = dict(os.environ, OMP_NUM_THREADS="1")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run([binary, prm], check=True, stdout=subprocess.DEVNULL,
                   env=env)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    diagnostics = rows(os.path.join(folder, label, "diagnostics.csv"))[1:]
    return {
        "projection": projection,
        "steps": len(diagnostics),
        "newton_iterations": sum(int(r["newton_iterations"])
                                 for r in diagnostics),
        "projected_hessians": sum(int(r["projected_hessians"])
                                  for r in diagnostics),
        "max_step_iterations": max(int(r["newton_iterations"])
                                   for r in diagnostics),
        "cpu_seconds": cpu,
        "wall_seconds": wall,
        "centres_of_mass": centres_of_mass(
            os.path.join(folder, label, "bodies.csv")),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--output", default=os.path.join(
        ROOT, "benchmarks", "results", "hessian_projection.json"))
    args = parser.parse_args()
    binary = os.path.join(args.build, "bfemp")
    if not os.access(binary, os.X_OK):
        sys.exit(f"hessian_projection.py: no executable {binary}; build first")

    results = []
    with tempfile.TemporaryDirectory() as folder:
        for name, scene, end_time, compared in SCENES:
            if args.quick and name not in QUICK:
                continue
            always = run(binary, folder, name, scene, end_time, "always")
            exact = run(binary, folder, name, scene, end_time,
                        "when indefinite")
            difference = max(abs(always["centres_of_mass"][k] -
                                 exact["centres_of_mass"][k])
                             for k in always["centres_of_mass"])
            results.append({"scene": name, "end_time": end_time,
                            "compared": compared,
                            "always": always, "when_indefinite": exact,
                            "max_centre_of_mass_difference": difference,
                            "iteration_ratio": exact["newton_iterations"] /
                            always["newton_iterations"],
                            "cpu_ratio": exact["cpu_seconds"] /
                            always["cpu_seconds"]})
            print(f"{name:26s} iterations {always['newton_iterations']:6d} ->"
                  f" {exact['newton_iterations']:6d} (fall-backs "
                  f"{exact['projected_hessians']}), CPU "
                  f"{always['cpu_seconds']:7.1f} -> "
                  f"{exact['cpu_seconds']:7.1f} s, COM difference "
                  f"{difference:.2e} m", flush=True)

    record = {
        "benchmark": "hessian_projection",
        "date": time.strftime("%Y-%m-%d"),
        "quick": args.quick,
        "commit": subprocess.run(["git", "-C", ROOT, "rev-parse", "HEAD"],
                                 capture_output=True, text=True).stdout.strip(),
        "machine": {"processor": platform.processor() or platform.machine(),
                    "cpus": os.cpu_count(), "system": platform.platform()},
        "results": results,
    }
    out = args.output
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    with open(out + ".tmp", "w") as f:
        json.dump(record, f, indent=1)
    os.replace(out + ".tmp", out)
    print("wrote", out)
    worst = max(r["max_centre_of_mass_difference"] for r in results
                if r["compared"])
    if worst > TOLERANCE:
        sys.exit(f"hessian_projection.py: the two settings end {worst:.3e} m "
                 f"apart (more than {TOLERANCE} m)")


if __name__ == "__main__":
    main()
