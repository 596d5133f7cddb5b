#!/usr/bin/python3
"""Draws seed 002 Fig. 24 and (as curves over time) the r_u it reports for
the lattice bar from bfemp's output: the bar of BSMPM-fine and of cMPM on
boundary B-spline and on B-spline coarse elements at t = 1.0 and 1.6 s,
coloured by von Mises stress, and r_u(t) of both cMPM runs against
BSMPM-fine with the seed's maxima.

  for v in "" _bspline _fine; do build/bfemp prm/cmpm/lattice_bar_2d$v.prm; done
  for v in "" _bspline; do /usr/bin/python3 doc/experiments/particle_error.py \\
      output/cmpm_lattice_bar_2d_fine output/cmpm_lattice_bar_2d$v \\
      --csv doc/experiments/data/cmpm_lattice_bar_2d${v}_errors.csv; done
  /usr/bin/python3 doc/experiments/plot_cmpm_lattice_bar.py output 2d \\
      doc/images/cmpm_lattice_bar_2d.png

The first argument is the folder that holds the three run folders ("-" to
draw only the error curves); the error CSVs are read from
doc/experiments/data/. Where the series of the 3D bar cut to a 0.5 m slab
exist (cmpm_lattice_bar_3d_slab{,_bspline,_h3}_errors.csv, doc/cmpm.md
"Lattice bar"), their r_u(t) is drawn too."""

import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from plot_cmpm_bending_beam import errors, particles  # noqa: E402

RUNS = [("_fine", "BSMPM-fine (reference)"),
        ("", "cMPM, boundary B-spline elements"),
        ("_bspline", "cMPM, B-spline elements")]
SEED_MAX_R_U = {"": 0.025, "_bspline": 0.021}  # seed 002 Section 8.1.3, 3D


def main():
    folder, dim, target = sys.argv[1], sys.argv[2], sys.argv[3]
    times = (1.0, 1.6)
    rows = len(RUNS) if folder != "-" else 0
    figure = plt.figure(figsize=(11, 2.4 * rows + 3.2))
    grid = figure.add_gridspec(rows + 1, 2, height_ratios=[1] * rows + [1.3])
    for row in range(rows):
        suffix, label = RUNS[row]
        run = os.path.join(folder, f"cmpm_lattice_bar_{dim}{suffix}")
        for column, time in enumerate(times):
            axis = figure.add_subplot(grid[row, column])
            x, von_mises = particles(run, time, "von_mises")
            dots = axis.scatter(x[:, 0], x[:, 1], s=0.3, c=von_mises,
                                cmap="viridis", vmin=0, vmax=2000,
                                linewidths=0)
            axis.set_xlim(-0.3, 8.3)
            axis.set_ylim(-2.7, 2.3)
            axis.set_aspect("equal")
            axis.set_title(f"{label}, t = {time:g} s", fontsize=9)
            axis.tick_params(labelsize=7)
        figure.colorbar(dots, ax=axis, shrink=0.8, label="von Mises [Pa]")
    axis = figure.add_subplot(grid[rows, :])
    for (suffix, label), colour in zip(RUNS[1:], ("black", "tab:blue")):
        t, r_u, _ = errors(dim, suffix, "lattice_bar")
        axis.plot(t, r_u, "o-", color=colour, markersize=3, label=label)
        axis.axhline(SEED_MAX_R_U[suffix], color=colour, linestyle="--",
                     linewidth=0.8, label=f"seed (3D), max r_u: "
                     f"{SEED_MAX_R_U[suffix]}")
        # the 3D bar cut to a 0.5 m slab (doc/cmpm.md "Lattice bar"), where
        # its series exists
        if os.path.exists(os.path.join(HERE, "data", "cmpm_lattice_bar_3d_"
                                       f"slab{suffix}_errors.csv")):
            t, r_u, _ = errors("3d", "_slab" + suffix, "lattice_bar")
            axis.plot(t, r_u, "s:", color=colour, markersize=3,
                      label=label.replace("cMPM", "3D slab 0.5 m deep"))
    if os.path.exists(os.path.join(HERE, "data", "cmpm_lattice_bar_3d_"
                                   "slab_h3_errors.csv")):
        t, r_u, _ = errors("3d", "_slab_h3", "lattice_bar")
        axis.plot(t, r_u, "s:", color="tab:green", markersize=3,
                  label="3D slab 0.5 m deep, boundary B-spline elements, "
                  "L = H/3")
    axis.axvline(1.0, color="0.6", linewidth=0.8)
    axis.set_xlabel("t [s]")
    axis.set_ylabel("r_u against BSMPM-fine (eq. 38)")
    axis.set_ylim(bottom=0)
    axis.grid(alpha=0.3)
    axis.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(target, dpi=100)


if __name__ == "__main__":
    main()
