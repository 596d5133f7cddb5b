#!/usr/bin/env python3
"""Figures of BFEMP Section 6.2 (sine-wave boundary) from bfemp runs of
prm/experiments/6_2_sine_wave/sine_wave_{bfemp,level_set}.prm:

    build/bfemp prm/experiments/6_2_sine_wave/sine_wave_bfemp.prm
    build/bfemp prm/experiments/6_2_sine_wave/sine_wave_level_set.prm
    /usr/bin/python3 doc/experiments/plot_sine_wave.py [OUTPUT_DIR [IMAGE_DIR]]

OUTPUT_DIR (default 'output') holds the run folders sine_wave_bfemp/ and
sine_wave_level_set/ (or, if these are missing, the *_reduced ones).
Writes into IMAGE_DIR (default doc/images/experiments):
  sine_wave_penetration.png  particles inside the boundary vs time (both
                             variants) and the box's centre-of-mass height;
  sine_wave_snapshots.png    particles coloured by von Mises stress at the
                             instants of the paper's Figure 8 (start, end of
                             the downward motion, halfway and end of the
                             sideways motion, twice during the lift), BFEMP
                             (top row, FEM mesh in grey) and level set (bottom
                             row, the level set's curve in black).
Needs numpy, matplotlib and vtk (Debian: python3-numpy python3-matplotlib
python3-vtk9; use /usr/bin/python3). The snapshots are drawn with matplotlib
from the VTU files read by VTK, so no display is needed.
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
from run_data import csv, prm_entries, prm_entry, pvd, read_grid  # noqa: E402

OUT = sys.argv[1] if len(sys.argv) > 1 else "output"
IMG = sys.argv[2] if len(sys.argv) > 2 else os.path.normpath(os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "images", "experiments"))
os.makedirs(IMG, exist_ok=True)


def run_folder(variant):
    for name in (f"sine_wave_{variant}", f"sine_wave_{variant}_reduced"):
        if os.path.isdir(os.path.join(OUT, name)):
            return os.path.join(OUT, name)
    sys.exit(f"no run folder sine_wave_{variant}[_reduced] in {OUT}")


def entry(folder, name):
    """The value of the prm entry whose path ends in @p name in the run's
    input.prm (includes followed)."""
    return prm_entry(prm_entries(os.path.join(folder, "input.prm")), name)


def keyframes(folder):
    """Phase start times and velocities of the boundary."""
    frames = []
    for piece in entry(folder, "keyframes").split(";"):
        t, v = piece.split(":")
        frames.append((float(t), [float(c) for c in v.split(",")][:2]))
    return frames


def offset(folder):
    """Height of the sine wave's mid line at t = 0 (level set: 'offset')."""
    return float(entry(folder, "offset"))


def displacement(frames, t):
    u = np.zeros(2)
    for k, (t0, v) in enumerate(frames):
        t1 = frames[k + 1][0] if k + 1 < len(frames) else t
        if t > t0:
            u += (min(t, t1) - t0) * np.array(v)
    return u


bfemp, level = run_folder("bfemp"), run_folder("level_set")
db, dl = csv(f"{bfemp}/diagnostics.csv"), csv(f"{level}/diagnostics.csv")
bb, bl = csv(f"{bfemp}/bodies.csv"), csv(f"{level}/bodies.csv")
frames = keyframes(bfemp)
t_side, t_up = frames[1][0], frames[2][0]

# Penetration count and centre-of-mass height.
fig, (a0, a1) = plt.subplots(1, 2, figsize=(10, 3.4))
a0.plot(dl["time"], dl["particles_in_level_sets"], label="level set (slip)")
a0.plot(db["time"], db["particles_in_fem"], label="BFEMP (FEM boundary)")
a0.set_xlabel("t [s]")
a0.set_ylabel("particles inside the boundary")
a1.plot(bl["time"], bl["mpm0_com_y"], label="level set (slip)")
a1.plot(bb["time"], bb["mpm0_com_y"], label="BFEMP (FEM boundary)")
a1.set_xlabel("t [s]")
a1.set_ylabel("box centre of mass y [m]")
for a in (a0, a1):
    for t in (t_side, t_up):
        a.axvline(t, color="0.7", lw=0.8, ls="--")
    a.legend(fontsize=8)
a0.set_title("penetration (down | left | up)", fontsize=9)
a1.set_title("adhesion: the box is lifted by the level set", fontsize=9)
fig.tight_layout()
fig.savefig(os.path.join(IMG, "sine_wave_penetration.png"), dpi=80)

# Snapshots at the instants of Figure 8.
down = t_side - frames[0][0]
instants = [0., t_side, 0.5 * (t_side + t_up), t_up,
            t_up + 0.5 * down, t_up + 0.75 * down]
series = {v: pvd(os.path.join(f, "particles.pvd")) for v, f in (("b", bfemp), ("l", level))}
fem = pvd(os.path.join(bfemp, "fem_body_0.pvd"))
c0 = offset(level)
vmax = 2e5
fig, axes = plt.subplots(2, len(instants), figsize=(2.3 * len(instants), 4.6))
for row, (v, folder) in enumerate((("b", bfemp), ("l", level))):
    for col, t in enumerate(instants):
        ax = axes[row, col]
        k = int(np.argmin([abs(s[0] - t) for s in series[v]]))
        tk = series[v][k][0]
        g = read_grid(series[v][k][1])
        x = vtk_to_numpy(g.GetPoints().GetData())
        vm = vtk_to_numpy(g.GetPointData().GetArray("von_mises"))
        sc = ax.scatter(x[:, 0], x[:, 1], c=vm, s=1.5, cmap="viridis",
                        vmin=0, vmax=vmax, rasterized=True)
        u = displacement(frames, tk)
        if v == "b":
            f = read_grid(fem[k][1])
            y = vtk_to_numpy(f.GetPoints().GetData())
            cells = vtk_to_numpy(f.GetCells().GetConnectivityArray()).reshape(-1, 3)
            ax.tripcolor(mtri.Triangulation(y[:, 0], y[:, 1], cells),
                         np.zeros(len(cells)), cmap="Greys", vmin=-1, vmax=3,
                         edgecolors="none")
        else:
            xs = np.linspace(0, 2, 2001)
            ax.plot(xs, c0 + u[1] + np.cos(2 * np.pi * (xs - u[0]) / 0.1) / 40,
                    "k", lw=0.5)
        # A window of 0.5 m x 0.35 m at the box's centre line, around the
        # boundary's lowest point, so that single particles are visible.
        low = c0 - 1 / 40 + u[1]
        ax.set_xlim(0.75, 1.25)
        ax.set_ylim(low - 0.2, low + 0.15)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(f"t = {tk:.2f} s\nu = ({u[0]:.2f}, {u[1]:.2f})", fontsize=7)
    axes[row, 0].set_ylabel("BFEMP" if v == "b" else "level set", fontsize=9)
fig.colorbar(sc, ax=axes, label="von Mises stress [Pa]", shrink=0.8)
fig.savefig(os.path.join(IMG, "sine_wave_snapshots.png"), dpi=80,
            bbox_inches="tight")
# The numbers of doc/experiments/sine_wave.md.
top0 = vtk_to_numpy(read_grid(series["l"][0][1]).GetPoints().GetData())[:, 1].max()
for name, d, b, column in (("BFEMP", db, bb, "contact_pairs"),
                           ("level set", dl, bl, "particles_in_level_sets")):
    touching = np.nonzero(d[column] > 0)[0]
    inside = d["particles_in_fem"] if name == "BFEMP" else d["particles_in_level_sets"]
    line = (f"{name}: {len(d)} rows to t = {d['time'][-1]:.3f} s, particles inside "
            f"the boundary: max {int(inside.max())}")
    if len(touching):
        t_last = d["time"][touching[-1]]
        lowest = c0 - 1 / 40 + displacement(frames, t_last)[1]
        line += (f"; touching from t = {d['time'][touching[0]]:.3f} s to "
                 f"{t_last:.3f} s, when the boundary's lowest point is "
                 f"{1e3 * (lowest - top0):.1f} mm above the box's initial top "
                 f"particles")
    rise = b["mpm0_com_y"] - b["mpm0_com_y"][0]
    lifted = b["time"] > t_up
    line += (f"; centre of mass at most {1e3 * rise.max():.1f} mm above its start "
             f"(after {t_up:g} s: {1e3 * rise[lifted].max():.1f} mm)")
    if name == "BFEMP":
        line += f", closest particle {d['min_distance'][touching].min():.2e} m"
    print(line)
print("wrote", os.path.join(IMG, "sine_wave_penetration.png"), "and",
      os.path.join(IMG, "sine_wave_snapshots.png"))
