#!/usr/bin/python3
"""Accuracy against cost of substepped MPM coupled with implicit FEM.

Runs the scene prm/substepping/impact.prm (an elastic MPM block hitting a
free FEM slab at 2 m/s) with

  * 'substepped explicit' at several macro steps dt (S from the substep CFL
    number 0.5) and, at dt = 5e-3 s, several fixed S;
  * 'implicit backward Euler' (fully implicit MPM and FEM) at several dt;
  * the explicit rate: 'substepped explicit' with dt = the substep of the
    CFL-0.5 run and S = 1, i.e. one explicit MPM step and one contact solve
    per explicit step (the scene has an FEM body, which bfemp integrates
    implicitly only, so a fully explicit run of it does not exist);

and measures, against a reference (fully implicit, dt = 5e-3 / 256):
the block's centre-of-mass velocity and the slab's after the impact
(t = 0.1 s), relative to v_0 = 2 m/s. Every run uses one thread.

  /usr/bin/python3 benchmarks/substepping.py [--build build] [--quick]

writes benchmarks/results/substepping.json and
doc/images/substepping_tradeoff.png (see doc/performance.md).
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
SCENE = os.path.join(ROOT, "prm", "substepping", "impact.prm")
V0 = 2.0
BASE_DT = 5e-3


def write_prm(folder, name, integrator, dt, substeps=0):
    path = os.path.join(folder, name + ".prm")
    with open(path, "w") as prm:
        prm.write(f"include {SCENE}\n"
                  f"subsection run\n  set name = {name}\n"
                  f"  set quiet = true\n  set threads = 1\nend\n"
                  f"subsection output\n  set directory = {folder}\n"
                  f"  set interval = 1\n  set write particles = false\n"
                  f"  set write grid = false\nend\n"
                  f"subsection time\n  set integrator = {integrator}\n"
                  f"  set time step = {dt!r}\n"
                  f"  subsection substepping\n    set substeps = {substeps}\n"
                  f"  end\nend\n")
    return path


def last_row(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return rows


def run(binary, folder, name, integrator, dt, substeps=0):
    prm = write_prm(folder, name, integrator, dt, substeps)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run([binary, prm], check=True, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    bodies = last_row(os.path.join(folder, name, "bodies.csv"))[-1]
    diagnostics = last_row(os.path.join(folder, name, "diagnostics.csv"))
    newton = sum(int(float(r["newton_iterations"])) for r in diagnostics[1:])
    result = {
        "name": name,
        "integrator": integrator,
        "dt": dt,
        "steps": len(diagnostics) - 1,
        "newton_iterations": newton,
        "wall_time": wall,
        "cpu_time": cpu,
        "block_velocity": float(bodies["mpm0_com_velocity_y"]),
        "slab_velocity": float(bodies["fem0_com_velocity_y"]),
        "max_particles_in_fem": max(int(float(r["particles_in_fem"]))
                                    for r in diagnostics),
    }
    if "substeps" in diagnostics[-1]:
        result["substeps"] = int(float(diagnostics[-1]["substeps"]))
    print(f"{name:28s} dt {dt:9.3e} S {result.get('substeps', '-'):>4} "
          f"wall {wall:7.2f} s  cpu {cpu:7.2f} s  block "
          f"{result['block_velocity']:+.4f}  slab "
          f"{result['slab_velocity']:+.4f}", flush=True)
    return result


def plot(results, reference, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    series = [("substepped, S from CFL 0.5", "substepped_dt", "o-"),
              ("substepped, dt = 5e-3 s, fixed S", "substepped_S", "s--"),
              ("fully implicit (backward Euler)", "implicit", "^-"),
              ("explicit rate (S = 1 at the CFL step)", "explicit_rate", "D")]
    for label, group, style in series:
        runs = [r for r in results if r["group"] == group]
        ax.loglog([r["cpu_time"] for r in runs],
                  [max(r["block_error"], 1e-4) for r in runs], style,
                  label=label)
        for r in runs:
            tag = (f"S={r['substeps']}" if group == "substepped_S" else
                   f"{r['dt']:.2g}")
            ax.annotate(tag, (r["cpu_time"], max(r["block_error"], 1e-4)),
                        textcoords="offset points", xytext=(4, 3),
                        fontsize=7)
    ax.set_xlabel("CPU time of the run [s] (run/threads = 1; BLAS may add threads)")
    ax.set_ylabel("|v_block - v_ref| / v_0 at t = 0.1 s")
    ax.set_title("MPM block on FEM slab: accuracy against cost\n"
                 f"reference: implicit dt = {reference['dt']:.3g} s, "
                 f"v_ref = {reference['block_velocity']:+.4f} m/s",
                 fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--quick", action="store_true",
                        help="two runs only (a smoke test)")
    parser.add_argument("--output",
                        default=os.path.join(ROOT, "benchmarks", "results",
                                             "substepping.json"))
    parser.add_argument("--plot", default=os.path.join(
        ROOT, "doc", "images", "substepping_tradeoff.png"))
    args = parser.parse_args()
    binary = os.path.join(args.build, "bfemp")

    plan = []
    if args.quick:
        plan = [("substepped_dt", "substepped explicit", BASE_DT, 0),
                ("implicit", "implicit backward Euler", BASE_DT, 0)]
        reference_dt = BASE_DT / 4
    else:
        for k in (1, 2, 4, 8):
            plan.append(("substepped_dt", "substepped explicit", BASE_DT / k, 0))
        for S in (30, 80, 160):
            plan.append(("substepped_S", "substepped explicit", BASE_DT, S))
        for k in (1, 4, 16, 64):
            plan.append(("implicit", "implicit backward Euler", BASE_DT / k, 0))
        reference_dt = BASE_DT / 256

    results = []
    with tempfile.TemporaryDirectory() as folder:
        reference = run(binary, folder, "reference",
                        "implicit backward Euler", reference_dt)
        for i, (group, integrator, dt, S) in enumerate(plan):
            r = run(binary, folder, f"{group}_{i}", integrator, dt, S)
            r["group"] = group
            results.append(r)
        if not args.quick:
            # One explicit MPM step per contact solve, at the CFL-0.5 step
            # of the first substepped run.
            first = results[0]
            explicit_dt = first["dt"] / first["substeps"]
            r = run(binary, folder, "explicit_rate", "substepped explicit",
                    explicit_dt, 1)
            r["group"] = "explicit_rate"
            results.append(r)

    for r in results:
        r["block_error"] = abs(r["block_velocity"] -
                               reference["block_velocity"]) / V0
        r["slab_error"] = abs(r["slab_velocity"] -
                              reference["slab_velocity"]) / V0
        if r["max_particles_in_fem"] != 0:
            sys.exit(f"{r['name']}: particles inside the FEM slab")

    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short",
                             "HEAD"], capture_output=True, text=True).stdout
    record = {
        "benchmark": "substepping",
        "scene": os.path.relpath(SCENE, ROOT),
        "date": time.strftime("%Y-%m-%d"),
        "commit": commit.strip(),
        "machine": {"processor": platform.processor() or platform.machine(),
                    "cpus": os.cpu_count(), "system": platform.platform()},
        "reference": reference,
        "runs": results,
    }
    os.makedirs(os.path.dirname(args.output), exist_ok=True)
    with open(args.output, "w") as f:
        json.dump(record, f, indent=1)
    if not args.quick:
        plot(results, reference, args.plot)
    print("wrote", args.output)


if __name__ == "__main__":
    main()
