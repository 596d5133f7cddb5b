#!/usr/bin/env python3
"""Draws doc/images/cmpm_coarse_grid.png from cMPM's coarse-grid output
(`output/write grid = true` with cMPM): the coarse elements of one step of
prm/cmpm/beam_2d.prm, each subdivided into its fine knot spans and coloured by
the vertical velocity interpolated through the matrix-valued shape functions,
with the particles of the soft inclusions on top.
    build/bfemp doc/images/cmpm_coarse_grid.prm
    /usr/bin/python3 doc/images/plot_cmpm_coarse_grid.py output/cmpm_coarse_grid \
        doc/images/cmpm_coarse_grid.png
(Debian python3 with python3-vtk9 and python3-matplotlib.)"""
import glob
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import vtk
from matplotlib.collections import PolyCollection
from vtk.util.numpy_support import vtk_to_numpy


def read(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    folder, target = sys.argv[1], sys.argv[2]
    coarse = read(sorted(glob.glob(folder + "/coarse_grid_*.vtu"))[-1])
    x = vtk_to_numpy(coarse.GetPoints().GetData())[:, :2]
    cells = vtk_to_numpy(coarse.GetCells().GetData()).reshape(-1, 5)[:, 1:]
    velocity = vtk_to_numpy(coarse.GetPointData().GetArray("velocity"))[:, 1]
    element = vtk_to_numpy(coarse.GetPointData().GetArray("element"))

    # the snapshot of the particles at the same time
    index = sorted(glob.glob(folder + "/coarse_grid_*.vtu"))[-1][-9:-4]
    particles = read(folder + "/particles_" + index + ".vtu")
    p = vtk_to_numpy(particles.GetPoints().GetData())[:, :2]
    material = vtk_to_numpy(particles.GetPointData().GetArray("material_id"))
    # Phi v is meaningful where particles are; in elements that hold only a
    # few, the coarse-node combinations no particle sees are unconstrained
    # and the field far from the particles is not (doc/cmpm.md): take the
    # colour range from the particles
    particle_velocity = vtk_to_numpy(particles.GetPointData().GetArray("velocity"))
    vmin, vmax = particle_velocity[:, 1].min(), particle_velocity[:, 1].max()

    fig, ax = plt.subplots(figsize=(10, 2.8))
    spans = PolyCollection(
        [x[c] for c in cells],
        array=velocity[cells].mean(axis=1),
        cmap="viridis",
        clim=(vmin, vmax),
        edgecolors="0.6",
        linewidths=0.2,
    )
    ax.add_collection(spans)
    # the coarse elements: the bounding box of each element's patch points
    for e in np.unique(element):
        box = x[element == e]
        lo, hi = box.min(axis=0), box.max(axis=0)
        ax.add_patch(
            plt.Rectangle(lo, *(hi - lo), fill=False, edgecolor="black", lw=0.8)
        )
    inclusion = material > 0
    ax.scatter(p[inclusion, 0], p[inclusion, 1], s=0.05, c="red", alpha=0.5)
    fig.colorbar(
        spans, ax=ax, label="vertical velocity [m/s]", pad=0.01, extend="both"
    )
    ax.set_xlim(x[:, 0].min() - 0.05, x[:, 0].max() + 0.05)
    ax.set_ylim(x[:, 1].min() - 0.05, x[:, 1].max() + 0.05)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(
        "coarse elements (black), knot spans (grey), velocity through Phi; "
        "inclusion particles red",
        fontsize=9,
    )
    fig.tight_layout()
    fig.savefig(target, dpi=150)


if __name__ == "__main__":
    main()
