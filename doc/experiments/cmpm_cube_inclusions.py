#!/usr/bin/python3
"""How the heterogeneous cube's r_u (seed 002 Section 8.1.4, eq. 38) depends
on how much of the cube its soft inclusions fill.

The seed gives neither the cube's size nor its inclusions: only "a
simplified version" of the bending beam (E 1e2 columns in E 1e5), pulled up
by 5000 N/m^2 on its top face, and r_u 0.040 (first Newton step in the local
problem) and 0.031 (full Newton) at 0.05 s. bfemp's cube
(prm/cmpm/heterogeneous_cube_*.prm, doc/experiments/make_cmpm_prms.py) has
four soft columns filling 15.8 % of it. This study scales the columns'
semi-axes by the given factors (0: no columns, a homogeneous cube), keeps
their centres and everything else, and runs for each factor cMPM with the
first Newton step, cMPM with full Newton and BSMPM-fine (the reference) to
0.05 s. Each row: the soft fraction of the cube, and the max r_u over the
five steps and r_u at 0.05 s of both cMPM runs.

    /usr/bin/python3 doc/experiments/cmpm_cube_inclusions.py [options]

options:
  --bfemp PATH    the bfemp executable (default: build/bfemp)
  --scales LIST   factors on the columns' semi-axes, comma separated, in
                  [0, 1] (default 0,0.25,0.5,0.75,1)
  --out DIR       work folder (default: output/cmpm_cube_inclusions); the
                  table goes to DIR/inclusions.csv
  --quiet         no progress lines

Resumable: a factor whose DIR/scale_<f>/result.csv exists is not run again.
Every CSV is written complete or not at all. About 15 s per factor in 2D on
a 2-core machine. doc/cmpm.md ("Heterogeneous cube") discusses the result;
doc/experiments/data/cmpm_cube_inclusions_2d.csv is a copy of one run.

Needs numpy and the vtk Python module (Debian: python3-numpy,
python3-vtk9)."""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_cmpm_prms  # noqa: E402
import particle_error  # noqa: E402
from cmpm_beam_layouts import read_result, run_bfemp  # noqa: E402
import parameter_study  # noqa: E402
from run_data import write_atomically, write_table  # noqa: E402

DIM = 2
END_TIME = 0.05
COLUMNS = ["column_scale", "soft_fraction", "max_r_u_first", "max_r_u_full",
           "r_u_end_first", "r_u_end_full"]
VARIANTS = ("", "full_newton", "fine")  # first Newton step, full, reference


def soft_fraction(scale):
    """The columns' share of the unit cube: their ellipses lie inside it
    for every scale up to 1 (centres 0.25-0.75 from the sides, semi-axes at
    most 0.15), so it is the sum of pi a b."""
    return sum(math.pi * a * b * scale**2
               for _, _, a, b, _ in make_cmpm_prms.HCUBE_COLUMNS)


def write_scene(folder, scale):
    """The three prm files of one scale and the wrappers that run them
    quietly; returns (run name, wrapper) per variant."""
    os.makedirs(folder, exist_ok=True)
    name = make_cmpm_prms.name_of
    write_atomically(os.path.join(folder, name("heterogeneous_cube", DIM, "")),
                     make_cmpm_prms.heterogeneous_cube(DIM, scale))
    runs = []
    for variant in VARIANTS:
        file = name("heterogeneous_cube", DIM, variant)
        if variant:
            write_atomically(os.path.join(folder, file),
                             make_cmpm_prms.heterogeneous_cube_variant(
                                 DIM, variant))
        run = f"cmpm_heterogeneous_cube_{DIM}d" + (f"_{variant}" if variant
                                                   else "")
        wrapper = os.path.join(folder, f"run_{variant or 'first'}.prm")
        write_atomically(wrapper, f"include {file}\nsubsection run\n"
                         "  set quiet = true\nend\n")
        runs.append((run, wrapper))
    return runs


def study_scale(bfemp, folder, scale):
    """Runs one scale (or reads its result.csv) and returns its row."""
    result = os.path.join(folder, "result.csv")
    row = read_result(result, COLUMNS)
    if row is not None:
        return row
    runs = write_scene(folder, scale)
    for _, wrapper in runs:
        run_bfemp(bfemp, folder, wrapper)
    first, full, fine = (os.path.join(folder, "output", run)
                         for run, _ in runs)
    row = {"column_scale": f"{scale:.4f}",
           "soft_fraction": f"{soft_fraction(scale):.4f}"}
    for label, path in (("first", first), ("full", full)):
        rows = particle_error.compare(fine, path)
        end = [r for r in rows
               if abs(r[0] - END_TIME) <= particle_error.TIME_TOLERANCE]
        if not end:
            raise particle_error.ToolError(
                f"{path}: no snapshot at t = {END_TIME}")
        row[f"max_r_u_{label}"] = f"{max(r[1] for r in rows):.5f}"
        row[f"r_u_end_{label}"] = f"{end[0][1]:.5f}"
    write_table(result, COLUMNS, [row])
    return row


def main():
    parameter_study.main(
        __doc__, "cmpm_cube_inclusions.py", "scales", "scale",
        "0,0.25,0.5,0.75,1", (0.0, 1.0),
        "above 1 the columns leave the cube or overlap", study_scale,
        lambda f, r: (f"scale {f:g} (soft fraction {r['soft_fraction']}): r_u "
                       f"at {END_TIME} s first Newton step {r['r_u_end_first']}"
                       f", full Newton {r['r_u_end_full']}"),
        "inclusions.csv", COLUMNS, particle_error.ToolError)


if __name__ == "__main__":
    main()
