#!/usr/bin/python3
"""The Hertz ratio of a run of prm/experiments/6_3_hertz/ at its last
particle snapshot, for `tools/bfemp-study` (quantity = "script"):

    /usr/bin/python3 doc/experiments/hertz_measure.py RUN_FOLDER

prints F / F_Hertz(a) on its last line, with F the contact force on the
bottom plate and a the mean of the half-widths of the particles within dhat
of the plate and within dhat plus one particle spacing (the contact edge lies
between the two layers; plot_hertz.py draws both). F_Hertz = pi E a^2 /
(4 (1 - nu^2) R) (plane strain). The ratio tends to 1 as the particle
spacing shrinks, up to the model's own difference from Hertz.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_hertz import measure  # noqa: E402


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    run = measure(sys.argv[1])
    if len(run["rows"]) == 0:
        sys.exit(f"{sys.argv[1]}: no snapshot with contact on the bottom "
                 "plate")
    t, F, a, a_next = run["rows"][-1]
    a_mid = 0.5 * (a + a_next)
    hertz = math.pi * run["E"] * a_mid**2 / (
        4. * (1. - run["nu"]**2) * run["R"])
    print(f"t = {t:g} s: F = {F:.6g} N/m, a = {a:.4g} .. {a_next:.4g} m, "
          f"F_Hertz(a_mid) = {hertz:.6g} N/m")
    print(f"{F / hertz:.8g}")


if __name__ == "__main__":
    main()
