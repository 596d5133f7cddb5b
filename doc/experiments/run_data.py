"""Readers of bfemp run folders shared by the experiment plot scripts:
diagnostics.csv / bodies.csv as a numpy record array, the (time, file) list
of a PVD series, and one VTU file as VTK's unstructured grid or as its
points, cells and von Mises stress; and the entries of a run's input.prm.
Also the writer the scripts share for their tables (complete or absent).
Needs numpy and the vtk Python module (Debian: python3-numpy,
python3-vtk9)."""
import os
import tempfile
import time
import xml.etree.ElementTree as ET


def write_atomically(path, text):
    """Writes @p text to a temporary file in @p path's folder and renames it
    into place, so that @p path is either complete or untouched."""
    folder = os.path.dirname(os.path.abspath(path))
    handle, temporary = tempfile.mkstemp(dir=folder, suffix=".part")
    with os.fdopen(handle, "w") as out:
        out.write(text)
    os.chmod(temporary, 0o644)
    os.replace(temporary, path)


def write_table(path, columns, rows):
    """The rows (dicts keyed by @p columns) as a CSV file, complete or
    absent."""
    write_atomically(path, ",".join(columns) + "\n" + "".join(
        ",".join(row[c] for c in columns) + "\n" for row in rows))


def run_units(units, run_unit, describe, quiet):
    """The rows run_unit(u) of a study's units, in order, with one progress
    line per unit (describe(u, row), its number and an estimate of the time
    left) unless @p quiet."""
    rows, start = [], time.time()
    for i, unit in enumerate(units):
        rows.append(run_unit(unit))
        if not quiet:
            left = (time.time() - start) / (i + 1) * (len(units) - i - 1)
            print(f"{describe(unit, rows[-1])} ({i + 1}/{len(units)}); "
                  f"about {left:.0f} s left", flush=True)
    return rows


def csv(path):
    """A bfemp CSV file as a numpy record array (columns by header name)."""
    import numpy as np

    return np.genfromtxt(path, delimiter=",", names=True)


def read_grid(path):
    """The vtkUnstructuredGrid of a VTU file."""
    import vtk

    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def pvd(path):
    """(time, file) pairs of a .pvd series."""
    root = ET.parse(path).getroot()
    folder = os.path.dirname(path)
    return [(float(e.get("timestep")), os.path.join(folder, e.get("file")))
            for e in root.iter("DataSet")]


def read_vtu(path):
    """points (x, y), cell connectivity and the point and cell von Mises
    arrays (None where the file has none) of a 2D VTU file."""
    from vtk.util.numpy_support import vtk_to_numpy

    grid = read_grid(path)
    points = vtk_to_numpy(grid.GetPoints().GetData())[:, :2]
    cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray()) if hasattr(
        grid.GetCells(), "GetConnectivityArray") else None
    point_vm = grid.GetPointData().GetArray("von_mises")
    cell_vm = grid.GetCellData().GetArray("von_mises")
    return dict(points=points, cells=cells,
                point_vm=None if point_vm is None else vtk_to_numpy(point_vm),
                cell_vm=None if cell_vm is None else vtk_to_numpy(cell_vm))


def prm_entries(path):
    """{'subsection/.../entry': value} of a prm file with its includes
    followed (a relative include path is tried next to the including file,
    then as written), later 'set' lines winning as in deal.II."""
    entries, sections = {}, []

    def scan(name):
        for line in open(name):
            line = line.split("#")[0].strip()
            words = line.split(None, 1)
            if not words:
                continue
            key = words[0].lower()
            if key == "subsection":
                sections.append(words[1].strip())
            elif key == "end" and sections:
                sections.pop()
            elif key == "set" and "=" in line:
                entry, value = words[1].split("=", 1)
                entries["/".join(sections + [entry.strip()])] = value.strip()
            elif key == "include":
                target = words[1].strip()
                beside = os.path.join(os.path.dirname(name), target)
                scan(beside if os.path.exists(beside) else target)

    scan(path)
    return entries


def prm_entry(entries, name):
    """The value of the entry whose path ends in @p name (e.g.
    'body 0/particles per cell'); the first such path in file order if
    several do."""
    for path, value in entries.items():
        if path == name or path.endswith("/" + name):
            return value
    raise KeyError(name)
