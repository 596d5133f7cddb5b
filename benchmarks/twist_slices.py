#!/usr/bin/python3
"""Twist slices: the cost of implicit 3D steps of BFEMP Section 6.7 per variant.

Runs the first steps of a twist scene (prm/experiments/6_7_twist/; the
compression with growing frictional contact) once per variant, each variant
a few prm entries changed on top of the scene, and records per run the wall
time, the CPU time, the Newton iterations, the friction updates, the time
split (assembly, factorization, solve, line search, summed over the steps
from the diagnostics) and the end state (elastic energy, contact force),
so that variants can be compared as ratios from the same run and their end
states checked against the baseline's.

  /usr/bin/python3 benchmarks/twist_slices.py [--scene twist_mu0_2]
      [--steps 10] [--start 0] [--variants baseline,loose,threads2,cg]
      [--build build] [--baseline-build OTHER_BUILD] [--output FILE]

--start T (> 0) slices the run at t = T instead of t = 0, for the twist
phase (T = 1: the shell has pressed 0.5 m and starts to turn). The state at
T comes from one run of the scene to T (variant
"material_loose_reuse_ew_threads2"; every variant of the slice starts from
the same state), whose folder with its checkpoint is kept in
<build>/twist_slices/ and reused; an interrupted run to T continues from
its last checkpoint when started again.

--scene is a file name in prm/experiments/6_7_twist/ without .prm
(twist_mu0_2: the paper's resolution, 110592 particles, about 30 s per step
on one thread once in contact; twist_medium_mu0_2: 4096 particles, 2-4 s).
--baseline-build runs the variant "baseline" also with the bfemp of another
build folder (e.g. a worktree of an earlier commit built the same way; its
RUNPATH must name its own libbfemp.so, so build it in place rather than copy
it) and records it as "baseline (other build)"; the ratios are taken against
it when "baseline" itself is not among the variants (without either, against
"full": the full-resolution prm files' solver settings, which the "full_*"
variants change one lever at a time). Writes
benchmarks/results/twist_slices_<scene>.json (see doc/performance.md).
"""

import argparse
import csv
import json
import os
import platform
import shutil
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = os.path.join(ROOT, "prm", "experiments", "6_7_twist")

# name -> {subsection: {entry: value}} on top of the scene. Every variant
# runs on one thread unless it says otherwise, so that variants compare on
# a machine with other load too. "baseline" is the scene with the paper's
# Newton (Algorithm 1 as written, the increment over the unknowns).
# No variant inherits the scene's own 'factorization reuse', 'projected step
# extrapolation' or 'skip failed exact factorizations' unless it names it.
PAPER = {"Newton increment": "unknowns", "factorization reuse": "0",
         "forcing term": "none", "Hessian projection": "when indefinite",
         "projected step extrapolation": "0",
         "skip failed exact factorizations": "false"}
MATERIAL = {"Newton increment": "material points", "factorization reuse": "0",
            "forcing term": "none", "Hessian projection": "when indefinite",
            "projected step extrapolation": "0",
            "skip failed exact factorizations": "false"}
# Entries that builds before commit 06376d9 (or 2026-11-28's) reject: --baseline-build runs
# without them (their behaviour there is that of the values above).
NEWER_ENTRIES = {"projected step extrapolation", "eigenvalue filter",
                 "exact step growth limit", "skip failed exact factorizations",
                 "friction pass mollifier factor"}
FULL = {"contact": {"friction pass tolerance factor": "100",
                    "friction pass mollifier factor": "1"},
        "solver": {"Newton increment": "material points",
                   "factorization reuse": "30",
                   "forcing term": "Eisenstat-Walker",
                   "projected step extrapolation": "3",
                   "skip failed exact factorizations": "false"}}
SKIP = {"skip failed exact factorizations": "true"}
GROWTH4 = {"exact step growth limit": "4"}
VARIANTS = {
    "baseline": {"contact": {"friction pass tolerance factor": "1"},
                 "solver": PAPER},
    "loose": {"contact": {"friction pass tolerance factor": "100"},
              "solver": PAPER},
    "threads2": {"contact": {"friction pass tolerance factor": "1"},
                 "solver": PAPER, "run": {"threads": "2"}},
    "cg": {"contact": {"friction pass tolerance factor": "1"},
           "solver": dict(PAPER, **{"linear solver": "CG AMG"})},
    "material": {"contact": {"friction pass tolerance factor": "1"},
                 "solver": MATERIAL},
    "material_loose": {"contact": {"friction pass tolerance factor": "100"},
                       "solver": MATERIAL},
    "material_loose_reuse": {
        "contact": {"friction pass tolerance factor": "100"},
        "solver": dict(MATERIAL, **{"factorization reuse": "10"})},
    "material_loose_threads2": {
        "contact": {"friction pass tolerance factor": "100"},
        "solver": MATERIAL, "run": {"threads": "2"}},
    "material_loose_reuse_threads2": {
        "contact": {"friction pass tolerance factor": "100"},
        "solver": dict(MATERIAL, **{"factorization reuse": "10"}),
        "run": {"threads": "2"}},
    "material_loose_reuse_ew_threads2": {
        "contact": {"friction pass tolerance factor": "100"},
        "solver": dict(MATERIAL, **{"factorization reuse": "10",
                                    "forcing term": "Eisenstat-Walker"}),
        "run": {"threads": "2"}},
    "material_loose_reuse30_ew_threads2": {
        "contact": {"friction pass tolerance factor": "100"},
        "solver": dict(MATERIAL, **{"factorization reuse": "30",
                                    "forcing term": "Eisenstat-Walker"}),
        "run": {"threads": "2"}},
    "material_loose_reuse30_ew_extrapolated_threads2": {
        "contact": {"friction pass tolerance factor": "100"},
        "solver": dict(MATERIAL, **{"factorization reuse": "30",
                                    "forcing term": "Eisenstat-Walker",
                                    "projected step extrapolation": "3"}),
        "run": {"threads": "2"}},
    "material_loose_reuse_ew_projected_threads2": {
        "contact": {"friction pass tolerance factor": "100"},
        "solver": dict(MATERIAL, **{"factorization reuse": "10",
                                    "forcing term": "Eisenstat-Walker",
                                    "Hessian projection": "always"}),
        "run": {"threads": "2"}},
    # The full-resolution prm files' settings of 2026-11-28 before they set
    # 'skip failed exact factorizations' (on the medium and reduced scenes
    # too, which leave them at their defaults), and single levers on top.
    "full": FULL,
    "full_skip": {"contact": FULL["contact"],
                  "solver": dict(FULL["solver"], **SKIP)},
    "full_growth4": {"contact": FULL["contact"],
                     "solver": dict(FULL["solver"], **GROWTH4)},
    "full_skip_growth4": {"contact": FULL["contact"],
                          "solver": dict(FULL["solver"], **SKIP, **GROWTH4)},
    # The prm files' settings of 2026-11-28 (with the skip) and the friction
    # passes before the last on a widened mollifier (G eps_v dt, G / 10, ...)
    "full_skip_mollifier100": {
        "contact": dict(FULL["contact"],
                        **{"friction pass mollifier factor": "100"}),
        "solver": dict(FULL["solver"], **SKIP)},
    "full_skip_mollifier1000": {
        "contact": dict(FULL["contact"],
                        **{"friction pass mollifier factor": "1000"}),
        "solver": dict(FULL["solver"], **SKIP)},
}
TIMES = ["assembly_time", "factorization_time", "solve_time",
         "line_search_time"]


def scene_without(folder, scene, entries):
    """A copy of the scene's prm file without the lines that set @p entries,
    for a build that does not know them."""
    path = os.path.join(folder, scene + "_older_build.prm")
    with open(os.path.join(SCENES, scene + ".prm")) as original:
        kept = [line for line in original
                if not (line.strip().startswith("set ") and
                        line.strip()[4:].split("=")[0].strip() in entries)]
    with open(path, "w") as copy:
        copy.writelines(kept)
    return path


def write_prm(folder, scene, name, end_time, changes, drop=frozenset()):
    run = {"name": name, "end time": f"{end_time:.6g}", "quiet": "true",
           "threads": "1"}
    run.update(changes.get("run", {}))
    scene_path = (scene_without(folder, scene, drop) if drop else
                  os.path.join(SCENES, scene + ".prm"))
    lines = [f"include {scene_path}"]
    sections = dict(changes)
    sections["run"] = run
    sections["output"] = {"directory": folder, "interval": "100",
                          "write particles": "false", "write grid": "false"}
    sections["output"].update(changes.get("output", {}))
    for section, entries in sections.items():
        lines.append(f"subsection {section}")
        lines += [f"  set {key} = {value}" for key, value in entries.items()
                  if key not in drop]
        lines.append("end")
    path = os.path.join(folder, name + ".prm")
    with open(path, "w") as prm:
        prm.write("\n".join(lines) + "\n")
    return path


def run_to_start(binary, build, scene, start):
    """The scene's state at t = start: a checkpoint in a folder kept in the
    build folder, made once (and continued if an earlier try stopped)."""
    folder = os.path.join(build, "twist_slices", f"{scene}_t{start:g}")
    checkpoint = os.path.join(folder, "prefix", "checkpoint.h5")
    done = os.path.join(folder, "prefix", "reached")
    if os.path.exists(done):
        return os.path.join(folder, "prefix")
    os.makedirs(folder, exist_ok=True)
    # the fastest variant: the start state is the same for every variant,
    # and differs from any other variant's by the Newton tolerance
    changes = dict(VARIANTS["material_loose_reuse_ew_threads2"])
    changes["checkpoint"] = {"interval": f"{start:g}",
                             "wall time interval": "600", "resume": "auto"}
    path = write_prm(folder, scene, "prefix", start, changes)
    print(f"running {scene} to t = {start:g} s for the slices' start state "
          f"({folder})", flush=True)
    subprocess.run([binary, path], cwd=folder, check=True,
                   capture_output=True, text=True)
    if not os.path.exists(checkpoint):
        raise RuntimeError(f"no checkpoint {checkpoint} after the run to "
                           f"t = {start:g}")
    open(done, "w").close()
    return os.path.join(folder, "prefix")


def run_measured(command, folder):
    """Runs command in folder and returns the resource usage of that process
    alone (os.wait4): RUSAGE_CHILDREN's ru_maxrss is the largest of all
    children so far, which gave every run the peak memory of the largest."""
    with tempfile.TemporaryFile() as log:
        process = subprocess.Popen(command, cwd=folder, stdout=log,
                                   stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(process.pid, 0)
        process.returncode = os.waitstatus_to_exitcode(status)
        if process.returncode != 0:
            log.seek(0)
            raise subprocess.CalledProcessError(
                process.returncode, command,
                log.read().decode(errors="replace"))
    return usage


def run(binary, folder, scene, name, steps, changes, start=0., prefix=None,
        drop=frozenset()):
    if prefix is not None:
        # the variant continues the run to `start` in a copy of its folder
        shutil.copytree(prefix, os.path.join(folder, name))
        changes = dict(changes)
        changes["checkpoint"] = {"resume": "true"}
    path = write_prm(folder, scene, name, start + steps * 1e-2, changes,
                     drop)
    clock = time.perf_counter()
    usage = run_measured([binary, path], folder)
    wall = time.perf_counter() - clock
    with open(os.path.join(folder, name, "diagnostics.csv")) as f:
        # the slice's rows (row 0 of a run from t = 0: the initial state)
        rows = [r for r in csv.DictReader(f)
                if float(r["time"]) > start + 1e-9]
    result = {
        "wall time [s]": wall,
        "CPU time [s]": usage.ru_utime + usage.ru_stime,
        "peak memory [MB]": usage.ru_maxrss / 1024.,
        "steps": len(rows),
        "Newton iterations": sum(int(r["newton_iterations"]) for r in rows),
        "friction updates": sum(int(r["friction_updates"]) for r in rows),
        "factorizations": sum(int(r["factorizations"]) for r in rows),
        "particles inside the shell (max)": max(
            int(float(r["particles_in_fem"])) for r in rows),
        "Newton iterations per step": [int(r["newton_iterations"])
                                       for r in rows],
    }
    for key in TIMES:
        result[key.replace("_", " ") + " [s]"] = sum(float(r[key])
                                                     for r in rows)
    last = rows[-1]
    result["end state"] = {
        key: float(last[key]) for key in
        ["elastic_energy", "kinetic_energy", "contact_force_m0_f0_x",
         "contact_force_m0_f0_y", "contact_force_m0_f0_z", "min_J"]}
    return result


def end_state_difference(state, base):
    """Largest relative difference of the end states: energies and min J
    relative to their own size, the contact force's components relative to
    the force's magnitude (a component near zero has no scale of its own)."""
    force = [k for k in base if k.startswith("contact_force")]
    magnitude = max(sum(base[k] ** 2 for k in force) ** 0.5, 1e-300)
    return max(abs(state[k] - base[k]) /
               (magnitude if k in force else max(abs(base[k]), 1e-300))
               for k in base)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="twist_mu0_2")
    parser.add_argument("--steps", type=int, default=10)
    parser.add_argument("--start", type=float, default=0.)
    parser.add_argument("--variants", default=",".join(VARIANTS))
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--baseline-build", default=None)
    parser.add_argument("--output", default=None)
    args = parser.parse_args()
    suffix = f"_t{args.start:g}" if args.start > 0. else ""
    output = args.output or os.path.join(
        ROOT, "benchmarks", "results",
        f"twist_slices_{args.scene}{suffix}.json")
    names = [v.strip() for v in args.variants.split(",") if v.strip()]
    unknown = [v for v in names if v not in VARIANTS]
    if unknown:
        parser.error(f"unknown variant(s) {', '.join(unknown)}; known: "
                     f"{', '.join(VARIANTS)}")
    jobs = [(v, os.path.join(args.build, "bfemp"), v) for v in names]
    if args.baseline_build:
        jobs.append(("baseline (other build)",
                     os.path.join(args.baseline_build, "bfemp"), "baseline"))
    prefix = None
    if args.start > 0.:
        prefix = run_to_start(os.path.join(args.build, "bfemp"), args.build,
                              args.scene, args.start)
    runs = {}
    with tempfile.TemporaryDirectory() as folder:
        for label, binary, variant in jobs:
            name = label.replace(" ", "_").replace("(", "").replace(")", "")
            older = label == "baseline (other build)"
            runs[label] = run(binary, folder, args.scene, name, args.steps,
                              VARIANTS[variant], args.start, prefix,
                              NEWER_ENTRIES if older else frozenset())
            runs[label]["changes"] = VARIANTS[variant]
            r = runs[label]
            print(f"{label}: {r['wall time [s]']:.1f} s wall, "
                  f"{r['CPU time [s]']:.1f} s CPU, "
                  f"{r['Newton iterations']} Newton iterations", flush=True)
    record = {
        "benchmark": "twist_slices",
        "scene": os.path.relpath(os.path.join(SCENES, args.scene + ".prm"),
                                 ROOT),
        "steps": args.steps,
        "start time [s]": args.start,
        "date": time.strftime("%Y-%m-%d"),
        "machine": {"processor": platform.processor() or platform.machine(),
                    "cpus": os.cpu_count(), "system": platform.platform()},
        "runs": runs,
    }
    # the ratios against the baseline of this build, or else of the other,
    # or else against the scene's own settings
    reference = ("baseline" if "baseline" in runs else
                 "baseline (other build)" if args.baseline_build else
                 "full" if "full" in runs else None)
    if reference is not None:
        record["ratios against"] = reference
        base = runs[reference]
        for label, r in runs.items():
            if label == reference:
                continue
            r["wall time / baseline"] = (r["wall time [s]"] /
                                         base["wall time [s]"])
            r["Newton iterations / baseline"] = (r["Newton iterations"] /
                                                 base["Newton iterations"])
            r["end state, largest relative difference to baseline"] = (
                end_state_difference(r["end state"], base["end state"]))
    os.makedirs(os.path.dirname(output), exist_ok=True)
    with open(output + ".tmp", "w") as f:
        json.dump(record, f, indent=1)
    os.replace(output + ".tmp", output)
    print("wrote", output)


if __name__ == "__main__":
    main()
