#!/usr/bin/env python3
"""BFEMP Section 6.5 (convergence under refinement): Figures 13 and 14.

    /usr/bin/python3 doc/experiments/plot_refinement.py [OUTPUT]

OUTPUT (default `output`) holds the run folders refinement_N<N>_ppc<PPC> of
prm/experiments/6_5_refinement/ (see make_refinement_prms.py); missing runs
are skipped. For each PPC the reference is the largest N present (the paper:
N = 30). Writes into doc/images/experiments/:
  refinement_convergence.png  |h_N - h_ref| against dx, log-log, with the
                              least-squares order per PPC (Figure 14);
  refinement_settling.png     |h(t) - h(end)| of each run (is it static?);
  refinement_scene.png        final equilibria at low and high resolution,
                              coloured by von Mises stress (Figure 13 b, c).
h is the centre-of-mass height of the whole system (MPM box + FEM box,
mass-weighted, from bodies.csv). Prints the table of heights and errors.
Needs numpy, matplotlib and the vtk Python module.
"""
import glob
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from vtk.util.numpy_support import vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from run_data import csv, pvd, read_grid  # noqa: E402

IMAGES = os.path.join(HERE, "..", "images", "experiments")
END = 8.0  # end time of the full runs (make_refinement_prms.py)


def height(folder):
    """Time and whole-system centre-of-mass height of a run."""
    d = csv(os.path.join(folder, "bodies.csv"))
    m1, m2 = d["mpm0_mass"], d["fem0_mass"]
    return d["time"], (m1 * d["mpm0_com_y"] + m2 * d["fem0_com_y"]) / (m1 + m2)


def runs(out, prefix="refinement_N"):
    """{ppc: {N: folder}} of the runs that reached END (unfinished ones are
    skipped)."""
    found = {}
    for folder in glob.glob(os.path.join(out, prefix + "*_ppc*")):
        m = re.search(r"N(\d+)_ppc(\d+)$", folder)
        if m and os.path.isfile(os.path.join(folder, "bodies.csv")):
            t = height(folder)[0]
            if np.size(t) > 1 and t[-1] >= END - 1e-9:
                found.setdefault(int(m.group(2)), {})[int(m.group(1))] = folder
            else:
                print("skipped (unfinished):", folder)
    return found


def order(dx, err):
    """Least-squares slope of log(err) over log(dx)."""
    return np.polyfit(np.log(dx), np.log(err), 1)


def last_snapshot(folder, series):
    return read_grid(pvd(os.path.join(folder, series + ".pvd"))[-1][1])


def plot_convergence(found):
    """Left: each PPC against its own finest run (the paper's reading);
    right: every PPC against the finest run of the largest PPC."""
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6), sharey=True)
    top = max(found)
    common_n = max(found[top])
    h_common = height(found[top][common_n])[1][-1]
    print("PPC  N  h_end  |h - h_ref(own PPC)|  |h - h(N=%d, PPC %d)|  "
          "end-time drift |h(T) - h(T - 1 s)|" % (common_n, top))
    for k, ppc in enumerate(sorted(found)):
        runs_ppc = found[ppc]
        ref = max(runs_ppc)
        h_ref = height(runs_ppc[ref])[1][-1]
        rows = []
        for n in sorted(runs_ppc):
            t, h = height(runs_ppc[n])
            drift = abs(h[-1] - h[np.argmin(abs(t - (t[-1] - 1.0)))])
            rows.append((n, h[-1], abs(h[-1] - h_ref), abs(h[-1] - h_common)))
            print("%3d %3d  %.10f  %.3e  %.3e  %.1e" % (ppc, n, h[-1],
                                                     rows[-1][2], rows[-1][3],
                                                     drift))
        for ax, col, r, what in ((axes[0], 2, ref, "own"),
                                 (axes[1], 3, common_n, "common")):
            pts = [(n, e[col]) for n, e in zip([x[0] for x in rows], rows)
                   if n < r or (what == "common" and ppc != top
                                and n <= r)]
            if len(pts) < 2:
                continue
            dx = 1.0 / np.array([p_[0] for p_ in pts], float)
            err = np.array([p_[1] for p_ in pts])
            p = order(dx, err)
            ax.loglog(dx, err, "o-", color="C%d" % k,
                      label="PPC %d: order %.2f (ref. N = %d, PPC %d)"
                      % (ppc, p[0], r, ppc if what == "own" else top))
            print("PPC %d vs %s reference: fitted order %.3f over N = %s"
                  % (ppc, what, p[0], [p_[0] for p_ in pts]))
    for ax, title in ((axes[0], "each PPC against its finest run"),
                      (axes[1], "against the finest PPC-%d run" % top)):
        x = np.array([1 / 20, 1 / 2])
        e0 = 0.5
        ax.loglog(x, e0 * (x / x[1]) ** 1, "k:", lw=1, label="order 1")
        ax.loglog(x, e0 * (x / x[1]) ** 2, "k--", lw=1, label="order 2")
        ax.set_xlabel("dx = 1/N [m]")
        ax.set_title(title, fontsize=10)
        ax.legend(fontsize=7)
        ax.grid(True, which="both", lw=0.3)
    axes[0].set_ylabel("|COM height - reference| [m]")
    fig.suptitle("BFEMP 6.5: convergence under refinement", fontsize=11)
    fig.tight_layout()
    fig.savefig(os.path.join(IMAGES, "refinement_convergence.png"), dpi=75)
    plt.close(fig)


def plot_settling(found):
    fig, ax = plt.subplots(figsize=(6, 4))
    for k, ppc in enumerate(sorted(found)):
        for j, n in enumerate(sorted(found[ppc])):
            t, h = height(found[ppc][n])
            ax.semilogy(t[:-1], np.abs(h[:-1] - h[-1]) + 1e-14,
                        color="C%d" % k, alpha=0.3 + 0.7 * j / len(found[ppc]),
                        lw=0.8, label="PPC %d" % ppc if j == 0 else None)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("|h(t) - h(end)| [m]")
    ax.set_title("settling of every run (darker: finer)", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(IMAGES, "refinement_settling.png"), dpi=80)
    plt.close(fig)


def plot_scene(found):
    ppc = max(found)
    ns = sorted(found[ppc])
    pick = [ns[0], ns[-1]] if len(ns) > 1 else ns
    fig, axes = plt.subplots(1, len(pick), figsize=(5.5 * len(pick), 2.9))
    axes = np.atleast_1d(axes)
    vmax = 1.2e4
    for ax, n in zip(axes, pick):
        folder = found[ppc][n]
        p = last_snapshot(folder, "particles")
        xy = vtk_to_numpy(p.GetPoints().GetData())[:, :2]
        vm = vtk_to_numpy(p.GetPointData().GetArray("von_mises"))
        f = last_snapshot(folder, "fem_body_0")
        pts = vtk_to_numpy(f.GetPoints().GetData())[:, :2]
        cells = vtk_to_numpy(f.GetCells().GetData()).reshape(-1, 4)[:, 1:]
        fvm = vtk_to_numpy(f.GetPointData().GetArray("von_mises"))
        ax.tripcolor(pts[:, 0], pts[:, 1], cells, fvm, shading="gouraud",
                     cmap="viridis", vmin=0, vmax=vmax)
        ax.triplot(pts[:, 0], pts[:, 1], cells, color="w", lw=0.1)
        sc = ax.scatter(xy[:, 0], xy[:, 1], c=vm, s=40.0 / n, cmap="viridis",
                        vmin=0, vmax=vmax, linewidths=0)
        ax.set_aspect("equal")
        ax.set_xlim(-0.1, 4.1)
        ax.set_ylim(-0.1, 2.1)
        ax.set_title("N = %d, PPC %d, final equilibrium" % (n, ppc),
                     fontsize=9)
        ax.tick_params(labelsize=7)
    fig.colorbar(sc, ax=axes, label="von Mises [Pa]", shrink=0.8,
                 fraction=0.03, pad=0.02)
    fig.savefig(os.path.join(IMAGES, "refinement_scene.png"), dpi=70)
    plt.close(fig)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "output"
    os.makedirs(IMAGES, exist_ok=True)
    found = runs(out)
    if not found:
        sys.exit("no refinement_N*_ppc* runs in " + out)
    plot_convergence(found)
    plot_settling(found)
    plot_scene(found)


if __name__ == "__main__":
    main()
