#!/usr/bin/python3
"""Phase times of two bfemp builds on the same implicit scenes.

For a code change that should make the implicit solver faster without
changing its results (e.g. the per-cell assembly of the MPM Hessian), this
runs each scene below with a reference build and with the build under test,
alternating them REPEATS times on one thread, and records per run the CPU
time, the Newton iterations and the summed phase times of diagnostics.csv
(assembly, factorization, solve, line search). The ratios (test /
reference) come from the same invocation, so both builds share the
machine's state. The run fails if the two builds do not take the same
Newton iterations or end at different total energies (beyond 1e-9
relative): the change must not alter the computation beyond round-off.

  /usr/bin/python3 benchmarks/compare_builds.py REFERENCE_BUILD TEST_BUILD
      [--scenes twist_full_3_steps,...] [--repeats 2] [--output file]

A build is a folder holding the bfemp executable and its libbfemp.so (e.g.
a copy of build/ from another commit). Writes
benchmarks/results/compare_builds.json (see doc/performance.md).
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

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXPERIMENTS = os.path.join(ROOT, "prm", "experiments")

# name -> (prm, extra entries). twist_full_3_steps: the full-resolution 6.7
# scene (110592 particles, 27 per cell, 24723 unknowns) for three steps of
# 0.1 s, which press the shell into the cube (about 12 Newton iterations
# each).
SCENES = {
    "twist_full_3_steps": (
        os.path.join(EXPERIMENTS, "6_7_twist", "twist_mu0.prm"),
        "subsection run\n  set end time = 0.3\nend\n"
        "subsection time\n  set time step = 0.1\nend\n"
        "subsection output\n  set write particles = false\nend\n"),
    "refinement_N20_ppc4": (
        os.path.join(EXPERIMENTS, "6_5_refinement", "refinement_N20_ppc4.prm"),
        ""),
    "twist_reduced_mu0_5_to_1_3s": (
        os.path.join(EXPERIMENTS, "6_7_twist", "twist_reduced_mu0_5.prm"),
        "subsection run\n  set end time = 1.3\nend\n"),
}
PHASES = ["assembly_time", "factorization_time", "solve_time",
          "line_search_time"]


def run(build, prm, extra, folder):
    wrapper = os.path.join(folder, "scene.prm")
    with open(wrapper, "w") as f:
        f.write("include %s\n%s" % (prm, extra))
        f.write("subsection run\n  set name = run\n  set threads = 1\n"
                "  set quiet = true\nend\n")
        f.write("subsection output\n  set directory = %s\nend\n" % folder)
    env = dict(os.environ, OMP_NUM_THREADS="1",
               LD_LIBRARY_PATH=os.path.abspath(build))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([os.path.join(build, "bfemp"), wrapper], env=env,
                   check=True, stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(folder, "run", "diagnostics.csv")) as f:
        rows = list(csv.DictReader(f))
    result = {
        "cpu_seconds": (after.ru_utime - before.ru_utime) +
                       (after.ru_stime - before.ru_stime),
        "newton_iterations": sum(int(r["newton_iterations"]) for r in rows),
        "total_energy": float(rows[-1]["total_energy"]),
    }
    for phase in PHASES:
        result[phase] = sum(float(r[phase]) for r in rows)
    return result


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("reference")
    parser.add_argument("test")
    parser.add_argument("--scenes", default=",".join(SCENES))
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--output", default=os.path.join(
        ROOT, "benchmarks", "results", "compare_builds.json"))
    args = parser.parse_args()

    results = {"machine": platform.node(), "processor": platform.processor(),
               "cpus": os.cpu_count(), "reference": args.reference,
               "test": args.test, "repeats": args.repeats, "scenes": {}}
    failed = False
    for name in args.scenes.split(","):
        prm, extra = SCENES[name]
        runs = {"reference": [], "test": []}
        for _ in range(args.repeats):
            for which in ("reference", "test"):
                with tempfile.TemporaryDirectory() as folder:
                    runs[which].append(
                        run(getattr(args, which), prm, extra, folder))
        best = {w: min(r, key=lambda x: x["cpu_seconds"])
                for w, r in runs.items()}
        ref, new = best["reference"], best["test"]
        same = (ref["newton_iterations"] == new["newton_iterations"] and
                abs(ref["total_energy"] - new["total_energy"]) <=
                1e-9 * abs(ref["total_energy"]))
        failed = failed or not same
        ratios = {k: new[k] / ref[k] for k in ["cpu_seconds"] + PHASES
                  if ref[k] > 0}
        results["scenes"][name] = {"runs": runs, "best": best,
                                   "ratios_test_over_reference": ratios,
                                   "same_computation": same}
        print("%-28s iterations %d / %d, CPU %.1f / %.1f s (%.2f), "
              "assembly %.1f / %.1f s (%.2f)%s" % (
                  name, ref["newton_iterations"], new["newton_iterations"],
                  ref["cpu_seconds"], new["cpu_seconds"],
                  ratios["cpu_seconds"], ref["assembly_time"],
                  new["assembly_time"], ratios["assembly_time"],
                  "" if same else "  DIFFERENT COMPUTATION"))
        sys.stdout.flush()
    os.makedirs(os.path.dirname(args.output), exist_ok=True)
    with open(args.output + ".part", "w") as f:
        json.dump(results, f, indent=1)
    os.replace(args.output + ".part", args.output)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
