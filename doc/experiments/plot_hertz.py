#!/usr/bin/python3
"""BFEMP Section 6.3, Brazilian disk / Hertz contact: contact force F on the
bottom plate vs contact half-width a (the paper's Figure 10) and a snapshot
of the compressed disk coloured by von Mises stress (Figure 9).

usage: /usr/bin/python3 doc/experiments/plot_hertz.py [OUTPUT_DIR] [RUN ...]

OUTPUT_DIR (default `output`) holds the run folders; the runs default to
hertz_linear and hertz_neohookean (prm/experiments/6_3_hertz/). For every
particle snapshot: F = -contact_force_m0_f0_y of diagnostics.csv at that time
(the bottom plate is FEM body 0), a = half the horizontal range of the
particles within dhat of the bottom plate's top face, and a_next = the same
for the particles within dhat + one particle spacing (the next particle
layer: the contact edge lies between a and a_next). Hertz (plane strain):
F = pi E a^2 / (4 (1 - nu^2) R). Writes doc/images/experiments/hertz_force.png
and hertz_disk.png. Needs numpy, matplotlib and the vtk Python module.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from run_data import csv, prm_entries, prm_entry, pvd, read_vtu  # noqa: E402
IMAGES = os.path.join(HERE, "..", "images", "experiments")


def measure(folder):
    prm = prm_entries(os.path.join(folder, "input.prm"))
    dhat = float(prm_entry(prm, "contact/activation distance"))
    E = float(prm_entry(prm, "body 0/material/Young's modulus"))
    nu = float(prm_entry(prm, "body 0/material/Poisson's ratio"))
    R = float(prm_entry(prm, "body 0/primitive 0/outer radius"))
    spacing = (float(prm_entry(prm, "grid/cell size")) /
               float(prm_entry(prm, "body 0/particles per cell")))
    model = prm_entry(prm, "body 0/material/model")
    d = csv(os.path.join(folder, "diagnostics.csv"))
    plate = read_vtu(pvd(os.path.join(folder, "fem_body_0.pvd"))[0][1])["points"]
    top = plate[:, 1].max()
    rows = []
    for t, path in pvd(os.path.join(folder, "particles.pvd")):
        k = int(np.argmin(np.abs(d["time"] - t)))
        F = -d["contact_force_m0_f0_y"][k]
        x = read_vtu(path)["points"]
        gap = x[:, 1] - top
        near = x[gap < dhat, 0]
        layer = x[gap < dhat + spacing, 0]
        if len(near) == 0 or F <= 0:
            continue
        rows.append((t, F, 0.5 * (near.max() - near.min()),
                     0.5 * (layer.max() - layer.min())))
    return dict(model=model, E=E, nu=nu, R=R, rows=np.array(rows), folder=folder)


def main():
    output = sys.argv[1] if len(sys.argv) > 1 else "output"
    names = sys.argv[2:] or ["hertz_linear", "hertz_neohookean"]
    os.makedirs(IMAGES, exist_ok=True)
    runs = [measure(os.path.join(output, n)) for n in names]
    fig, ax = plt.subplots(figsize=(5.5, 4))
    amax = 0.
    for j, r in enumerate(runs):
        t, F, a, a_next = r["rows"].T
        amax = max(amax, a_next.max())
        ax.errorbar(a, F, xerr=[np.zeros_like(a), a_next - a], fmt="o", ms=3,
                    color="C%d" % j, elinewidth=0.6, capsize=0,
                    label="%s (a .. next layer)" % r["model"])
        hertz = np.pi * r["E"] * a ** 2 / (4 * (1 - r["nu"] ** 2) * r["R"])
        for ti, Fi, ai, hi in zip(t, F, a, hertz):
            print("%s t = %.3f s: F = %.4g N/m, a = %.4f m, F_Hertz(a) = %.4g, ratio %.3f"
                  % (r["model"], ti, Fi, ai, hi, Fi / hi))
    r = runs[0]
    a = np.linspace(0, 1.05 * amax, 200)
    ax.plot(a, np.pi * r["E"] * a ** 2 / (4 * (1 - r["nu"] ** 2) * r["R"]), "k",
            label=r"Hertz $F = \pi E a^2 / (4 (1 - \nu^2) R)$")
    ax.set_xlabel("contact half-width a [m]")
    ax.set_ylabel("contact force F [N/m]")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(IMAGES, "hertz_force.png"), dpi=90)
    plt.close(fig)

    # the last snapshot of the first run, coloured by von Mises stress
    t, path = pvd(os.path.join(runs[0]["folder"], "particles.pvd"))[-1]
    snapshot = read_vtu(path)
    x, vm = snapshot["points"], snapshot["point_vm"]
    fig, axes = plt.subplots(1, 2, figsize=(8, 4))
    for ax, zoom in zip(axes, [False, True]):
        sc = ax.scatter(x[:, 0], x[:, 1], c=vm, s=0.2 if not zoom else 4,
                        cmap="viridis", linewidths=0)
        for b in (0, 1):
            p = read_vtu(pvd(os.path.join(runs[0]["folder"], "fem_body_%d.pvd" % b))[-1][1])["points"]
            ax.fill([p[:, 0].min(), p[:, 0].max(), p[:, 0].max(), p[:, 0].min()],
                    [p[:, 1].min(), p[:, 1].min(), p[:, 1].max(), p[:, 1].max()],
                    color="0.6")
        ax.set_aspect("equal")
        if zoom:
            ax.set_xlim(-0.3, 0.3)
            ax.set_ylim(-1.05, -0.85)
        ax.set_title(("zoom: bottom contact" if zoom else "t = %.2f s" % t), fontsize=9)
    fig.colorbar(sc, ax=axes, shrink=0.8, label="von Mises stress [Pa]")
    fig.savefig(os.path.join(IMAGES, "hertz_disk.png"), dpi=80)
    plt.close(fig)


if __name__ == "__main__":
    main()
