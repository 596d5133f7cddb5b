#!/usr/bin/python3
"""Draws seed 002 Fig. 19 from bfemp's output: the von Mises stress along
the line of particles through the sheared cube at t = 0.01, 0.15, 0.21 s,
for linear-kernel MPM, BSMPM and cMPM.

  for v in "" _bsmpm _linear; do build/bfemp prm/cmpm/cube_shearing_2d$v.prm; done
  /usr/bin/python3 doc/experiments/cmpm_stress_line.py output/cmpm_cube_shearing_2d \\
      output/cmpm_cube_shearing_2d_bsmpm output/cmpm_cube_shearing_2d_linear \\
      --csv doc/experiments/data/cmpm_cube_shearing_2d_line.csv
  /usr/bin/python3 doc/experiments/plot_cmpm_cube_shearing.py \\
      doc/experiments/data/cmpm_cube_shearing_2d_line.csv doc/images/cmpm_cube_shearing_2d.png

(3D: the same with cube_shearing_3d.)"""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LABELS = {"linear": ("MPM (linear kernel)", "tab:red", "-"),
          "bsmpm": ("BSMPM (quadratic B-splines)", "tab:blue", "-"),
          "": ("cMPM", "black", "--")}


def variant(run):
    for key in ("linear", "bsmpm"):
        if run.endswith("_" + key):
            return key
    return ""


def main():
    source, target = sys.argv[1], sys.argv[2]
    data = {}
    with open(source) as handle:
        for row in csv.DictReader(handle):
            key = (variant(row["run"]), float(row["time"]))
            data.setdefault(key, ([], []))
            data[key][0].append(float(row["x"]))
            data[key][1].append(float(row["von_mises"]))
    times = sorted({t for _, t in data})
    figure, axes = plt.subplots(1, len(times), figsize=(4 * len(times), 3.4),
                                sharey=False)
    for axis, time in zip(axes, times):
        for key in ("linear", "bsmpm", ""):
            if (key, time) not in data:
                continue
            label, colour, style = LABELS[key]
            x, s = data[(key, time)]
            axis.plot(x, s, style, color=colour, label=label, linewidth=1.2)
        axis.set_title(f"t = {time:g} s")
        axis.set_xlabel("x [m] (current position)")
        axis.grid(alpha=0.3)
    axes[0].set_ylabel("von Mises stress [Pa]")
    axes[0].legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(target, dpi=120)


if __name__ == "__main__":
    main()
