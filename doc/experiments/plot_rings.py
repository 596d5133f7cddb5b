#!/usr/bin/python3
"""BFEMP Section 6.1, colliding rings: the paper's Figure 7 (energy and
momentum vs time, APIC and FLIP) and Figure 6 (snapshots coloured by von
Mises stress) from bfemp's output.

usage: /usr/bin/python3 doc/experiments/plot_rings.py [OUTPUT_DIR] [APIC_RUN FLIP_RUN]

OUTPUT_DIR (default `output`) holds the run folders; the run names default to
rings_apic and rings_flip (prm/experiments/6_1_rings/). Writes
doc/images/experiments/rings_energy.png and rings_snapshots.png and prints
the numbers of doc/experiments/rings.md (contact window, energy lost).
Needs numpy, matplotlib and the vtk Python module (Debian: python3-vtk9).
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from run_data import csv, pvd, read_vtu  # noqa: E402
IMAGES = os.path.join(HERE, "..", "images", "experiments")


def summary(folder):
    """Contact window, energy lost in the collision, per-ring energies."""
    d = csv(os.path.join(folder, "diagnostics.csv"))
    b = csv(os.path.join(folder, "bodies.csv"))
    t = d["time"]
    E = d["total_energy"] + d["barrier_energy"]
    rows = np.nonzero(d["contact_pairs"][1:] > 0)[0] + 1
    first, last = rows[0], rows[-1]
    after = min(last + 1, len(t) - 1)
    fem = b["fem0_kinetic_energy"] + b["fem0_elastic_energy"]
    mpm = b["mpm0_kinetic_energy"] + b["mpm0_elastic_energy"]
    p = d["momentum_x"]
    # Chatter of the contact: how often the FEM ring's kinetic energy turns
    # from rising to falling, and the energy added or removed step by step.
    window = slice(first, last + 1)
    rise = np.diff(b["fem0_kinetic_energy"][window])
    steps = np.diff(E[window]) / E[0]
    chatter = dict(turns=int(np.sum(rise[1:] * rise[:-1] < 0)),
                   steps=last - first + 1,
                   pairs=float(np.mean(d["contact_pairs"][window])),
                   no_pairs=int(np.sum(d["contact_pairs"][window] == 0)),
                   gained=float(steps[steps > 0].sum()),
                   lost=float(-steps[steps < 0].sum()))
    return dict(chatter=chatter, t=t, E=E, fem=fem, mpm=mpm, barrier=d["barrier_energy"], p=p,
                py=d["momentum_y"], M=d["mass"][0], first=t[first],
                last=t[last], loss=1 - E[after] / E[0],
                fem_after=fem[-1] / fem[after] - 1,
                mpm_after=mpm[-1] / mpm[after] - 1,
                dp=np.max(np.abs(np.r_[p - p[0], d["momentum_y"] - d["momentum_y"][0]])))


def energy_figure(runs, out):
    fig, axes = plt.subplots(2, len(runs), figsize=(4.2 * len(runs), 5.2),
                             sharex=True, squeeze=False)
    for j, (label, s) in enumerate(runs):
        ax = axes[0, j]
        E0 = s["E"][0]
        ax.plot(s["t"], s["E"] / 1e6, "k", label="total (incl. barrier)")
        ax.plot(s["t"], s["mpm"] / 1e6, "C0", label="MPM ring")
        ax.plot(s["t"], s["fem"] / 1e6, "C3", label="FEM ring")
        ax.axvspan(s["first"], s["last"], color="0.9", zorder=0)
        ax.set_title("%s: %.1f %% lost in the collision" % (label, 100 * s["loss"]),
                     fontsize=9)
        ax.set_ylim(0, 1.05 * E0 / 1e6)
        ax.set_ylabel("energy [MJ/m]")
        ax.legend(fontsize=7, loc="lower left")
        ax = axes[1, j]
        ax.plot(s["t"], s["p"] / 1e3, "k", label="total $p_x$")
        ax.plot(s["t"], s["py"] / 1e3, "k--", label="total $p_y$")
        ax.axvspan(s["first"], s["last"], color="0.9", zorder=0)
        ax.set_ylabel("momentum [1e3 kg m/s /m]")
        ax.set_xlabel("time [s]")
        ax.set_ylim(-0.05 * s["M"] * 40 / 1e3, 0.05 * s["M"] * 40 / 1e3)
        ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def snapshots(folder, times, out):
    particles = pvd(os.path.join(folder, "particles.pvd"))
    fem = pvd(os.path.join(folder, "fem_body_0.pvd"))
    fig, axes = plt.subplots(2, (len(times) + 1) // 2, figsize=(9, 3.9))
    vmax = 2.5e7
    markersize = 2.0 if len(read_vtu(particles[0][1])["points"]) < 5000 else 0.3
    for ax, want in zip(axes.flat, times):
        k = int(np.argmin([abs(t - want) for t, _ in particles]))
        t, pfile = particles[k]
        ffile = fem[int(np.argmin([abs(tf - t) for tf, _ in fem]))][1]
        p = read_vtu(pfile)
        f = read_vtu(ffile)
        tri = f["cells"].reshape(-1, 3)
        # per-element stress, written as discontinuous point data
        value = f["cell_vm"] if f["cell_vm"] is not None else f["point_vm"][tri].mean(axis=1)
        polys = PolyCollection(f["points"][tri], array=value,
                               cmap="viridis", edgecolors="none")
        polys.set_clim(0, vmax)
        ax.add_collection(polys)
        ax.scatter(p["points"][:, 0], p["points"][:, 1], c=p["point_vm"], s=markersize,
                   cmap="viridis", vmin=0, vmax=vmax, linewidths=0)
        ax.set_xlim(-11, 11)
        ax.set_ylim(-5.5, 5.5)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title("t = %.3f s" % t, fontsize=9)
    sm = plt.cm.ScalarMappable(cmap="viridis",
                               norm=matplotlib.colors.Normalize(0, vmax))
    fig.subplots_adjust(left=0.01, right=0.86, bottom=0.02, top=0.93, wspace=0.04, hspace=0.15)
    fig.colorbar(sm, cax=fig.add_axes([0.88, 0.1, 0.02, 0.78]), label="von Mises stress [Pa]")
    fig.savefig(out, dpi=80)
    plt.close(fig)


def main():
    output = sys.argv[1] if len(sys.argv) > 1 else "output"
    names = sys.argv[2:4] if len(sys.argv) > 3 else ["rings_apic", "rings_flip"]
    os.makedirs(IMAGES, exist_ok=True)
    runs = []
    for label, name in zip(["APIC", "FLIP"], names):
        s = summary(os.path.join(output, name))
        runs.append((label, s))
        print("%s (%s): contact %.4f .. %.4f s, energy lost in the collision "
              "%.2f %%, at the end %.2f %%; after the separation FEM ring %+.3f %%, "
              "MPM ring %+.2f %%; max |p - p0| / (M v0) %.1e"
              % (label, name, s["first"], s["last"], 100 * s["loss"],
                 100 * (1 - s["E"][-1] / s["E"][0]), 100 * s["fem_after"],
                 100 * s["mpm_after"], s["dp"] / (s["M"] * 40)))
        c = s["chatter"]
        print("    contact steps %d: %d without pairs, %.1f pairs on average; the FEM "
              "ring's kinetic energy turns %d times; steps that add energy add "
              "%.1f %% of E0 in all, steps that remove it remove %.1f %%"
              % (c["steps"], c["no_pairs"], c["pairs"], c["turns"],
                 100 * c["gained"], 100 * c["lost"]))
    energy_figure(runs, os.path.join(IMAGES, "rings_energy.png"))
    snapshots(os.path.join(output, names[0]), [0.0, 0.03, 0.08, 0.15, 0.22, 0.3],
              os.path.join(IMAGES, "rings_snapshots.png"))


if __name__ == "__main__":
    main()
