#!/usr/bin/python3
"""How the lattice bar's r_u (seed 002 Section 8.1.3, eq. 38) depends on how
many knot spans its struts are wide.

The seed shows no lattice geometry. bfemp's bar (prm/cmpm/lattice_bar_*.prm,
doc/experiments/make_cmpm_prms.py) has square holes on a lattice of pitch
0.5 m, struts 0.15 m wide: three fine knot spans of 0.05 m. This study keeps
the void fraction (49 %: holes 0.7 pitch, struts 0.3 pitch) and the
discretization (H = 0.25 m, L = H/2, n = 7) and widens the lattice, so that
the struts are 3, 4 and 6 knot spans wide (pitch 0.5, 2/3, 1.0 m). For each
pitch it runs cMPM on boundary B-spline and on B-spline coarse elements and
BSMPM-fine (the reference) to 1.0 s, the seed's first snapshot, and writes
one row: the max r_u of both cMPM runs to 1.0 s, and the sag (the
volume-weighted mean vertical displacement) of all three at 1.0 s.

    /usr/bin/python3 doc/experiments/cmpm_lattice_struts.py [options]

options:
  --bfemp PATH    the bfemp executable (default: build/bfemp)
  --pitches LIST  lattice pitches in m, comma separated (default
                  0.5,0.666667,1.0); 8 / pitch and 2 / pitch are rounded
                  to whole numbers of holes
  --out DIR       work folder (default: output/cmpm_lattice_struts); the
                  table goes to DIR/struts.csv
  --quiet         no progress lines

Resumable: a pitch whose DIR/pitch_<p>/result.csv exists is not run again.
Every CSV is written complete or not at all. About a minute per pitch in 2D
on a 2-core machine. doc/cmpm.md ("Lattice bar") discusses the result;
doc/experiments/data/cmpm_lattice_struts_2d.csv is a copy of one run.

Needs numpy and the vtk Python module (Debian: python3-numpy,
python3-vtk9)."""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_cmpm_prms  # noqa: E402
import particle_error  # noqa: E402
from cmpm_beam_layouts import read_result, run_bfemp  # noqa: E402
import parameter_study  # noqa: E402
from run_data import write_atomically, write_table  # noqa: E402

DIM = 2
END_TIME = 1.0
COLUMNS = ["pitch", "strut_width", "strut_spans", "max_r_u_boundary_bspline",
           "max_r_u_bspline", "sag_fine", "sag_boundary_bspline",
           "sag_bspline"]
VARIANTS = ("", "bspline", "fine")  # boundary B-spline, B-spline, reference


def write_scene(folder, pitch):
    """The three prm files of one pitch and the wrappers that run them to
    END_TIME quietly; returns (run name, wrapper) per variant."""
    os.makedirs(folder, exist_ok=True)
    name = make_cmpm_prms.name_of
    write_atomically(os.path.join(folder, name("lattice_bar", DIM, "")),
                     make_cmpm_prms.lattice_bar(DIM, pitch))
    runs = []
    for variant in VARIANTS:
        file = name("lattice_bar", DIM, variant)
        if variant:
            write_atomically(os.path.join(folder, file),
                             make_cmpm_prms.lattice_bar_variant(DIM, variant))
        run = f"cmpm_lattice_bar_{DIM}d" + (f"_{variant}" if variant else "")
        wrapper = os.path.join(folder, f"run_{variant or 'boundary'}.prm")
        write_atomically(wrapper, f"include {file}\nsubsection run\n"
                         f"  set quiet    = true\n  set end time = {END_TIME}"
                         "\nend\n")
        runs.append((run, wrapper))
    return runs


def sag(path):
    """Volume-weighted mean vertical displacement of the run at END_TIME."""
    for t, vtu in particle_error.series(path):
        if abs(t - END_TIME) <= particle_error.TIME_TOLERANCE:
            s = particle_error.snapshot(vtu)
            weight = s["J"] * s["volume"]
            return float((weight * s["displacement"][:, 1]).sum() /
                         weight.sum())
    raise particle_error.ToolError(f"{path}: no snapshot at t = {END_TIME}")


def study_pitch(bfemp, folder, pitch):
    """Runs one pitch (or reads its result.csv) and returns its row."""
    result = os.path.join(folder, "result.csv")
    row = read_result(result, COLUMNS)
    if row is not None:
        return row
    runs = write_scene(folder, pitch)
    for _, wrapper in runs:
        run_bfemp(bfemp, folder, wrapper)
    boundary, bspline, fine = (os.path.join(folder, "output", run)
                               for run, _ in runs)
    strut = 0.3 * pitch
    row = {"pitch": f"{pitch:.4f}", "strut_width": f"{strut:.4f}",
           "strut_spans": f"{strut / make_cmpm_prms.LATTICE_SPAN:.2f}",
           "sag_fine": f"{sag(fine):.5f}"}
    for label, path in (("boundary_bspline", boundary), ("bspline", bspline)):
        rows = particle_error.compare(fine, path)
        row[f"max_r_u_{label}"] = f"{max(r[1] for r in rows):.5f}"
        row[f"sag_{label}"] = f"{sag(path):.5f}"
    write_table(result, COLUMNS, [row])
    return row


def main():
    parameter_study.main(
        __doc__, "cmpm_lattice_struts.py", "pitches", "pitch",
        "0.5,0.666667,1.0", (0.1, 2.0),
        "m; the bar is 2 m high", study_pitch,
        lambda p, r: (f"pitch {p:g} m (struts {r['strut_spans']} knot spans): "
                       f"max r_u boundary B-spline "
                       f"{r['max_r_u_boundary_bspline']}, B-spline "
                       f"{r['max_r_u_bspline']}"),
        "struts.csv", COLUMNS, particle_error.ToolError)


if __name__ == "__main__":
    main()
