#!/usr/bin/env python3
"""Writes the prm files of BFEMP Section 6.5 (convergence under refinement)
into prm/experiments/6_5_refinement/: one standalone file per resolution N
and particles per cell, plus the reduced set that ctest runs
(tests/experiments/refinement.cc).

    /usr/bin/python3 doc/experiments/make_refinement_prms.py [target directory]

The set: N = 2, 4, 6, 8, 10, 12, 16, 20 and the reference N = 30, each with
PPC 4, 9, 16 (particles per cell and direction 2, 3, 4): 27 files named
refinement_N<N>_ppc<PPC>.prm. The paper runs every even N up to 20; the
two even N left out (14, 18) would add points on the same line at a cost
comparable to N = 16 and 20.
Reduced set: refinement_reduced_N<N>.prm, N = 2, 4, 8 and the reference
N = 12, PPC 16, settled 6 s instead of 8 s.
"""
import os
import sys

HEADER = """# BFEMP Section 6.5 "Convergence under Refinement" (Figures 13, 14): {what}
# Written by doc/experiments/make_refinement_prms.py; edit that script, not
# this file.
#
# Paper: an MPM box 2 x 1 m (E = 4e4 Pa, nu = 0.4, rho = 1e3 kg/m^2) on an
# FEM box 4 x 1 m (E = 4e4 Pa, nu = 0.4, rho = 1e2 kg/m^2) whose bottom is
# held; MPM grid dx = minimal FEM edge = 1/N, dhat = 1/N^2, N even in 2..20,
# reference N = 30; the MPM box starts dx above the FEM box and settles under
# gravity 10 m/s^2 until static. Particles at sub-cell centres, PPC 4, 9, 16.
# PIC, backward Euler with large steps (up to the MPM CFL limit), eps_d =
# 1e-9 m/s, kappa = 1e6 Pa. Error: |centre-of-mass height of the whole system
# (MPM + FEM) - that of N = 30|; the paper reports order 2.75 with PPC 16.
#
# This file: N = {N}, dx = 1/N = {dx:.17g} m, dhat = 1/N^2 = {dhat:.17g} m,
# PPC = {ppc} (particles per cell and direction {ppd}).
# Choices:
# - neo-Hookean both bodies (the paper's default); the static load compresses
#   the MPM box by about 25 %, so the equilibrium is nonlinear.
# - FEM box: fem_box_N{N}.geo beside this file, a structured gmsh mesh of
#   4N x N squares split into two triangles with alternating diagonals:
#   min edge = legs = 1/N (= dx), {fem_v} vertices, {fem_t} triangles. The
#   built-in rectangle has the same counts, but all its diagonals lean one
#   way; that asymmetry pushes the MPM box sideways, and on the frictionless
#   contact the box then keeps sliding slowly to and fro (a nearly free mode,
#   period ~6 s, hardly damped), so the system never becomes static. The
#   alternating mesh is mirror-symmetric about x = 2, as the rest of the scene.
#   Bottom nodes (y = 0) fixed.
# - MPM box [1, 3] x [1 + dx, 2 + dx] (cell-aligned, so sub-cell centres fill
#   it exactly): {n_p} particles; its lowest particles are dx + dx/(2 {ppd})
#   above the FEM box, i.e. the box is dx above it.
# - Time step: the paper's "large steps up to the MPM CFL limit" is read as
#   the particle-speed CFL of implicit MPM (a particle crosses at most a
#   fraction of a cell per step; the elastic wave CFL of explicit MPM, dx / c
#   with c = 9.3 m/s, would be small steps): time step mode = CFL with CFL
#   number 0.5, capped at {dtmax} s (the first step, from rest, takes the cap:
#   the box moves 0.4 m within it, into contact for N > 2). Backward Euler's numerical
#   damping (omega dt ~ 1 for the box's bouncing mode) then brings the system
#   to rest. Projected Newton alone ('solver/Hessian projection = always')
#   converges only linearly here (the projection acts at this compressed
#   equilibrium) and needs up to 900 iterations in a step; the default exact
#   Hessian needs at most ~170. 'maximum Newton iterations' = 1000 allows
#   both.
# - End time {end} s: the centre-of-mass height h is then static. Full runs
#   (8 s): |h(8 s) - h(7 s)| < 1e-9 m for most, at most 6e-5 m (N = 2,
#   PPC 4, a slow creep), far below each run's error (see
#   doc/experiments/refinement.md); reduced runs (6 s, PPC 16): < 1e-7 m.
# - Grid [0, 4] x [0, 3] (whole multiples of every dx), no walls: the grid
#   only carries the MPM box; the FEM box is held by its own prescribed nodes.
set dimension            = 2
set number of bodies     = 1
set number of FEM bodies = 1

subsection run
  set name     = {name}
  set end time = {end}
end

subsection output
  set interval             = {interval}
  set diagnostics interval = 1
  set write particles      = true
end

subsection grid
  set lower corner = 0, 0
  set upper corner = 4, 3
  set cell size    = {dx:.17g}
  set kernel       = quadratic
end

subsection gravity
  set acceleration = 0, -10
end

subsection boundaries
  set walls = none
end

subsection transfer
  set scheme = PIC
end

subsection time
  set integrator        = implicit backward Euler
  set time step mode    = CFL
  set CFL number        = 0.5
  set maximum time step = {dtmax}
end

subsection solver
  set Newton tolerance = 1e-9
  set maximum Newton iterations = 1000
end

subsection contact
  set activation distance = {dhat:.17g}
  set barrier stiffness   = 1e6
end

subsection body 0
  set particles per cell = {ppd}
  set sampling           = regular
  subsection primitive 0
    set type         = box
    set lower corner = 1, {y0:.17g}
    set upper corner = 3, {y1:.17g}
  end
  subsection material
    set model           = neo-Hookean
    set Young's modulus = 4e4
    set Poisson's ratio = 0.4
    set density         = 1e3
  end
end

subsection fem body 0
  subsection mesh
    set source             = file
    set file               = fem_box_N{N}.geo
    set target edge length = {dx:.17g}
  end
  subsection material
    set model           = neo-Hookean
    set Young's modulus = 4e4
    set Poisson's ratio = 0.4
    set density         = 1e2
  end
  subsection prescribed motion
    set nodes            = box
    set box lower corner = -1, -1e-6
    set box upper corner = 5, 1e-6
    set motion           = fixed
  end
end
"""

FULL_N = [2, 4, 6, 8, 10, 12, 16, 20, 30]
PPC = [4, 9, 16]
REDUCED_N = [2, 4, 8, 12]
FULL_END, REDUCED_END = 8.0, 6.0
DT_MAX = 0.2


GEO = """// FEM box 4 x 1 m of BFEMP Section 6.5 for N = {N} (dx = 1/N): 4N x N squares,
// each split into two triangles with alternating diagonals (mirror-symmetric
// about x = 2). Written by doc/experiments/make_refinement_prms.py.
N = {N};
Point(1) = {{0, 0, 0}};
Point(2) = {{4, 0, 0}};
Point(3) = {{4, 1, 0}};
Point(4) = {{0, 1, 0}};
Line(1) = {{1, 2}};
Line(2) = {{2, 3}};
Line(3) = {{3, 4}};
Line(4) = {{4, 1}};
Curve Loop(1) = {{1, 2, 3, 4}};
Plane Surface(1) = {{1}};
Transfinite Curve{{1, 3}} = 4 * N + 1;
Transfinite Curve{{2, 4}} = N + 1;
Transfinite Surface{{1}} = {{1, 2, 3, 4}} Alternate;
"""


def text(name, what, n, ppd, end):
    dx = 1.0 / n
    return HEADER.format(what=what, name=name, N=n, dx=dx, dhat=dx * dx,
                         ppc=ppd * ppd, ppd=ppd,
                         fem_v=(4 * n + 1) * (n + 1), fem_t=8 * n * n,
                         n_p=2 * n * n * ppd * ppd, y0=1 + dx, y1=2 + dx,
                         dtmax=DT_MAX, end=end, interval=end / 4)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    target = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        here, "..", "..", "prm", "experiments", "6_5_refinement")
    os.makedirs(target, exist_ok=True)
    for n in FULL_N:
        with open(os.path.join(target, "fem_box_N%d.geo" % n), "w") as f:
            f.write(GEO.format(N=n))
        for ppc in PPC:
            ppd = int(round(ppc ** 0.5))
            name = f"refinement_N{n}_ppc{ppc}"
            with open(os.path.join(target, name + ".prm"), "w") as f:
                f.write(text(name, f"full run N = {n}, PPC {ppc}.", n, ppd,
                             FULL_END))
    for n in REDUCED_N:
        name = f"refinement_reduced_N{n}"
        with open(os.path.join(target, name + ".prm"), "w") as f:
            f.write(text(name, f"reduced run for ctest, N = {n}.", n, 4,
                         REDUCED_END))


if __name__ == "__main__":
    main()
