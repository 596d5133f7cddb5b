#!/usr/bin/python3
"""Draws seed 002 Figs. 21 and (as curves over time) the r_u it reports for
the bending beam from bfemp's output: the deformed beam of BSMPM-fine,
BSMPM-coarse and cMPM at two times, coloured by material, and r_u(t),
r_sigma(t) of cMPM and BSMPM-coarse against BSMPM-fine (in 3D also of
cMPM with L = H/3 and interior modes, prm/cmpm/bending_beam_3d_h3_modes.prm,
whose series doc/experiments/data/cmpm_bending_beam_3d_h3_modes_errors.csv
is made the same way).

  for v in "" _fine _coarse; do build/bfemp prm/cmpm/bending_beam_2d$v.prm; done
  for v in "" _coarse; do /usr/bin/python3 doc/experiments/particle_error.py \\
      output/cmpm_bending_beam_2d_fine output/cmpm_bending_beam_2d$v \\
      --csv doc/experiments/data/cmpm_bending_beam_2d${v}_errors.csv; done
  /usr/bin/python3 doc/experiments/plot_cmpm_bending_beam.py output 2d \\
      doc/images/cmpm_bending_beam_2d.png

The first argument is the folder that holds the three run folders; the
error CSVs are read from doc/experiments/data/. Without the run folders
(e.g. for 3D, whose runs are not kept) only the error curves are drawn:
pass "-" as the folder."""

import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import run_data  # noqa: E402

RUNS = [("_fine", "BSMPM-fine (reference)"), ("_coarse", "BSMPM-coarse"),
        ("", "cMPM")]
# the error curves, where their series exist: bfemp's richer coarse space
# (prm/cmpm/bending_beam_3d_h3_modes.prm) has a 3D series only
CURVES = [("", "cMPM", "black"),
          ("_h3_modes", "cMPM, L = H/3 and interior modes", "tab:green"),
          ("_coarse", "BSMPM-coarse", "tab:blue")]


def errors(dim, suffix, scene="bending_beam"):
    """(times, r_u, r_sigma) of a run of @p scene against its reference, as
    particle_error.py --csv wrote them to doc/experiments/data/."""
    path = os.path.join(HERE, "data",
                        f"cmpm_{scene}_{dim}{suffix}_errors.csv")
    with open(path) as handle:
        rows = list(csv.DictReader(handle))
    return ([float(r["time"]) for r in rows], [float(r["r_u"]) for r in rows],
            [float(r["r_sigma"]) for r in rows])


def particles(folder, time, field="material_id"):
    """The positions and the point field @p field of a run's particles at
    @p time."""
    from vtk.util.numpy_support import vtk_to_numpy

    series = run_data.pvd(os.path.join(folder, "particles.pvd"))
    vtu = [f for t, f in series if abs(t - time) < 1e-9][0]
    grid = run_data.read_grid(vtu)
    x = vtk_to_numpy(grid.GetPoints().GetData())
    return x, vtk_to_numpy(grid.GetPointData().GetArray(field))


def main():
    folder, dim, target = sys.argv[1], sys.argv[2], sys.argv[3]
    times = (0.3, 0.6)
    draw_beams = folder != "-"
    rows = len(RUNS) if draw_beams else 0
    figure = plt.figure(figsize=(11, 2.0 * rows + 3.2))
    grid = figure.add_gridspec(rows + 1, 2, height_ratios=[1] * rows + [1.6])
    if draw_beams:
        for row, (suffix, label) in enumerate(RUNS):
            run = os.path.join(folder, f"cmpm_bending_beam_{dim}{suffix}")
            for column, time in enumerate(times):
                axis = figure.add_subplot(grid[row, column])
                x, material = particles(run, time)
                soft = material > 0
                axis.scatter(x[~soft, 0], x[~soft, 1], s=0.2, c="0.6",
                             linewidths=0)
                axis.scatter(x[soft, 0], x[soft, 1], s=0.2, c="tab:red",
                             linewidths=0)
                axis.set_xlim(-0.5, 20.5)
                axis.set_ylim(-3.5, 2.5)
                axis.set_aspect("equal")
                axis.set_title(f"{label}, t = {time:g} s", fontsize=9)
                axis.tick_params(labelsize=7)
    for column, (index, name) in enumerate(((1, "r_u"), (2, "r_sigma"))):
        axis = figure.add_subplot(grid[rows, column])
        for suffix, label, colour in CURVES:
            if not os.path.isfile(os.path.join(
                    HERE, "data", f"cmpm_bending_beam_{dim}{suffix}"
                    "_errors.csv")):
                continue  # e.g. no 2D series of the H/3 space
            data = errors(dim, suffix)
            axis.plot(data[0], data[index], "o-", color=colour, markersize=3,
                      label=label)
        axis.set_xlabel("t [s]")
        axis.set_ylabel(f"{name} against BSMPM-fine (eq. 38)")
        axis.set_ylim(bottom=0)
        axis.grid(alpha=0.3)
        axis.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(target, dpi=120)


if __name__ == "__main__":
    main()
