#!/usr/bin/python3
"""Draws seed 002 Fig. 25(b) and the r_u it reports for the heterogeneous
cube from bfemp's output: the cube of BSMPM-fine and of cMPM with the first
Newton step and with full Newton in the local problem at t = 0.05 s,
coloured by displacement magnitude, r_u(t) of both cMPM runs against
BSMPM-fine, and r_u at 0.05 s against how much of the cube is soft
(doc/experiments/cmpm_cube_inclusions.py), each with the seed's values.

  for v in "" _full_newton _fine; do build/bfemp prm/cmpm/heterogeneous_cube_2d$v.prm; done
  for v in "" _full_newton; do /usr/bin/python3 doc/experiments/particle_error.py \\
      output/cmpm_heterogeneous_cube_2d_fine output/cmpm_heterogeneous_cube_2d$v \\
      --csv doc/experiments/data/cmpm_heterogeneous_cube_2d${v}_errors.csv; done
  /usr/bin/python3 doc/experiments/plot_cmpm_heterogeneous_cube.py output 2d \\
      doc/images/cmpm_heterogeneous_cube_2d.png

The first argument is the folder that holds the three run folders ("-" to
draw only the curves); the CSVs are read from doc/experiments/data/. Fig.
26(a, b) (the strain energy over the Newton iterations) is drawn by
doc/experiments/cmpm_newton_history.py."""

import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from plot_cmpm_bending_beam import errors, particles  # noqa: E402

RUNS = [("_fine", "BSMPM-fine (reference)"),
        ("", "cMPM, first Newton step"),
        ("_full_newton", "cMPM, full Newton")]
SEED_R_U = {"": 0.040, "_full_newton": 0.031}  # seed 002 Section 8.1.4, 3D


def inclusions():
    with open(os.path.join(HERE, "data", "cmpm_cube_inclusions_2d.csv")) as f:
        rows = list(csv.DictReader(f))
    return ([100 * float(r["soft_fraction"]) for r in rows],
            [float(r["r_u_end_first"]) for r in rows],
            [float(r["r_u_end_full"]) for r in rows])


def main():
    folder, dim, target = sys.argv[1], sys.argv[2], sys.argv[3]
    draw_cubes = folder != "-"
    figure = plt.figure(figsize=(11, 7.2 if draw_cubes else 3.6))
    grid = figure.add_gridspec(2 if draw_cubes else 1, 6)
    if draw_cubes:
        axes = []
        for column, (suffix, label) in enumerate(RUNS):
            run = os.path.join(folder, f"cmpm_heterogeneous_cube_{dim}{suffix}")
            axis = figure.add_subplot(grid[0, 2 * column:2 * column + 2])
            axes.append(axis)
            x, u = particles(run, 0.05, "displacement")
            dots = axis.scatter(x[:, 0], x[:, 1], s=2, linewidths=0,
                                c=np.linalg.norm(u, axis=1), cmap="viridis",
                                vmin=0, vmax=0.1)
            axis.set_xlim(-0.1, 1.1)
            axis.set_ylim(-0.1, 1.2)
            axis.set_aspect("equal")
            axis.set_title(f"{label}, t = 0.05 s", fontsize=9)
            axis.tick_params(labelsize=7)
    row = 1 if draw_cubes else 0
    colours = ("black", "tab:blue")
    axis = figure.add_subplot(grid[row, :3])
    for (suffix, label), colour in zip(RUNS[1:], colours):
        t, r_u, _ = errors(dim, suffix, "heterogeneous_cube")
        axis.plot(t, r_u, "o-", color=colour, markersize=3, label=label)
        axis.plot([0.05], [SEED_R_U[suffix]], "x", color=colour,
                  label=f"seed (3D): {SEED_R_U[suffix]}")
    axis.set_xlabel("t [s]")
    axis.set_ylabel("r_u against BSMPM-fine (eq. 38)")
    axis.set_ylim(bottom=0)
    axis.grid(alpha=0.3)
    axis.legend(fontsize=8)
    axis = figure.add_subplot(grid[row, 3:])
    soft, first, full = inclusions()
    axis.plot(soft, first, "o-", color=colours[0], markersize=3,
              label="cMPM, first Newton step")
    axis.plot(soft, full, "s--", color=colours[1], markersize=3,
              label="cMPM, full Newton")
    for suffix, colour in zip(("", "_full_newton"), colours):
        axis.axhline(SEED_R_U[suffix], color=colour, linestyle=":",
                     linewidth=0.8)
    axis.set_xlabel("soft share of the cube [%] (bfemp's cube: 15.8)")
    axis.set_ylabel("r_u at t = 0.05 s")
    axis.set_ylim(bottom=0)
    axis.grid(alpha=0.3)
    axis.legend(fontsize=8, title="dotted: seed's values", title_fontsize=8)
    figure.tight_layout()
    if draw_cubes:
        # after the layout, so that the bar takes its room from all three
        figure.colorbar(dots, ax=axes, shrink=0.8, label="|u| [m]")
    figure.savefig(target, dpi=120)


if __name__ == "__main__":
    main()
