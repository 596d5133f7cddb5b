#!/usr/bin/env python3
"""Draws the time per Newton iteration of bfemp's implicit solver, split into
assembly, factorization, solve and line search, against the number of
unknowns, from the JSON that benchmarks/implicit_newton.cc writes.

Usage (see doc/performance.md):

  build/benchmarks/implicit_newton
  /usr/bin/python3 benchmarks/plot_implicit_newton.py \\
      [benchmarks/results/implicit_newton.json] [--output doc/images/implicit_newton.png]
  /usr/bin/python3 benchmarks/plot_implicit_newton.py --check FILE

One log-log panel per (dimension, MPM/FEM). Factorization (solid) and solve
(dashed) are drawn per linear solver (colour); assembly and line search do not
depend on the solver (the same code runs before and after it), so they are
drawn once, as the median over the solvers at each size (black). The dotted
grey line is assembly + solve + line search of CHOLMOD: the target is that it
stays below CHOLMOD's factorization in 3D at about 1e5 unknowns (the faint
red vertical line in the 3D panels).

--check only loads the file and checks the fields this script reads (no
matplotlib needed); it fails if a run failed. The quick ctest uses it.
"""

import argparse
import json
import os
import statistics
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_INPUT = os.path.join(ROOT, "benchmarks", "results", "implicit_newton.json")
DEFAULT_OUTPUT = os.path.join(ROOT, "doc", "images", "implicit_newton.png")

PHASES = ("assembly", "factorization", "solve", "line_search")
SOLVERS = ("CHOLMOD", "UMFPACK", "CG AMG")
COLOURS = {"CHOLMOD": "tab:blue", "UMFPACK": "tab:orange", "CG AMG": "tab:green"}
PANELS = [(2, "MPM"), (3, "MPM"), (2, "FEM"), (3, "FEM")]


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def timed(run):
    return not run["skipped"] and not run["failed"] and run["iterations"] > 0


def check(data):
    """Returns a list of problems (empty if the file is usable)."""
    problems = []
    if data.get("benchmark") != "implicit_newton":
        problems.append("'benchmark' is not 'implicit_newton'")
    for key in ("mode", "machine", "date", "git_commit", "build", "runs"):
        if key not in data:
            problems.append(f"missing top-level field '{key}'")
    runs = data.get("runs", [])
    if not isinstance(runs, list) or not runs:
        problems.append("'runs' is empty")
        return problems
    for i, run in enumerate(runs):
        name = f"run {i} ({run.get('case')}, {run.get('solver')})"
        for key in ("case", "dim", "kind", "solver", "n_dofs", "nnz",
                    "skipped", "failed", "reason", "iterations",
                    "per_iteration", "ratio_rest_to_factorization"):
            if key not in run:
                problems.append(f"{name}: missing field '{key}'")
        if any(key not in run for key in ("skipped", "failed", "iterations")):
            continue
        if run["failed"]:
            problems.append(f"{name}: failed: {run['reason']}")
            continue
        if not timed(run):
            continue
        for phase in PHASES:
            value = run["per_iteration"].get(phase)
            if not isinstance(value, (int, float)) or not value >= 0:
                problems.append(f"{name}: per_iteration.{phase} = {value}")
        if not run["n_dofs"] > 0 or not run["nnz"] >= run["n_dofs"]:
            problems.append(f"{name}: n_dofs {run['n_dofs']}, nnz {run['nnz']}")
    return problems


def series(runs, value):
    """Sorted (n_dofs, value) of the runs where value is a number."""
    points = [(r["n_dofs"], value(r)) for r in runs]
    return sorted((n, v) for n, v in points
                  if v is not None and isinstance(v, (int, float)) and v > 0)


def plot(data, output):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    runs = [r for r in data["runs"] if timed(r)]
    figure, axes = plt.subplots(2, 2, figsize=(11, 8.5), squeeze=False)
    for ax, (dim, kind) in zip(axes.flat, PANELS):
        panel = [r for r in runs if r["dim"] == dim and r["kind"] == kind]
        ax.set_title(f"{kind} block, {dim}D")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.grid(True, which="both", alpha=0.3)
        ax.set_xlabel("unknowns (DoFs)")
        ax.set_ylabel("seconds per Newton iteration")
        if not panel:
            ax.text(0.5, 0.5, "no data", transform=ax.transAxes,
                    ha="center", va="center", color="grey")
            continue
        for solver in SOLVERS:
            mine = [r for r in panel if r["solver"] == solver]
            for phase, style, marker in (("factorization", "-", "s"),
                                         ("solve", "--", "x")):
                points = series(mine, lambda r: r["per_iteration"][phase])
                if points:
                    ax.plot(*zip(*points), style, marker=marker,
                            color=COLOURS[solver])
        by_size = {}
        for r in panel:
            by_size.setdefault(r["size_index"], []).append(r)
        for phase, style, marker in (("assembly", "-", "o"),
                                     ("line_search", ":", "^")):
            points = sorted(
                (statistics.median(r["n_dofs"] for r in group),
                 statistics.median(r["per_iteration"][phase] for r in group))
                for group in by_size.values())
            points = [(n, v) for n, v in points if v > 0]
            if points:
                ax.plot(*zip(*points), style, marker=marker, color="black")
        rest = series([r for r in panel if r["solver"] == "CHOLMOD"],
                      lambda r: r["per_iteration"]["assembly"]
                      + r["per_iteration"]["solve"]
                      + r["per_iteration"]["line_search"])
        if rest:
            ax.plot(*zip(*rest), ":", color="grey", linewidth=2.5, alpha=0.7)
        notes = [f"{r['solver']} skipped at {r['n_dofs']:,} DoFs"
                 for r in data["runs"]
                 if r["dim"] == dim and r["kind"] == kind and r["skipped"]]
        notes += [f"{r['solver']} failed at {r['n_dofs']:,} DoFs"
                  for r in data["runs"]
                  if r["dim"] == dim and r["kind"] == kind and r["failed"]]
        if dim == 3:
            ax.axvline(1e5, color="red", alpha=0.25, linewidth=1)
        if notes:
            ax.text(0.02, 0.98, "\n".join(notes), transform=ax.transAxes,
                    ha="left", va="top", fontsize=8, color="dimgrey")

    handles = [Line2D([], [], color=COLOURS[s], label=s) for s in SOLVERS]
    handles += [
        Line2D([], [], color="dimgrey", linestyle="-", marker="s",
               label="factorization (per solver)"),
        Line2D([], [], color="dimgrey", linestyle="--", marker="x",
               label="solve (per solver)"),
        Line2D([], [], color="black", linestyle="-", marker="o",
               label="assembly"),
        Line2D([], [], color="black", linestyle=":", marker="^",
               label="line search"),
        Line2D([], [], color="grey", linestyle=":", linewidth=2.5, alpha=0.7,
               label="assembly + solve + line search (CHOLMOD)"),
    ]
    figure.legend(handles=handles, loc="lower center", ncol=4, fontsize=9,
                  frameon=False)
    commit = (data.get("git_commit") or "unknown")[:7]
    figure.suptitle(
        f"bfemp implicit Newton iteration: time split vs unknowns "
        f"({data['mode']} run, commit {commit}, {data['date']}, "
        f"{data['machine']['cpu']}, {data.get('threads', '?')} threads)",
        fontsize=10)
    figure.tight_layout(rect=(0, 0.08, 1, 0.96))
    os.makedirs(os.path.dirname(os.path.abspath(output)), exist_ok=True)
    figure.savefig(output, dpi=120)
    print(f"wrote {output}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input", nargs="?", default=DEFAULT_INPUT)
    parser.add_argument("--output", default=DEFAULT_OUTPUT)
    parser.add_argument("--check", action="store_true",
                        help="only validate the JSON (no plot)")
    args = parser.parse_args()

    try:
        data = load(args.input)
    except (OSError, json.JSONDecodeError) as error:
        print(f"{args.input}: {error}", file=sys.stderr)
        return 1
    problems = check(data)
    if problems:
        for problem in problems:
            print(f"{args.input}: {problem}", file=sys.stderr)
        return 1
    if args.check:
        runs = data["runs"]
        print(f"{args.input}: valid, {len(runs)} runs "
              f"({sum(timed(r) for r in runs)} timed, "
              f"{sum(r['skipped'] for r in runs)} skipped)")
        return 0
    plot(data, args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
