#!/usr/bin/python3
"""Reads a bfemp run folder back with VTK's own readers and checks it.

usage: read_vtu.py FOLDER N_PARTICLES TOTAL_MASS PX PY

FOLDER holds particles.pvd (+ particles_*.vtu) and, if written, grid.pvd
(+ grid_*.vtu). N_PARTICLES, TOTAL_MASS and the final linear momentum (PX,
PY) are what the simulation itself says; the last particle VTU must agree.
Prints one line per check ("OK ..." or "FAIL ...") and exits non-zero if
any check failed. Run with Debian's /usr/bin/python3 (python3-vtk9).
"""

import math
import os
import sys
import xml.etree.ElementTree as ElementTree

import vtk
from vtk.util import numpy_support
import numpy

# name -> number of components in the VTK file (2D vectors and tensors are
# padded to 3 and 9 components by deal.II's VTU writer)
PARTICLE_ARRAYS = {"velocity": 3, "displacement": 3, "cauchy_stress": 9,
                   "von_mises": 1, "J": 1, "mass": 1, "volume": 1, "material_id": 1,
                   "body_id": 1}
GRID_ARRAYS = {"mass": 1, "velocity": 3}

failures = 0


def check(condition, text):
    global failures
    print(("OK   " if condition else "FAIL ") + text)
    if not condition:
        failures += 1


def read_pvd(path):
    """(time, file) of every data set of a PVD collection, in file order."""
    root = ElementTree.parse(path).getroot()
    check(root.tag == "VTKFile" and root.get("type") == "Collection",
          os.path.basename(path) + " is a VTK collection")
    return [(float(d.get("timestep")), d.get("file"))
            for d in root.iter("DataSet")]


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def point_arrays(grid, expected, label):
    """Checks that the arrays exist with their component counts and finite
    values; returns them as numpy arrays."""
    data = grid.GetPointData()
    arrays = {}
    good = True
    for name, components in expected.items():
        array = data.GetArray(name)
        if array is None:
            check(False, label + ": array " + name + " exists")
            good = False
            continue
        values = numpy_support.vtk_to_numpy(array).reshape(
            array.GetNumberOfTuples(), array.GetNumberOfComponents())
        if array.GetNumberOfTuples() != grid.GetNumberOfPoints():
            check(False, "%s: %s has a value per point" % (label, name))
            good = False
        if array.GetNumberOfComponents() != components:
            check(False, "%s: %s has %d components, expected %d" %
                  (label, name, array.GetNumberOfComponents(), components))
            good = False
        if not numpy.all(numpy.isfinite(values)):
            check(False, label + ": " + name + " is finite")
            good = False
        arrays[name] = values
    return good, arrays


def time_field(grid):
    array = grid.GetFieldData().GetArray("TIME")
    return None if array is None else array.GetValue(0)


def check_series(folder, pvd_name, expected_arrays, check_vtu,
                 first_time_zero=True):
    """Common checks of one PVD series; check_vtu(index, grid, arrays) adds
    its own. Returns the (grid, arrays) of the last VTU."""
    series = read_pvd(os.path.join(folder, pvd_name))
    times = [t for t, _ in series]
    check(len(series) > 1, "%s: %d snapshots" % (pvd_name, len(series)))
    check(all(b > a for a, b in zip(times, times[1:])),
          pvd_name + ": times increase")
    if first_time_zero:
        check(times[0] == 0., pvd_name + ": the first snapshot is at t = 0")
    else:
        # no grid state exists before the first step
        check(times[0] > 0., pvd_name + ": the first snapshot is after t = 0")
    n_good = 0
    last = None
    for index, (time, name) in enumerate(series):
        path = os.path.join(folder, name)
        if not os.path.isfile(path):
            check(False, name + " exists")
            continue
        grid = read_vtu(path)
        good, arrays = point_arrays(grid, expected_arrays, name)
        t = time_field(grid)
        if t is None or abs(t - time) > 1e-6 * max(1., abs(time)):
            check(False, "%s: TIME field %s equals the PVD time %g" %
                  (name, t, time))
            good = False
        good = check_vtu(index, name, grid, arrays) and good
        n_good += good
        last = (grid, arrays)
    check(n_good == len(series),
          "%s: %d of %d VTU files read with all arrays finite" %
          (pvd_name, n_good, len(series)))
    return last


def main():
    folder = sys.argv[1]
    n_particles = int(sys.argv[2])
    total_mass = float(sys.argv[3])
    momentum = [float(sys.argv[4]), float(sys.argv[5])]

    def particle_checks(index, name, grid, arrays):
        good = True
        if grid.GetNumberOfPoints() != n_particles or \
           grid.GetNumberOfCells() != n_particles:
            check(False, "%s: %d points and %d cells, expected %d" %
                  (name, grid.GetNumberOfPoints(), grid.GetNumberOfCells(),
                   n_particles))
            good = False
        if len(arrays) == len(PARTICLE_ARRAYS):
            # a 2D run: no out-of-plane components, no z coordinate
            stress = arrays["cauchy_stress"]
            planar = (numpy.all(arrays["velocity"][:, 2] == 0.) and
                      numpy.all(stress[:, [2, 5, 6, 7, 8]] == 0.) and
                      numpy.all(numpy_support.vtk_to_numpy(
                          grid.GetPoints().GetData())[:, 2] == 0.))
            if not planar:
                check(False, name + ": 2D data have no z components")
                good = False
            mass = float(numpy.sum(arrays["mass"], dtype=numpy.float64))
            if abs(mass - total_mass) > 1e-6 * total_mass:
                check(False, "%s: total mass %.9g, expected %.9g" %
                      (name, mass, total_mass))
                good = False
            if not (numpy.all(arrays["J"] > 0.) and
                    numpy.all(arrays["von_mises"] >= 0.) and
                    set(numpy.unique(arrays["body_id"])) == {0., 1.}):
                check(False, name + ": J > 0, von Mises >= 0, bodies 0, 1")
                good = False
            if index == 0 and not (numpy.all(arrays["displacement"] == 0.) and
                                   numpy.all(arrays["J"] == 1.)):
                check(False, name + ": no displacement, J = 1 at t = 0")
                good = False
        return good

    grid, arrays = check_series(folder, "particles.pvd", PARTICLE_ARRAYS,
                                particle_checks)
    print("particles per snapshot: %d" % grid.GetNumberOfPoints())
    # The last snapshot against the simulation's own final state.
    mass = arrays["mass"][:, 0].astype(numpy.float64)
    velocity = arrays["velocity"].astype(numpy.float64)
    p = [float(numpy.sum(mass * velocity[:, c])) for c in range(2)]
    scale = float(numpy.sum(mass * numpy.linalg.norm(velocity, axis=1)))
    check(all(abs(p[c] - momentum[c]) <= 1e-5 * scale for c in range(2)),
          "last snapshot: momentum (%.3f, %.3f) is the simulation's "
          "(%.3f, %.3f)" % (p[0] + 0., p[1] + 0., momentum[0] + 0.,
                            momentum[1] + 0.))

    if os.path.isfile(os.path.join(folder, "grid.pvd")):
        def grid_checks(index, name, grid, arrays):
            good = grid.GetNumberOfPoints() > 0 and grid.GetNumberOfCells() > 0
            if good and len(arrays) == len(GRID_ARRAYS):
                good = (numpy.all(arrays["mass"] >= 0.) and
                        numpy.any(arrays["mass"] > 0.))
            if not good:
                check(False, name + ": cells, nodal mass >= 0 and not all 0")
            return good
        grid, _ = check_series(folder, "grid.pvd", GRID_ARRAYS, grid_checks,
                               first_time_zero=False)
        check(grid.GetNumberOfCells() > 0,
              "grid: the last snapshot has active cells")

    print("checks failed: %d" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
