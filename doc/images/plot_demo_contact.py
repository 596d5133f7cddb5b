#!/usr/bin/env python3
"""Draws doc/images/demo_contact.png from a run of prm/demo_contact.prm:
    build/bfemp prm/demo_contact.prm
    /usr/bin/python3 doc/images/plot_demo_contact.py output/demo_contact doc/images/demo_contact.png
Particles as dots and the FEM meshes (ramp, block) as triangles, coloured by von Mises stress
(Debian python3 with python3-vtk9 and python3-matplotlib)."""
import sys
import vtk
from vtk.util.numpy_support import vtk_to_numpy
import matplotlib; matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri


def read(path):
    r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(path); r.Update()
    return r.GetOutput()


folder = sys.argv[1]
FRAMES = [0, 15, 30, 45, 60]
fig, axes = plt.subplots(1, len(FRAMES), figsize=(20, 2.6))
for ax, k in zip(axes, FRAMES):
    g = read(f"{folder}/particles_{k:05d}.vtu")
    x = vtk_to_numpy(g.GetPoints().GetData())
    vm = vtk_to_numpy(g.GetPointData().GetArray("von_mises"))
    sc = ax.scatter(x[:, 0], x[:, 1], c=vm, s=0.8, cmap="viridis", vmin=0, vmax=1e4)
    for b in (0, 1):
        f = read(f"{folder}/fem_body_{b}_{k:05d}.vtu")
        y = vtk_to_numpy(f.GetPoints().GetData())
        cells = vtk_to_numpy(f.GetCells().GetConnectivityArray()).reshape(-1, 3)
        fvm = vtk_to_numpy(f.GetPointData().GetArray("von_mises"))[cells[:, 0]]
        ax.tripcolor(mtri.Triangulation(y[:, 0], y[:, 1], cells), facecolors=fvm,
                     cmap="viridis", vmin=0, vmax=1e4, edgecolors="k", linewidth=0.1)
    ax.set_xlim(0, 2); ax.set_ylim(0, 1); ax.set_aspect("equal")
    ax.set_title(f"t = {0.02 * k:.2f} s")
fig.colorbar(sc, ax=axes, label="von Mises stress [Pa]", shrink=0.8)
plt.savefig(sys.argv[2] if len(sys.argv) > 2 else "demo_contact.png", dpi=70, bbox_inches="tight")
