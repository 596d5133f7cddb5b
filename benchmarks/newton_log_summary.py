#!/usr/bin/env python3
"""Sums a bfemp log written with `solver/log iterations = true` per time step
and friction pass: where a scene's Newton iterations, factorizations and CG
iterations go.

Usage (see doc/performance.md):

  build/bfemp scene.prm > scene.log        # with 'solver/log iterations = true'
  python3 benchmarks/newton_log_summary.py scene.log [--from STEP] [--csv F]

One line per step: the Newton iterations of each friction pass (pass 0 with
friction lagged at the step's start, pass k after the k-th update), the
iterations that made a new factorization (diagnostics.csv's `factorizations`
also counts the attempts on an exact Hessian that turned out indefinite), the
iterations that fell back to the projected Hessian (logs of builds before
this flag was logged show none), the
CG iterations with an older factorization and those of them spent in solves
that did not reach their tolerance (a factorization followed), and the line
search's backtracks. A last line sums the steps shown. --csv writes the same
per step, for plots.
"""

import argparse
import collections
import csv
import re
import sys

LINE = re.compile(
    r"^\s+step (?P<step>\d+), t = (?P<t>[\d.e+-]+)"
    r"(?:, full-Newton pass)?(?:, friction update (?P<update>\d+))?"
    r": iteration (?P<iteration>\d+), \|\|p\|\|/dt (?P<residual>\S+) m/s"
    r" \(stop (?P<stop>\S+)\), step (?P<step_length>\S+), "
    r"backtracks (?P<backtracks>\d+), .*?"
    r"(?P<kind>factorized|CG with an older factorization)"
    r"(?:.*?, (?P<cg>\d+) CG iterations)?(?P<projected>, projected Hessian)?")


def read(path):
    steps = collections.OrderedDict()
    with open(path, errors="replace") as log:
        for line in log:
            match = LINE.match(line)
            if not match:
                continue
            step = int(match["step"])
            entry = steps.setdefault(step, {
                "time": float(match["t"]),
                "passes": collections.Counter(),
                "factorizations": 0, "projected": 0, "cg": 0,
                "cg failed": 0, "backtracks": 0})
            entry["passes"][int(match["update"] or 0)] += 1
            cg = int(match["cg"] or 0)
            entry["cg"] += cg
            if match["kind"] == "factorized":
                entry["factorizations"] += 1
                # CG ran first and did not give the direction
                entry["cg failed"] += cg
            entry["projected"] += match["projected"] is not None
            # the count is cumulative over the Newton solve of one pass
            entry.setdefault("backtracks by pass", {})[
                int(match["update"] or 0)] = int(match["backtracks"])
    for entry in steps.values():
        entry["backtracks"] = sum(entry.pop("backtracks by pass").values())
        entry["iterations"] = sum(entry["passes"].values())
    return steps


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("log")
    parser.add_argument("--from", dest="first", type=int, default=0,
                        help="first step shown and summed")
    parser.add_argument("--csv", help="also write the rows to this file")
    args = parser.parse_args()
    steps = {s: e for s, e in read(args.log).items() if s >= args.first}
    if not steps:
        sys.exit(f"{args.log}: no Newton iteration lines from step "
                 f"{args.first} on (was 'solver/log iterations' true?)")
    keys = ["iterations", "factorizations", "projected", "cg", "cg failed",
            "backtracks"]
    print(f"{'step':>6} {'t':>8} {'its':>4} {'fact':>4} {'proj':>4} "
          f"{'CG':>5} {'CGlost':>6} {'bt':>4}  iterations per friction pass")
    for step, e in steps.items():
        passes = [e["passes"][k] for k in sorted(e["passes"])]
        print(f"{step:6d} {e['time']:8.3f} {e['iterations']:4d} "
              f"{e['factorizations']:4d} {e['projected']:4d} {e['cg']:5d} "
              f"{e['cg failed']:6d} {e['backtracks']:4d}  {passes}")
    total = {k: sum(e[k] for e in steps.values()) for k in keys}
    first_passes = sum(e["passes"][1] for e in steps.values())
    print(f"{len(steps)} steps: {total['iterations']} Newton iterations "
          f"({total['iterations'] / len(steps):.1f} per step, "
          f"{first_passes} of them in the pass after the first friction "
          f"update), {total['factorizations']} with a new factorization, "
          f"{total['projected']} with the projected Hessian, {total['cg']} CG "
          f"iterations "
          f"({total['cg failed']} in solves that did not reach their "
          f"tolerance), {total['backtracks']} backtracks")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(["step", "time"] + [k.replace(" ", "_")
                                                for k in keys] +
                            ["iterations_per_pass"])
            for step, e in steps.items():
                writer.writerow([step, e["time"]] + [e[k] for k in keys] +
                                [" ".join(str(e["passes"][k])
                                          for k in sorted(e["passes"]))])


if __name__ == "__main__":
    main()
