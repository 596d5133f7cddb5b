#!/usr/bin/env python3
"""Draws doc/images/cmpm_beam.png: the heterogeneous beam of prm/cmpm/beam_2d.prm at
rest (t = 0.5 s), on cMPM and, for comparison, on quadratic B-spline MPM with the
fine knot span as cell size (BSMPM-fine, as in tests/cmpm/beam_consistency). The
particles are coloured by their vertical displacement (magnified 20 times).
    build/bfemp prm/cmpm/beam_2d.prm
    build/bfemp <a copy of the prm with cmpm disabled and the fine grid>   (optional)
    /usr/bin/python3 doc/images/plot_cmpm_beam.py output/cmpm_beam_2d [output/<fine run>] \
        doc/images/cmpm_beam.png
(Debian python3 with python3-vtk9 and python3-matplotlib.)"""
import glob
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def last_snapshot(folder):
    files = sorted(glob.glob(f"{folder}/particles_*.vtu"))
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(files[-1])
    reader.Update()
    grid = reader.GetOutput()
    x = vtk_to_numpy(grid.GetPoints().GetData())
    u = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
    return x, u


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    folders, target = sys.argv[1:-1], sys.argv[-1]
    labels = ["cMPM (24 x 4 coarse elements, n = 7)", "BSMPM-fine (cell H/5)"]
    figure, axes = plt.subplots(len(folders), 1, figsize=(10, 2.2 * len(folders)),
                                squeeze=False)
    for axis, folder, label in zip(axes[:, 0], folders, labels):
        x, u = last_snapshot(folder)
        rest = x - u
        shown = rest + 20 * u
        image = axis.scatter(shown[:, 0], shown[:, 1], c=1e3 * u[:, 1], s=0.6,
                             cmap="viridis", vmin=-30, vmax=0)
        axis.set_aspect("equal")
        axis.set_xlim(-0.05, 2.45)
        axis.set_title(f"{label}: displacement x 20, min u_y = {1e3 * u[:, 1].min():.1f} mm")
        figure.colorbar(image, ax=axis, label="u_y [mm]", shrink=0.9)
    figure.tight_layout()
    figure.savefig(target, dpi=90)


if __name__ == "__main__":
    main()
