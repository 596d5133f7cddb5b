#!/usr/bin/env python3
"""Seed 002 Fig. 13 from bfemp's own output: the four components of the
matrix-valued coarsened shape function Phi_I of the upper right corner node
of one 2D coarse element (boundary B-spline, L = H, n = 7) with a circular
hard filling (E 1e8 in a matrix of E 1e5, radius H/3).

    build/benchmarks/cmpm_shape_functions --phi-csv /tmp/cmpm_phi.csv
    python3 doc/images/plot_cmpm_shape_function.py /tmp/cmpm_phi.csv \
        doc/images/cmpm_shape_function.png
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    data = np.loadtxt(sys.argv[1], delimiter=",", skiprows=1)
    n = int(round(np.sqrt(len(data))))
    x = data[:, 0].reshape(n, n)
    y = data[:, 1].reshape(n, n)
    names = ["(Phi_I)_xx", "(Phi_I)_xy", "(Phi_I)_yx", "(Phi_I)_yy"]
    figure, axes = plt.subplots(1, 4, figsize=(15, 3.6))
    for k, axis in enumerate(axes):
        z = data[:, 2 + k].reshape(n, n)
        image = axis.contourf(x, y, z, 30, cmap="viridis")
        axis.add_patch(plt.Circle((0.5, 0.5), 1.0 / 3.0, fill=False,
                                  color="white", linestyle="--"))
        axis.set_aspect("equal")
        axis.set_title(names[k])
        axis.set_xlabel("x / H")
        if k == 0:
            axis.set_ylabel("y / H")
        figure.colorbar(image, ax=axis, shrink=0.8)
    figure.suptitle("cMPM shape function of the upper right corner node, "
                    "element with a stiff circular filling (dashed)")
    figure.tight_layout()
    figure.savefig(sys.argv[2], dpi=110)


if __name__ == "__main__":
    main()
