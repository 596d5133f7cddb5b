#!/usr/bin/python3
"""The extremes suite (issue 23): small scenes at extreme parameters, one
entry changed at a time, each run classified by how it ends.

    extremes.py BFEMP [--subset ci|all] [--dim 2|3|both] [--jobs N]
                [--folder DIR] [--timeout S]

Every case is a base scene of this folder (drop_<dim>d.prm: an MPM block
dropped onto a fixed FEM slab with barrier contact and friction, implicit;
free_<dim>d.prm: a spinning block in zero gravity, explicit) with one or a
few entries changed. A run ends in one of three accepted ways:

  ran       exit 0, and every invariant held: no NaN or inf in
            diagnostics.csv (min_distance is inf while there is no contact)
            or in the last particle VTU, min J > 0 at every step, every
            contact distance > 0, the total energy (kinetic + elastic +
            gravitational) never above its initial value (by 1e-3 of it),
            and, in the free scene, the momentum kept (to 1e-8 of the mass
            times the largest initial speed);
  refused   exit 1 with bfemp's "input error" message and no output;
  stopped   exit 3 with bfemp's "simulation stopped" message, and every
            file written complete (each VTU opens, each CSV row is whole).

Anything else fails the suite: a crash (a signal), a hang past --timeout,
another exit status, a NaN, an inverted particle, a penetration, energy
from nowhere. The outcome of each case is printed, one line per case, and
written to <folder>/extremes.csv; the exit status is the number of failed
cases (capped at 100).

The ci subset (tests/extremes/CMakeLists.txt, a few seconds per case) runs
in CI; `--subset all` is the full matrix of doc/stability.md.
"""
import argparse
import concurrent.futures
import csv
import math
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def load_study_tool():
    """tools/bfemp-study, for its prm writer (a variant: the base included,
    the entries set in their subsections)."""
    import importlib.machinery
    import importlib.util
    path = os.path.join(HERE, "..", "..", "tools", "bfemp-study")
    loader = importlib.machinery.SourceFileLoader("bfemp_study", path)
    module = importlib.util.module_from_spec(
        importlib.util.spec_from_loader("bfemp_study", loader))
    loader.exec_module(module)
    return module


prm_text = load_study_tool().prm_text


# The matrix: (name, scene, {entry: value}, in the ci subset). Scales of the
# base scenes: body 0.2 m, dx 0.05 m, explicit CFL step of the block about
# 1.4e-3 s (c_p = 37 m/s), implicit step 2e-3 s.
def cases(dim):
    zero = ", ".join(["0"] * dim)
    down = lambda speed: ", ".join(["0", f"-{speed}"] + ["0"] * (dim - 2))
    c = []
    add = lambda name, scene, entries, ci=False: c.append(
        (f"{scene}_{dim}d/{name}", f"{scene}_{dim}d.prm", entries, ci))
    add("base", "drop", {}, True)
    add("base", "free", {}, True)
    for E in (1e3, 1e9, 1e12):
        add(f"E {E:g}", "drop", {"body 0/material/Young's modulus": E},
            E in (1e3, 1e12))
    for nu in (0.0, 0.45, 0.49, 0.499):
        add(f"nu {nu:g}", "drop", {"body 0/material/Poisson's ratio": nu},
            nu == 0.499)
        add(f"nu {nu:g}", "free", {"body 0/material/Poisson's ratio": nu},
            nu == 0.499)
    for rho in (1.0, 2e4):
        add(f"rho {rho:g}", "drop", {"body 0/material/density": rho}, True)
    for factor in (1, 10, 100, 1000):
        dt = 1.4e-3 * factor
        add(f"dt {factor}x CFL", "drop",
            {"time/time step": dt, "run/end time": max(0.05, 3 * dt),
             "output/interval": max(0.05, 3 * dt)}, factor == 1000)
    for relative in (1e-6, 1e-4, 1e-2, 1e-1):
        add(f"dhat {relative:g} L", "drop",
            {"contact/activation distance": 0.2 * relative},
            relative in (1e-6, 1e-1))
    for kappa in (1e3, 1e4, 1e5, 1e7, 1e8, 1e9):
        add(f"kappa {kappa:g}", "drop", {"contact/barrier stiffness": kappa},
            kappa in (1e3, 1e9))
    for speed in (10, 100, 500):
        add(f"speed {speed}", "drop", {"body 0/initial velocity": down(speed)},
            speed == 500)
    for ppc in (1, 3, 4):
        add(f"ppc {ppc}", "drop", {"body 0/particles per cell": ppc},
            ppc == 4)
        add(f"ppc {ppc}", "free", {"body 0/particles per cell": ppc})
    for mu in (0.0, 1.0, 10.0):
        add(f"mu {mu:g}", "drop", {"contact/friction coefficient": mu},
            mu == 10.0)
    for eps in (1e-8, 1e-3, 1e-1):
        add(f"eps_v {eps:g}", "drop",
            {"contact/static friction velocity": eps}, eps == 1e-8)
    add("contrast 1e8", "drop",
        {"body 0/material/Young's modulus": 1e3,
         "fem body 0/material/Young's modulus": 1e11}, True)
    add("thin plate", "drop",
        {"fem body 0/mesh/lower corner": ", ".join(
            ["0.2", "0.45"] + ["0.2"] * (dim - 2)),
         "fem body 0/mesh/target edge length": 0.05}, True)
    # Newmark's contact impulse at the step's end keeps the drop's energy
    # from rising when the block leaves the slab (the trapezoidal one of
    # BFEMP eq. 21, `time/Newmark contact impulse = trapezoidal`, gains 1-2 %
    # of it in 3D: doc/stability.md).
    add("implicit Newmark", "drop", {"time/integrator": "implicit Newmark"},
        True)
    for integrator in ("explicit USF", "substepped explicit"):
        add(integrator, "free", {"time/integrator": integrator}, True)
    for scheme in ("PIC", "FLIP"):
        add(scheme, "free", {"transfer/scheme": scheme}, scheme == "FLIP")
    for kernel in ("linear", "cubic"):
        add(f"{kernel} kernel", "free", {"grid/kernel": kernel}, True)
        add(f"{kernel} kernel", "drop", {"grid/kernel": kernel})
    add("gravity 0", "drop", {"gravity/acceleration": zero})
    return c


def read_rows(path):
    with open(path) as f:
        return list(csv.reader(f))


def finite(text):
    try:
        return math.isfinite(float(text))
    except ValueError:
        return False


def vtu_problems(folder, check_values):
    """Files that do not open (and, with check_values, the last particle
    file's non-finite values)."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    import numpy as np
    vtk.vtkObject.GlobalWarningDisplayOff()
    problems = []
    files = sorted(f for f in os.listdir(folder) if f.endswith(".vtu"))
    for name in files:
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(folder, name))
        reader.Update()
        if reader.GetErrorCode() != 0 or reader.GetOutput() is None:
            problems.append(f"{name} does not open")
    particles = [f for f in files if f.startswith("particles_")]
    if check_values and particles:
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(folder, particles[-1]))
        reader.Update()
        grid = reader.GetOutput()
        arrays = [vtk_to_numpy(grid.GetPoints().GetData())]
        data = grid.GetPointData()
        arrays += [vtk_to_numpy(data.GetArray(i))
                   for i in range(data.GetNumberOfArrays())]
        if not all(np.all(np.isfinite(a)) for a in arrays):
            problems.append(f"{particles[-1]} holds NaN or inf")
    return problems


def invariant_problems(run_folder, free):
    """What the diagnostics of a finished run violate."""
    rows = read_rows(os.path.join(run_folder, "diagnostics.csv"))
    header, data = rows[0], rows[1:]
    if not data:
        return ["diagnostics.csv has no rows"]
    column = {name: i for i, name in enumerate(header)}
    problems = []
    for row in data:
        if len(row) != len(header):
            return [f"diagnostics.csv: a row of {len(row)} fields"]
        for name, text in zip(header, row):
            if not finite(text) and not (name == "min_distance" and
                                         text.strip() == "inf"):
                problems.append(f"{name} = {text} at step {row[0]}")
                break
    if problems:
        return problems[:3]
    get = lambda name: [float(r[column[name]]) for r in data]
    if min(get("min_J")) <= 0:
        problems.append(f"min J {min(get('min_J')):.3g}")
    if "contact_pairs" in column:
        touching = [float(r[column["min_distance"]]) for r in data
                    if float(r[column["contact_pairs"]]) > 0]
        if touching and min(touching) <= 0:
            problems.append(f"contact distance {min(touching):.3g}")
    # kinetic + elastic + gravitational, plus the barrier's stored energy
    # and what friction dissipated: never above the start (nothing here
    # does work on the bodies)
    energy = get("total_energy")
    if "barrier_energy" in column:
        energy = [e + b + f for e, b, f in zip(energy, get("barrier_energy"),
                                                get("friction_dissipation"))]
    scale = max(abs(energy[0]), max(get("kinetic_energy")), 1e-300)
    if max(energy) > energy[0] + 1e-3 * scale:
        problems.append(f"energy rose to {max(energy):.6g} from "
                        f"{energy[0]:.6g}")
    if free:
        mass = get("mass")[0]
        speed = max(get("max_speed")[0], 1e-300)
        for axis in "xyz":
            name = f"momentum_{axis}"
            if name in column:
                p = get(name)
                drift = max(abs(x - p[0]) for x in p)
                if drift > 1e-8 * mass * speed:
                    problems.append(f"{name} drifts by {drift:.3g}")
    return problems


def run_case(bfemp, case, folder, timeout):
    name, scene, entries, _ = case
    safe = name.replace("/", "__").replace(" ", "_")
    prm = os.path.join(folder, safe + ".prm")
    runs = os.path.join(folder, "runs")
    with open(prm, "w") as f:
        f.write(prm_text(os.path.join(HERE, scene), entries, safe, runs))
    run_folder = os.path.join(runs, safe)
    shutil.rmtree(run_folder, ignore_errors=True)
    start = time.monotonic()
    try:
        done = subprocess.run([bfemp, prm], cwd=folder, capture_output=True,
                              text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "FAIL", f"no end after {timeout} s (a hang)", timeout
    wall = time.monotonic() - start
    status, stderr = done.returncode, done.stderr.strip()
    last = stderr.splitlines()[-1] if stderr else ""
    if status < 0:
        return "FAIL", f"killed by signal {-status}", wall
    if status == 1:
        if "input error" in stderr and not os.path.exists(run_folder):
            return "refused", last.split(": ", 3)[-1][:160], wall
        return "FAIL", f"exit 1 without a clean refusal: {last[:160]}", wall
    if status == 3:
        problems = vtu_problems(run_folder, False) if \
            os.path.isdir(run_folder) else []
        if "simulation stopped" in stderr and not problems:
            return "stopped", last.split(": ", 2)[-1][:160], wall
        return "FAIL", "stopped, but " + ("; ".join(problems) or
                                          "without a message"), wall
    if status != 0:
        return "FAIL", f"exit {status}: {last[:160]}", wall
    problems = invariant_problems(run_folder, scene.startswith("free")) + \
        vtu_problems(run_folder, True)
    if problems:
        return "FAIL", "; ".join(problems), wall
    return "ran", "every invariant held", wall


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("bfemp")
    parser.add_argument("--subset", choices=("ci", "all"), default="all")
    parser.add_argument("--dim", choices=("2", "3", "both"), default="both")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--folder", default="extremes")
    parser.add_argument("--timeout", type=float, default=300.)
    arguments = parser.parse_args()
    dims = (2, 3) if arguments.dim == "both" else (int(arguments.dim),)
    selected = [case for dim in dims for case in cases(dim)
                if arguments.subset == "all" or case[3]]
    folder = os.path.abspath(arguments.folder)
    os.makedirs(folder, exist_ok=True)
    bfemp = os.path.abspath(arguments.bfemp)
    with concurrent.futures.ThreadPoolExecutor(arguments.jobs) as pool:
        outcomes = list(pool.map(
            lambda case: run_case(bfemp, case, folder, arguments.timeout),
            selected))
    width = max(len(case[0]) for case in selected)
    lines = []
    for case, (outcome, detail, wall) in zip(selected, outcomes):
        print(f"{case[0]:<{width}}  {outcome:<8} {detail}", flush=True)
        lines.append([case[0], outcome, detail, f"{wall:.2f}"])
    with open(os.path.join(folder, "extremes.csv.part"), "w",
              newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["case", "outcome", "detail", "wall_s"])
        writer.writerows(lines)
    os.replace(os.path.join(folder, "extremes.csv.part"),
               os.path.join(folder, "extremes.csv"))
    failed = sum(1 for outcome, _, _ in outcomes if outcome == "FAIL")
    counts = {k: sum(1 for o, _, _ in outcomes if o == k)
              for k in ("ran", "refused", "stopped", "FAIL")}
    print(f"extremes: {len(selected)} cases: {counts['ran']} ran, "
          f"{counts['refused']} refused, {counts['stopped']} stopped, "
          f"{counts['FAIL']} failed")
    return min(failed, 100)


if __name__ == "__main__":
    sys.exit(main())
