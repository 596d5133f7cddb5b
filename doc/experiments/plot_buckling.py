#!/usr/bin/env python3
"""Figures of BFEMP Section 6.6 (buckling of stacked semi-rings) from bfemp
runs of prm/experiments/6_6_buckling/ with mu = 0, 0.2, 0.5 between the rings:

    /usr/bin/python3 doc/experiments/plot_buckling.py [OUTPUT_DIR [PREFIX [IMAGE_DIR [SUFFIX]]]]

OUTPUT_DIR (default 'output') holds the run folders PREFIX0, PREFIX0_2 and
PREFIX0_5 (missing ones are skipped); PREFIX defaults to 'buckling_mu_' (the
full-resolution prm files); SUFFIX (default empty) is appended to the image
names. doc/experiments/buckling.md lists the runs its figures were drawn from.
Writes into IMAGE_DIR (default doc/images/experiments):
  buckling_displacement<SUFFIX>.png  the plate's vertical displacement u_y at which the
                             inner (MPM) ring buckles, per mu (the paper's
                             Figure 15 reports the buckling at different u_y),
                             and the inner ring's centre-of-mass velocity
                             against u_y: buckling = the first time it moves
                             down faster than the plate (1 m/s);
  buckling_snapshots<SUFFIX>.png     particles and the FEM ring coloured by von Mises
                             stress, one row per mu, at u_y = 2 m, at the
                             buckling of mu = 0 and of mu = 0.2, and at the end.
Needs numpy, matplotlib and vtk (use /usr/bin/python3); the snapshots are
drawn with matplotlib from the VTU files read by VTK (no display needed).
"""
import os
import sys

import numpy as np
from vtk.util.numpy_support import vtk_to_numpy
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_data import csv, pvd, read_grid  # noqa: E402

OUT = sys.argv[1] if len(sys.argv) > 1 else "output"
PREFIX = sys.argv[2] if len(sys.argv) > 2 else "buckling_mu_"
IMG = sys.argv[3] if len(sys.argv) > 3 else os.path.normpath(os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "images", "experiments"))
os.makedirs(IMG, exist_ok=True)
SUFFIX = sys.argv[4] if len(sys.argv) > 4 else ""
PLATE_SPEED = 1.0
MUS = [("0", 0.0), ("0_2", 0.2), ("0_5", 0.5)]


def onset(bodies):
    """Plate displacement at the first row where the inner ring's centre of
    mass moves down faster than the plate, or None."""
    fast = np.nonzero(bodies["mpm0_com_velocity_y"] < -PLATE_SPEED)[0]
    return PLATE_SPEED * bodies["time"][fast[0]] if len(fast) else None


runs = {}
for tag, mu in MUS:
    folder = os.path.join(OUT, PREFIX + tag)
    if not os.path.isfile(os.path.join(folder, "bodies.csv")):
        continue
    b = csv(os.path.join(folder, "bodies.csv"))
    runs[tag] = dict(mu=mu, folder=folder, bodies=b, onset=onset(b),
                     end=PLATE_SPEED * b["time"][-1])
    o = runs[tag]["onset"]
    print(f"mu = {mu}: " + (f"buckles at -u_y = {o:.2f} m" if o is not None
                            else "no buckling") +
          f" (run to -u_y = {runs[tag]['end']:.2f} m)")

# u_y at buckling per mu, and the centre-of-mass velocity behind it.
fig, (a0, a1) = plt.subplots(1, 2, figsize=(10, 3.4))
for k, (tag, r) in enumerate(runs.items()):
    if r["onset"] is not None:
        a0.bar(k, r["onset"], color=f"C{k}")
        a0.text(k, r["onset"] + 0.1, f"{r['onset']:.2f} m", ha="center", fontsize=8)
    else:
        a0.bar(k, r["end"], color="none", edgecolor=f"C{k}", hatch="//")
        a0.text(k, r["end"] + 0.1, f"none up to {r['end']:.1f} m", ha="center",
                fontsize=8)
    b = r["bodies"]
    a1.plot(PLATE_SPEED * b["time"], -b["mpm0_com_velocity_y"], lw=0.8,
            label=f"mu = {r['mu']}")
a0.set_xticks(range(len(runs)), [f"mu = {r['mu']}" for r in runs.values()])
a0.set_ylabel("plate displacement -u_y at buckling [m]")
a0.set_ylim(0, 1.2 * max(r["end"] for r in runs.values()))
a1.axhline(PLATE_SPEED, color="k", lw=0.8, ls="--")
a1.text(0.2, PLATE_SPEED + 0.05, "plate speed", fontsize=8)
a1.set_xlabel("plate displacement -u_y [m]")
a1.set_ylabel("inner ring: downward c.o.m. speed [m/s]")
a1.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(IMG, f"buckling_displacement{SUFFIX}.png"), dpi=80)

# Snapshots.
instants = [2.0]
for tag in ("0", "0_2"):
    if tag in runs and runs[tag]["onset"] is not None:
        instants.append(runs[tag]["onset"] + 0.3)
instants.append(min(r["end"] for r in runs.values()))
fig, axes = plt.subplots(len(runs), len(instants), squeeze=False,
                         figsize=(2.6 * len(instants), 1.6 * len(runs)))
vmax = 2e5
for row, (tag, r) in enumerate(runs.items()):
    parts = pvd(os.path.join(r["folder"], "particles.pvd"))
    fem = pvd(os.path.join(r["folder"], "fem_body_0.pvd"))
    for col, u in enumerate(instants):
        ax = axes[row, col]
        k = int(np.argmin([abs(PLATE_SPEED * s[0] - u) for s in parts]))
        g = read_grid(parts[k][1])
        x = vtk_to_numpy(g.GetPoints().GetData())
        vm = vtk_to_numpy(g.GetPointData().GetArray("von_mises"))
        f = read_grid(fem[k][1])
        y = vtk_to_numpy(f.GetPoints().GetData())
        cells = vtk_to_numpy(f.GetCells().GetConnectivityArray()).reshape(-1, 3)
        fvm = vtk_to_numpy(f.GetPointData().GetArray("von_mises"))[cells].mean(axis=1)
        ax.tripcolor(mtri.Triangulation(y[:, 0], y[:, 1], cells), facecolors=fvm,
                     cmap="viridis", vmin=0, vmax=vmax)
        sc = ax.scatter(x[:, 0], x[:, 1], c=vm, s=0.2, cmap="viridis",
                        vmin=0, vmax=vmax, rasterized=True)
        plate = 14.001 - PLATE_SPEED * parts[k][0]
        ax.fill_between([-15, 15], plate, plate + 0.6, color="0.5")
        ax.set_xlim(-15, 15)
        ax.set_ylim(-0.5, 15)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        if row == 0:
            ax.set_title(f"u_y = -{PLATE_SPEED * parts[k][0]:.1f} m", fontsize=8)
    axes[row, 0].set_ylabel(f"mu = {r['mu']}", fontsize=8)
fig.colorbar(sc, ax=axes, label="von Mises stress [Pa]", shrink=0.8)
fig.savefig(os.path.join(IMG, f"buckling_snapshots{SUFFIX}.png"), dpi=80,
            bbox_inches="tight")
print("wrote", os.path.join(IMG, f"buckling_displacement{SUFFIX}.png"), "and",
      os.path.join(IMG, f"buckling_snapshots{SUFFIX}.png"))
