#!/usr/bin/env python3
"""BFEMP Section 6.4 (critical friction on a slope): Figures 11 and 12.

    /usr/bin/python3 doc/experiments/plot_slope.py [OUTPUT]

OUTPUT (default `output`) holds the run folders slope_mu_0, slope_mu_0_1,
slope_mu_0_1999 and slope_mu_0_2 of prm/experiments/6_4_slope/. Writes
doc/images/experiments/slope_velocity.png (centre-of-mass velocity along the
slope and its acceleration over the release window against
a = g (sin theta - mu cos theta)) and slope_scene.png (particles and FEM
bodies from the VTU output, coloured by von Mises stress, at the release and
at the end). Prints the fitted accelerations and their relative errors.
Needs numpy, matplotlib and the vtk Python module.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from vtk.util.numpy_support import vtk_to_numpy

G, TANGENT = 5.1, 0.2
SIN = TANGENT / np.sqrt(1 + TANGENT**2)
COS = 1 / np.sqrt(1 + TANGENT**2)
EPS_V = 1e-5
RUNS = [("slope_mu_0", 0.0), ("slope_mu_0_1", 0.1),
        ("slope_mu_0_1999", 0.1999), ("slope_mu_0_2", 0.2)]
RELEASE, END = 2.0, 3.0
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from run_data import csv, pvd, read_grid  # noqa: E402

IMAGES = os.path.join(HERE, "..", "images", "experiments")


def analytic(mu):
    return max(0.0, G * (SIN - mu * COS))


def bodies(folder):
    return csv(os.path.join(folder, "bodies.csv"))


def fitted_acceleration(t, v, release):
    """Least-squares slope of v(t) after the release step."""
    w = t > release + 0.01
    return np.polyfit(t[w] - release, v[w], 1)[0]


def snapshot(folder, index):
    """Particles (x, y, von Mises) and FEM bodies (points, triangles, von
    Mises) of VTU snapshot @p index."""
    p = read_grid(os.path.join(folder, "particles_%05d.vtu" % index))
    particles = (vtk_to_numpy(p.GetPoints().GetData())[:, :2],
                 vtk_to_numpy(p.GetPointData().GetArray("von_mises")))
    fem = []
    for body in (0, 1):
        f = read_grid(os.path.join(folder, "fem_body_%d_%05d.vtu" % (body,
                                                                     index)))
        cells = vtk_to_numpy(f.GetCells().GetData()).reshape(-1, 4)[:, 1:]
        fem.append((vtk_to_numpy(f.GetPoints().GetData())[:, :2], cells))
    return particles, fem


def snapshot_index(folder, time):
    """The VTU index whose time in particles.pvd is nearest to @p time."""
    times = [t for t, _ in pvd(os.path.join(folder, "particles.pvd"))]
    return int(np.argmin(np.abs(np.array(times) - time)))


def plot_curves(out):
    fig, axes = plt.subplots(2, 4, figsize=(13, 5.6))
    report = []
    for col, (name, mu) in enumerate(RUNS):
        folder = os.path.join(out, name)
        if not os.path.isdir(folder):
            continue
        d = bodies(folder)
        t, v = d["time"], d["mpm0_com_velocity_x"]
        w = t >= RELEASE - 0.05
        a_exact = analytic(mu)
        a_step = np.diff(v) / np.diff(t)
        a_fit = fitted_acceleration(t, v, RELEASE)
        ax = axes[0, col]
        ax.plot(t[w], v[w], "C0-", lw=2, label="bfemp")
        ax.plot(t[w], a_exact * np.clip(t[w] - RELEASE, 0, None), "k--",
                lw=1, label="analytic")
        if mu >= TANGENT:
            ax.axhline(EPS_V, color="C3", lw=0.8, ls=":",
                       label=r"$\epsilon_v$")
            ax.set_ylim(-0.1 * EPS_V, 1.5 * EPS_V)
        ax.set_title(r"$\mu$ = %g" % mu)
        ax.set_xlabel("t [s]")
        if col == 0:
            ax.set_ylabel("COM velocity along slope [m/s]")
        ax.legend(fontsize=8, loc="upper left")
        ax = axes[1, col]
        ta = t[1:]
        wa = ta >= RELEASE - 0.05
        ax.plot(ta[wa], a_step[wa], "C1-", lw=2, label="bfemp (per step)")
        ax.plot([RELEASE - 0.05, RELEASE, RELEASE, END],
                [0, 0, a_exact, a_exact], "k--", lw=1, label="analytic")
        if a_exact > 0:
            ax.set_ylim(-0.1 * a_exact, 1.3 * a_exact)
            err = abs(a_fit - a_exact) / a_exact
            txt = "fit a = %.7g\nrel. error %.1e" % (a_fit, err)
        else:
            ax.set_ylim(-1e-4, 1e-4)
            err = float("nan")
            txt = "fit a = %.2e\nmax |v| = %.3g eps_v" % (
                a_fit, np.abs(v[t > RELEASE]).max() / EPS_V)
        ax.text(0.35, 0.12, txt, transform=ax.transAxes, fontsize=8)
        ax.set_xlabel("t [s]")
        if col == 0:
            ax.set_ylabel(r"COM acceleration [m/s$^2$]")
        ax.legend(fontsize=8, loc="upper left")
        report.append((mu, a_exact, a_fit, err,
                       np.abs(v[t > RELEASE]).max(),
                       np.abs(v[(t > 0.1) & (t <= RELEASE)]).max()))
    fig.suptitle("BFEMP 6.4: box released on a slope, tan(theta) = 0.2, "
                 "g = 5.1 (release at t = 2 s)")
    fig.tight_layout()
    fig.savefig(os.path.join(IMAGES, "slope_velocity.png"), dpi=80)
    plt.close(fig)
    print("mu, analytic a, fitted a, relative error, max |v| after release,"
          " max |v| in 0.1 s .. release")
    for r in report:
        print("%g  %.10g  %.10g  %.2e  %.6e  %.2e" % r)


def plot_scene(out):
    panels = [("slope_mu_0", RELEASE, "settled, support in place (t = 2 s)")]
    panels += [(name, END, r"$\mu$ = %g, t = 3 s" % mu) for name, mu in RUNS]
    fig, axes = plt.subplots(len(panels), 1, figsize=(9, 1.3 * len(panels)),
                             gridspec_kw={"hspace": 0.55})
    vmax = 0.0
    shots = []
    for name, time, title in panels:
        folder = os.path.join(out, name)
        shot = snapshot(folder, snapshot_index(folder, time))
        shots.append(shot)
        vmax = max(vmax, shot[0][1].max())
    for ax, (name, time, title), shot in zip(axes, panels, shots):
        (xy, vm), fem = shot
        for points, cells in fem:
            ax.tripcolor(points[:, 0], points[:, 1], cells,
                         np.zeros(len(cells)), cmap="Greys", vmin=0, vmax=2,
                         edgecolors="0.4", linewidth=0.3)
        sc = ax.scatter(xy[:, 0], xy[:, 1], c=vm, s=3, cmap="viridis",
                        vmin=0, vmax=vmax)
        ax.set_xlim(0.05, 0.8)
        ax.set_ylim(0.078, 0.15)
        ax.set_aspect("equal")
        ax.set_title(title, fontsize=9)
        ax.tick_params(labelsize=7)
    fig.colorbar(sc, ax=axes, label="von Mises [Pa]", shrink=0.6)
    fig.suptitle("rotated frame: slope horizontal, gravity tilted by "
                 "theta = atan 0.2 (the support plate has left the view "
                 "after the release)", fontsize=9)
    fig.savefig(os.path.join(IMAGES, "slope_scene.png"), dpi=75)
    plt.close(fig)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "output"
    os.makedirs(IMAGES, exist_ok=True)
    plot_curves(out)
    plot_scene(out)


if __name__ == "__main__":
    main()
