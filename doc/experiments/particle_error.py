#!/usr/bin/python3
"""The errors r_u and r_sigma of seed 002 eq. (38) of a run against a
reference run on the same particles, at every output time of the run.

    r_u     = sqrt( int |u - u_ref|^2 dV / int |u_ref|^2 dV )
    r_sigma = sqrt( int (s - s_ref)^2 dV / int s_ref^2 dV )

u is the particle displacement x - X, s the von Mises stress. The integrals
are particle sums weighted with the reference's current particle volumes
J V_p^0 (the body as the benchmark has it at that time). The seed compares
cMPM, BSMPM-coarse and linear MPM against BSMPM-fine "on the same
particles": the particles are matched by their rest position X = x - u (and
must carry the same material), not by index, because a different grid
samples them in a different order (points are in particle-id order within
a run, so one matching serves all snapshots). A run whose particles are not
the reference's is refused.

usage:
  particle_error.py REFERENCE RUN [--csv FILE] [--quiet]
  particle_error.py --self-test

REFERENCE and RUN are run folders (holding particles.pvd) or .pvd files. For
every snapshot of RUN whose time the reference also has (to 1e-9 s), one row
"time,r_u,r_sigma" goes to the CSV (default: RUN/particle_error.csv, written
complete or not at all). Times at which the reference displacement or stress
vanishes everywhere (t = 0 of a body that starts at rest) are skipped: the
relative error is undefined there; r_sigma is left empty where the reference
stress vanishes. The last line printed gives the maxima over time, the seed's max(r_u).
--self-test writes synthetic snapshots with a known difference and checks the
tool on them (exit status 0 when every check holds).

Needs numpy and the vtk Python module (Debian: python3-numpy,
python3-vtk9)."""

import argparse
import math
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_data  # noqa: E402

TIME_TOLERANCE = 1e-9


class ToolError(Exception):
    """A refusal with a message for the user."""


def series(path):
    """(time, vtu file) pairs of a run folder or .pvd file."""
    pvd = path if path.endswith(".pvd") else os.path.join(path,
                                                          "particles.pvd")
    if not os.path.isfile(pvd):
        raise ToolError(f"{pvd}: no such particle series (expected a run "
                        "folder with particles.pvd, or a .pvd file)")
    return run_data.pvd(pvd)


def snapshot(path):
    """The particle fields of one VTU file as numpy arrays."""
    from vtk.util.numpy_support import vtk_to_numpy

    if not os.path.isfile(path):
        raise ToolError(f"{path}: no such file")
    grid = run_data.read_grid(path)
    data = grid.GetPointData()
    fields = {}
    for name in ("displacement", "von_mises", "J", "volume", "material_id"):
        array = data.GetArray(name)
        if array is None:
            raise ToolError(f"{path}: no point array '{name}' (written by "
                            "bfemp's particle output since 2026-11-26)")
        fields[name] = vtk_to_numpy(array).astype(float)
    fields["x"] = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    fields["X"] = fields["x"] - fields["displacement"]
    return fields


def match(reference, run, label):
    """The permutation p with run[p] the reference's particles: each
    reference particle's nearest run particle by rest position (VTK's static
    point locator). The VTU files hold single-precision floats, so rest
    positions agree to about 1e-7 of the body's size, not exactly."""
    import vtk
    from vtk.util.numpy_support import numpy_to_vtk

    if len(reference["X"]) != len(run["X"]):
        raise ToolError(f"{label}: {len(run['X'])} particles against the "
                        f"reference's {len(reference['X'])}; the errors of "
                        "eq. (38) need the same particles in both runs")
    points = vtk.vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(run["X"]), deep=True))
    cloud = vtk.vtkPolyData()
    cloud.SetPoints(points)
    locator = vtk.vtkStaticPointLocator()
    locator.SetDataSet(cloud)
    locator.BuildLocator()
    permutation = np.array(
        [locator.FindClosestPoint(x) for x in reference["X"]], dtype=int)
    if len(np.unique(permutation)) != len(permutation):
        raise ToolError(f"{label}: two particles of the reference have the "
                        "same nearest particle in the run; the runs do not "
                        "share their particles")
    check_match(reference, run, permutation, label)
    return permutation


def check_match(reference, run, permutation, label):
    """Refuses a permutation under which rest positions or materials
    differ."""
    extent = np.ptp(reference["X"], axis=0).max() or 1.0
    gap = np.abs(reference["X"] - run["X"][permutation]).max()
    if gap > 1e-5 * extent:
        raise ToolError(f"{label}: the particles' rest positions differ from "
                        f"the reference's by up to {gap:.3g} (allowed "
                        f"{1e-5 * extent:.3g}); the runs do not share their "
                        "particles")
    if np.any(reference["material_id"] != run["material_id"][permutation]):
        raise ToolError(f"{label}: particles at the same rest position carry "
                        "different materials")


def errors(reference, run, p):
    """(r_u, r_sigma) of eq. (38) with run[p] matched to the reference;
    None where the reference field is zero."""
    weight = reference["J"] * reference["volume"]
    du = run["displacement"][p] - reference["displacement"]
    ds = run["von_mises"][p] - reference["von_mises"]
    u_norm = np.sum(weight * np.sum(reference["displacement"]**2, axis=1))
    s_norm = np.sum(weight * reference["von_mises"]**2)
    r_u = math.sqrt(np.sum(weight * np.sum(du**2, axis=1)) /
                    u_norm) if u_norm > 0 else None
    r_s = math.sqrt(np.sum(weight * ds**2) / s_norm) if s_norm > 0 else None
    return r_u, r_s


def compare(reference_path, run_path):
    """[(time, r_u, r_sigma)] at the times both series have."""
    reference = series(reference_path)
    rows, permutation = [], None
    for time, vtu in series(run_path):
        hits = [f for t, f in reference if abs(t - time) <= TIME_TOLERANCE]
        if not hits:
            continue
        ref, run, label = snapshot(hits[0]), snapshot(vtu), f"{vtu} (t = {time:g})"
        # points are in particle-id order in every snapshot of a run, so
        # the matching found at the first common time holds at all others
        if permutation is None:
            permutation = match(ref, run, label)
        else:
            check_match(ref, run, permutation, label)
        r_u, r_s = errors(ref, run, permutation)
        if r_u is None:
            continue
        rows.append((time, r_u, r_s))
    if not rows:
        raise ToolError(f"{run_path}: no output time in common with "
                        f"{reference_path} at which the reference moved")
    return rows


def write_csv(path, rows):
    """Writes the rows complete or not at all (run_data.write_atomically)."""
    lines = ["time,r_u,r_sigma"]
    for time, r_u, r_s in rows:
        stress = "" if r_s is None else f"{r_s:.9e}"
        lines.append(f"{time:.9g},{r_u:.9e},{stress}")
    run_data.write_atomically(path, "\n".join(lines) + "\n")


def write_snapshot(path, X, u, von_mises, volume, J):
    """A particle VTU file like bfemp's (the arrays this tool reads)."""
    import vtk
    from vtk.util.numpy_support import numpy_to_vtk

    points = vtk.vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(X + u), deep=True))
    grid = vtk.vtkUnstructuredGrid()
    grid.SetPoints(points)
    for name, values in (("displacement", u), ("von_mises", von_mises),
                         ("J", J), ("volume", volume),
                         ("material_id", np.zeros(len(X)))):
        array = numpy_to_vtk(np.ascontiguousarray(values, dtype=float),
                             deep=True)
        array.SetName(name)
        grid.GetPointData().AddArray(array)
    writer = vtk.vtkXMLUnstructuredGridWriter()
    writer.SetFileName(path)
    writer.SetInputData(grid)
    writer.Write()


def write_series(folder, snapshots):
    os.makedirs(folder, exist_ok=True)
    entries = []
    for i, (time, fields) in enumerate(snapshots):
        name = f"particles_{i:05d}.vtu"
        write_snapshot(os.path.join(folder, name), *fields)
        entries.append(f'<DataSet timestep="{time}" file="{name}"/>')
    with open(os.path.join(folder, "particles.pvd"), "w") as out:
        out.write('<?xml version="1.0"?>\n<VTKFile type="Collection" '
                  'version="0.1">\n<Collection>\n' + "\n".join(entries) +
                  "\n</Collection>\n</VTKFile>\n")


def self_test():
    """Synthetic reference and run with a known difference: the run's
    displacement is the reference's plus a field orthogonal to it, its stress
    the reference's times 1 + 0.1 t, its particles in reverse order, and the
    volumes non-uniform."""
    rng = np.random.default_rng(7)
    n = 200
    X = np.column_stack([rng.uniform(0, 2, n), rng.uniform(0, 1, n),
                         np.zeros(n)])
    volume = rng.uniform(0.5, 1.5, n) * 1e-3
    J = rng.uniform(0.9, 1.1, n)
    failures = 0
    with tempfile.TemporaryDirectory() as folder:
        reference, run, expected = [], [], []
        for time in (0.0, 0.5, 1.0):
            u_ref = np.zeros((n, 3))
            u_ref[:, 1] = -time * X[:, 0]
            delta = np.zeros((n, 3))
            delta[:, 0] = 0.2 * time
            s_ref = 100.0 * time * (1 + X[:, 1])
            s_run = s_ref * (1 + 0.1 * time)
            reference.append((time, (X, u_ref, s_ref, volume, J)))
            flip = slice(None, None, -1)
            run.append((time, (X[flip], (u_ref + delta)[flip], s_run[flip],
                               volume[flip], J[flip])))
            w = J * volume
            if time > 0:
                expected.append(
                    (time, 0.2 * time * math.sqrt(w.sum() / np.sum(
                        w * u_ref[:, 1]**2)), 0.1 * time))
        write_series(os.path.join(folder, "reference"), reference)
        write_series(os.path.join(folder, "run"), run)
        rows = compare(os.path.join(folder, "reference"),
                       os.path.join(folder, "run"))
        ok = len(rows) == len(expected)
        print(("OK   " if ok else "FAIL ") +
              f"{len(rows)} rows (t = 0 skipped), expected {len(expected)}")
        failures += not ok
        for (t, r_u, r_s), (_, e_u, e_s) in zip(rows, expected):
            ok = abs(r_u - e_u) <= 1e-12 * e_u and abs(r_s - e_s) <= 1e-12 * e_s
            print(("OK   " if ok else "FAIL ") +
                  f"t = {t:g}: r_u {r_u:.12f} (exact {e_u:.12f}), r_sigma "
                  f"{r_s:.12f} (exact {e_s:.12f})")
            failures += not ok
        # a run on other particles is refused
        shifted = [(t, (f[0] + 1e-2,) + f[1:]) for t, f in run]
        write_series(os.path.join(folder, "other"), shifted)
        try:
            compare(os.path.join(folder, "reference"),
                    os.path.join(folder, "other"))
            print("FAIL a run on other particles was accepted")
            failures += 1
        except ToolError as error:
            print("OK   refused: " + str(error).split(": ", 1)[1])
    return failures


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("reference", nargs="?")
    parser.add_argument("run", nargs="?")
    parser.add_argument("--csv")
    parser.add_argument("--quiet", action="store_true")
    parser.add_argument("--self-test", action="store_true")
    arguments = parser.parse_args()
    if arguments.self_test:
        return 1 if self_test() else 0
    if not arguments.reference or not arguments.run:
        parser.error("REFERENCE and RUN are required")
    try:
        rows = compare(arguments.reference, arguments.run)
    except ToolError as error:
        print("particle_error.py: " + str(error), file=sys.stderr)
        return 2
    folder = (arguments.run if os.path.isdir(arguments.run) else
              os.path.dirname(arguments.run))
    write_csv(arguments.csv or os.path.join(folder, "particle_error.csv"),
              rows)
    if not arguments.quiet:
        for time, r_u, r_s in rows:
            stress = "-" if r_s is None else f"{r_s:.4e}"
            print(f"t = {time:.6g}: r_u {r_u:.4e}  r_sigma {stress}")
    stresses = [r[2] for r in rows if r[2] is not None]
    max_stress = f"{max(stresses):.4e}" if stresses else "-"
    print(f"max r_u {max(r[1] for r in rows):.4e}  max r_sigma "
          f"{max_stress}  over {len(rows)} output times")
    return 0


if __name__ == "__main__":
    sys.exit(main())
