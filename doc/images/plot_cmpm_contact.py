#!/usr/bin/env python3
"""Draws doc/images/cmpm_contact.png: snapshots of prm/cmpm/block_on_cantilever_2d.prm,
a heterogeneous cMPM block (stiff frame, soft core) falling onto a deformable FEM
cantilever in barrier frictional contact. Particles are coloured by material, the FEM mesh
by its von Mises stress.
    build/bfemp prm/cmpm/block_on_cantilever_2d.prm
    /usr/bin/python3 doc/images/plot_cmpm_contact.py output/cmpm_block_on_cantilever_2d \
        doc/images/cmpm_contact.png
(Debian python3 with python3-vtk9 and python3-matplotlib.)"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import vtk
from matplotlib.collections import PolyCollection
from vtk.util.numpy_support import vtk_to_numpy

SNAPSHOTS = [0, 9, 12, 40]  # output indices (interval 0.02 s)


def read(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def triangles(grid):
    """The triangles and the mean of a point field over each (the FEM output
    writes each element as its own patch, so its points carry its stress)."""
    x = vtk_to_numpy(grid.GetPoints().GetData())[:, :2]
    cells = vtk_to_numpy(grid.GetCells().GetData()).reshape(-1, 4)[:, 1:]
    stress = vtk_to_numpy(grid.GetPointData().GetArray("von_mises"))
    return [x[c] for c in cells], stress[cells].mean(axis=1)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    folder, target = sys.argv[1:]
    figure, axes = plt.subplots(1, len(SNAPSHOTS), figsize=(3.2 * len(SNAPSHOTS), 2.6))
    for axis, index in zip(axes, SNAPSHOTS):
        particles = read(f"{folder}/particles_{index:05d}.vtu")
        mesh = read(f"{folder}/fem_body_0_{index:05d}.vtu")
        x = vtk_to_numpy(particles.GetPoints().GetData())
        material = vtk_to_numpy(particles.GetPointData().GetArray("material_id"))
        shapes, stress = triangles(mesh)
        polygons = PolyCollection(shapes, array=stress, cmap="viridis",
                                  edgecolors="none")
        polygons.set_clim(0, 1e6)
        axis.add_collection(polygons)
        axis.scatter(x[:, 0], x[:, 1], s=0.4, c=["#c0392b" if m == 0 else "#f5b041"
                                                  for m in material])
        axis.set_xlim(0.05, 1.45)
        axis.set_ylim(0.2, 0.85)
        axis.set_aspect("equal")
        axis.set_title(f"t = {0.02 * index:.2f} s", fontsize=9)
        axis.tick_params(labelsize=7)
    figure.colorbar(polygons, ax=axes, shrink=0.7, label="FEM von Mises [Pa]")
    figure.savefig(target, dpi=130, bbox_inches="tight")


if __name__ == "__main__":
    main()
