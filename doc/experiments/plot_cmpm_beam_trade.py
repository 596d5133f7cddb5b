#!/usr/bin/python3
"""Draws the speed-accuracy trade of the 3D bending beam of seed 002 Section
8.1.2 at the seed's size: for each coarse method, the speed-up of its step
over BSMPM-fine's (one invocation of the benchmark, the means over the steps
after the first) against its max r_u over the run (eq. 38, against
BSMPM-fine), with the seed's cMPM point (r_u 0.016 at 11x).

  /usr/bin/python3 benchmarks/cmpm_step_split.py --quick --trade --h3-steps 8 \\
      --output benchmarks/results/cmpm_step_split_trade.json
  /usr/bin/python3 doc/experiments/plot_cmpm_beam_trade.py \\
      benchmarks/results/cmpm_step_split_trade.json doc/images/cmpm_beam_trade.png

The max r_u come from the error series in doc/experiments/data/ (doc/cmpm.md
"Bending beam" gives their commands): over the whole run to 0.6 s where it
was run, else over the first 0.1 s, where the maxima of every cMPM run to
0.6 s lie (at 0.05 s). Prints the table of the points."""

import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data")

# benchmark method -> (label, error series, window of the series)
POINTS = {
    "cMPM seed's space Newton": ("cMPM, seed's space (L = H/2), Newton",
                                 "cmpm_bending_beam_3d_errors.csv", "0.6 s"),
    "cMPM seed's space levers": ("cMPM, seed's space, modified Newton",
                                 "cmpm_bending_beam_3d_errors.csv", "0.6 s"),
    "cMPM H/2 modes levers": ("cMPM, L = H/2, modes, modified Newton",
                              "cmpm_bending_beam_3d_modes_to_0.1s_errors.csv",
                              "0.1 s"),
    "cMPM H/3 modes levers": ("cMPM, L = H/3, modes, modified Newton",
                              "cmpm_bending_beam_3d_h3_modes_errors.csv",
                              "0.6 s"),
    "BSMPM-coarse": ("BSMPM-coarse", "cmpm_bending_beam_3d_coarse_errors.csv",
                     "0.6 s"),
}
FINE = "BSMPM-fine CG + ML AMG"
SEED = (0.016, 11.0)  # seed 002 Section 8.1.2 and Table 3 (855.5 s / 77.5 s)


def max_r_u(name):
    """The largest r_u of an error series and the time it is reached at."""
    with open(os.path.join(DATA, name)) as f:
        rows = [(float(r["r_u"]), float(r["time"])) for r in csv.DictReader(f)]
    if not rows:
        raise SystemExit(f"plot_cmpm_beam_trade: {name} has no rows")
    return max(rows)


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    with open(sys.argv[1]) as f:
        results = [r for r in json.load(f)["results"]
                   if r["scene"] == "3d seed size trade"]
    steps = {r["method"]: r for r in results}
    if FINE not in steps:
        raise SystemExit(f"plot_cmpm_beam_trade: {sys.argv[1]} has no "
                         "'3d seed size trade' runs (benchmark --trade)")
    fine = steps[FINE]["step_s"]
    print(f"BSMPM-fine: {fine:.1f} s per step over {steps[FINE]['steps']} steps")
    print("| method | unknowns | step [s] | speed-up | max r_u | at t | over |")
    print("|---|---|---|---|---|---|---|")
    figure, axis = plt.subplots(figsize=(6.4, 4.4))
    for method, (label, series, window) in POINTS.items():
        if method not in steps:
            continue
        r_u, time = max_r_u(series)
        step = steps[method]["step_s"]
        print(f"| {label} | {steps[method]['unknowns']} | {step:.1f} | "
              f"{fine / step:.2f} | {r_u:.4f} | {time:g} s | {window} |")
        marker = ("s" if method == "BSMPM-coarse" else
                  "^" if method.endswith("Newton") else "o")
        axis.plot(r_u, fine / step, marker, markersize=8,
                  fillstyle="full" if window == "0.6 s" else "none",
                  label=f"{label} (r_u to {window})")
    axis.plot(*SEED, "*", color="k", markersize=13,
              label="seed 002: cMPM (L = H/2) against its fine run")
    axis.axvspan(1e-3, SEED[0], ymin=0, ymax=1, color="0.93", zorder=0)
    axis.axhline(SEED[1], color="0.6", linestyle=":", linewidth=1)
    axis.set_xscale("log")
    axis.set_xlim(0.01, 0.12)
    axis.set_ylim(0, 25)
    axis.set_xlabel("max r_u against BSMPM-fine")
    axis.set_ylabel("step time of BSMPM-fine (CG + ML AMG) / method's")
    axis.set_title("3D bending beam, seed's size (640,000 particles); "
                   "modified Newton\nwith factorization reuse; shaded: "
                   "r_u below the seed's 0.016", fontsize=9)
    axis.legend(fontsize=7, loc="lower right")
    axis.grid(alpha=0.3, which="both")
    figure.tight_layout()
    figure.savefig(sys.argv[2], dpi=120)


if __name__ == "__main__":
    main()
