#!/usr/bin/python3
"""The von Mises stress along a line of particles (seed 002 Fig. 19) and
its roughness, for one or more runs of the cube shearing scene.

usage:
  cmpm_stress_line.py RUN [RUN ...] [--times 0.01,0.15,0.21]
                      [--height 0.5] [--depth 0.5] [--csv FILE]

RUN is a run folder (holding particles.pvd). The line is the row of
particles along x whose rest position is nearest to y = --height (and, in
3D, z = --depth): the seed's "red line along the x-axis" through the cube.
For every run and time, the particles of the row are ordered by their
current x, and the roughness of their von Mises stresses s_1 ... s_m is

    R = sqrt( mean_i (s_{i+1} - 2 s_i + s_{i-1})^2 ) / mean_i |s_i|,

the RMS second difference relative to the mean stress: about 0 for a
smooth profile sampled at the particle spacing, and of order one where
the stress jumps from particle to particle (the cell-crossing noise of
linear-kernel MPM). Prints one line "RUN TIME ROUGHNESS" per pair; --csv
writes the profiles (run, time, x, von_mises) for the plot script,
complete or not at all.

Needs numpy and the vtk Python module (Debian: python3-numpy,
python3-vtk9)."""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_data  # noqa: E402

TIME_TOLERANCE = 1e-9


def profile(vtu, height, depth):
    """(x, von Mises) of the row of particles nearest the line, by x."""
    from vtk.util.numpy_support import vtk_to_numpy

    grid = run_data.read_grid(vtu)
    data = grid.GetPointData()
    x = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    u = vtk_to_numpy(data.GetArray("displacement")).astype(float)
    s = vtk_to_numpy(data.GetArray("von_mises")).astype(float)
    X = x - u
    three_d = np.ptp(X[:, 2]) > 0
    rows = [(1, height)] + ([(2, depth)] if three_d else [])
    keep = np.ones(len(X), dtype=bool)
    spacing = np.inf
    for axis, value in rows:
        levels = np.unique(np.round(X[:, axis], 6))
        nearest = levels[np.argmin(np.abs(levels - value))]
        keep &= np.abs(X[:, axis] - nearest) < 1e-6
        if len(levels) > 1:
            spacing = min(spacing, np.min(np.diff(levels)))
    order = np.argsort(x[keep, 0])
    return x[keep, 0][order], s[keep][order]


def roughness(stress):
    second = stress[2:] - 2 * stress[1:-1] + stress[:-2]
    return np.sqrt(np.mean(second**2)) / np.mean(np.abs(stress))


def snapshots(run, times):
    pvd = os.path.join(run, "particles.pvd")
    if not os.path.isfile(pvd):
        sys.exit(f"cmpm_stress_line.py: {pvd}: no such particle series")
    series = run_data.pvd(pvd)
    result = []
    for time in times:
        hits = [f for t, f in series if abs(t - time) <= TIME_TOLERANCE]
        if not hits:
            sys.exit(f"cmpm_stress_line.py: {pvd} has no snapshot at "
                     f"t = {time:g}; the output interval must hit it")
        result.append((time, hits[0]))
    return result


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--times", default="0.01,0.15,0.21")
    parser.add_argument("--height", type=float, default=0.5)
    parser.add_argument("--depth", type=float, default=0.5)
    parser.add_argument("--csv")
    arguments = parser.parse_args()
    times = [float(t) for t in arguments.times.split(",")]
    lines = []
    for run in arguments.runs:
        for time, vtu in snapshots(run, times):
            x, s = profile(vtu, arguments.height, arguments.depth)
            print(f"{os.path.basename(os.path.normpath(run))} {time:g} "
                  f"{roughness(s):.6e}")
            lines += [f"{os.path.basename(os.path.normpath(run))},{time:g},"
                      f"{xi:.9g},{si:.9g}" for xi, si in zip(x, s)]
    if arguments.csv:
        run_data.write_atomically(
            arguments.csv, "run,time,x,von_mises\n" + "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
