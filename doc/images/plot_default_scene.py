#!/usr/bin/env python3
"""Draws doc/images/default_scene.png from a run of prm/default.prm:
    build/bfemp prm/default.prm
    /usr/bin/python3 doc/images/plot_default_scene.py output/default doc/images/default_scene.png
(Debian python3 with python3-vtk9 and python3-matplotlib.)"""
import sys
import vtk
from vtk.util.numpy_support import vtk_to_numpy
import matplotlib; matplotlib.use("Agg")
import matplotlib.pyplot as plt
fig, axes = plt.subplots(1, 4, figsize=(14, 3.8))
for ax, k in zip(axes, [0, 8, 15, 25]):
    r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(f"{sys.argv[1]}/particles_{k:05d}.vtu"); r.Update()
    g = r.GetOutput(); x = vtk_to_numpy(g.GetPoints().GetData()); vm = vtk_to_numpy(g.GetPointData().GetArray("von_mises"))
    sc = ax.scatter(x[:,0], x[:,1], c=vm, s=1.5, cmap="viridis", vmin=0, vmax=2e4)
    ax.set_xlim(0,1); ax.set_ylim(0,1); ax.set_aspect("equal"); ax.set_title(f"t = {0.02*k:.2f} s")
fig.colorbar(sc, ax=axes, label="von Mises stress [Pa]", shrink=0.8)
plt.savefig(sys.argv[2] if len(sys.argv) > 2 else "default_scene.png", dpi=70, bbox_inches="tight")
