#!/usr/bin/python3
"""Draws seed 002 Figs. 28-29 for the static three-material beam (Section
8.2.1) from bfemp's output: the deformed beam of the FE_Q(2) benchmark,
BSMPM-fine and cMPM, coloured by von Mises stress on one scale, and the
displacement difference |u - u_FE| of the two MPM runs at each particle.

  build/bfemp --fe-reference prm/cmpm/three_material_beam_2d.prm
  build/bfemp prm/cmpm/three_material_beam_2d.prm
  build/bfemp prm/cmpm/three_material_beam_2d_fine.prm
  /usr/bin/python3 doc/experiments/plot_cmpm_three_material_beam.py output 2d \\
      doc/images/cmpm_three_material_beam_2d.png

The first argument is the folder that holds the run folders
(cmpm_three_material_beam_2d{_fe_reference,,_fine}); the last snapshot of
each is drawn. In 3D the mid-depth slice of particles is drawn."""

import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import particle_error  # noqa: E402
import run_data  # noqa: E402

RUNS = [("_fe_reference", "FE_Q(2) benchmark"), ("_fine", "BSMPM-fine"),
        ("", "cMPM")]


def last_snapshot(folder):
    series = run_data.pvd(os.path.join(folder, "particles.pvd"))
    return particle_error.snapshot(series[-1][1])


def mid_slice(fields, dim):
    """All particles in 2D; in 3D those nearest the mid-depth plane."""
    if dim == 2:
        return np.ones(len(fields["X"]), dtype=bool)
    z = fields["X"][:, 2]
    middle = 0.5 * (z.min() + z.max())
    nearest = np.min(np.abs(z - middle))
    return np.abs(np.abs(z - middle) - nearest) < 1e-6


def main():
    folder, dim_text, target = sys.argv[1], sys.argv[2], sys.argv[3]
    dim = int(dim_text[0])
    base = os.path.join(folder, f"cmpm_three_material_beam_{dim_text}")
    runs = {suffix: last_snapshot(base + suffix) for suffix, _ in RUNS}
    reference = runs["_fe_reference"]
    vmax = np.percentile(reference["von_mises"], 99.5)
    figure, axes = plt.subplots(len(RUNS) + 2, 1, figsize=(9, 11))
    for axis, (suffix, label) in zip(axes, RUNS):
        fields = runs[suffix]
        keep = mid_slice(fields, dim)
        points = axis.scatter(fields["x"][keep, 0], fields["x"][keep, 1],
                              c=fields["von_mises"][keep], s=0.3,
                              cmap="viridis", vmin=0, vmax=vmax)
        axis.set_title(f"{label}: von Mises stress [Pa]")
        axis.set_aspect("equal")
        axis.set_xlim(-0.2, 8.2)
        figure.colorbar(points, ax=axis, shrink=0.8)
    for axis, suffix, label in ((axes[3], "_fine", "BSMPM-fine"),
                                (axes[4], "", "cMPM")):
        run = runs[suffix]
        p = particle_error.match(reference, run, label)
        r_u, r_sigma = particle_error.errors(reference, run, p)
        difference = np.linalg.norm(run["displacement"][p] -
                                    reference["displacement"], axis=1)
        keep = mid_slice(reference, dim)
        points = axis.scatter(reference["X"][keep, 0], reference["X"][keep, 1],
                              c=difference[keep], s=0.3, cmap="magma")
        axis.set_title(f"{label}: |u - u_FE| [m] at the rest positions "
                       f"(r_u {r_u:.4f}, r_sigma {r_sigma:.3f})")
        axis.set_aspect("equal")
        axis.set_xlim(-0.2, 8.2)
        figure.colorbar(points, ax=axis, shrink=0.8)
    figure.tight_layout()
    temporary = target + ".part.png"
    figure.savefig(temporary, dpi=110)
    os.replace(temporary, target)


if __name__ == "__main__":
    main()
