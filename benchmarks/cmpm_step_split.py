#!/usr/bin/python3
"""The time of a step of cMPM against quadratic B-spline MPM on the fine mesh
(BSMPM-fine), split as seed 002's Table 3: the unknowns, the time outside the
Newton solve (cMPM: the shape functions of the step, P2G, G2P; BSMPM: P2G,
G2P), the assembly of the Newton systems (the integrals over the particles),
the factorization and solve (CHOLMOD), and the line search.

Two heterogeneous scenes, each run three ways on the same particles (cMPM
with the first-Newton-step local solve, cMPM with the full-Newton local solve
of seed 002 Section 8.1.4, BSMPM-fine):
  2D  prm/cmpm/beam_2d.prm (a beam with two rows of soft inclusions),
      cMPM H = 0.1, n = 7 (knot span s = 0.02), against BSMPM-fine with cell
      0.02 shifted by s/2 (as tests/cmpm/beam_consistency);
  3D  a beam 1.2 x 0.2 x 0.2 m clamped at both ends with soft ball material
      regions (E 1e3 in E 1e5), cMPM H = 0.1, n = 7, against BSMPM-fine with
      cell 0.02.
Each run takes a few steps of the scene on one thread; the figures are means
over the steps after the first.

With --h3-modes it also runs the seed-size beam with bfemp's richer coarse
space (prm/cmpm/bending_beam_3d_h3_modes.prm: L = H/3, interior modes),
three steps each on all threads (--h3-steps N: N steps): with Newton and
factorization reuse, with modified Newton (the prm's 'solver/modified Newton
contraction = 0.5') and BSMPM-fine with CG + ML AMG. About 15 minutes for three
steps; the fine run's step grows as the beam bends, so a longer window (N = 8,
about 45 minutes) weighs that in.

With --trade it also runs the seed-size beam over --h3-steps N steps in
three coarse spaces, each with the two levers of the H/3 file (factorization
reuse and modified Newton): the seed's (L = H/2), L = H/2 with interior modes
and L = H/3 with interior modes; the seed's space also with the paper's
Newton (the prm as it is); BSMPM-coarse and BSMPM-fine with CG + ML AMG. The
speed-ups of the points of the beam's speed-accuracy trade then come from one
invocation (their max r_u: doc/cmpm.md "Bending beam"; the plot:
doc/experiments/plot_cmpm_beam_trade.py). About 50 minutes for N = 8.

With --seed-size it also runs the seed's own size, the 3D bending beam of
seed 002 Section 8.1.2 (prm/cmpm/bending_beam_3d{,_fine}.prm: 640,000
particles, cMPM 40 x 4 x 4 coarse elements against BSMPM-fine with 293K
unknowns), two steps each on all threads: cMPM, BSMPM-fine with CG + ML
AMG (the prm's solver) and BSMPM-fine with CHOLMOD (12.4 GB). The speed-up
of cMPM at two sizes then comes from one invocation. About 25 minutes; on a
machine with less than 16 GB the CHOLMOD run is left out.

With --lattice it also runs the seed-size 3D lattice bar of seed 002
Section 8.1.3 (prm/cmpm/lattice_bar_3d{,_bspline}.prm: 32 x 8 x 8 coarse
elements, about a million particles), three steps each on all threads, on
boundary B-spline and on B-spline coarse elements: the ratio of their
integrals (assembly) is the seed's Table 3 comparison (3.2x).

  /usr/bin/python3 benchmarks/cmpm_step_split.py [--build build] [--quick]
                                                 [--seed-size] [--h3-modes]
                                                 [--h3-steps N] [--trade]
                                                 [--lattice]
                                                 [--output FILE]

writes benchmarks/results/cmpm_step_split.json (see doc/performance.md).
"""

import argparse
import csv
import json
import os
import platform
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BEAM_2D = os.path.join(ROOT, "prm", "cmpm", "beam_2d.prm")

FINE_2D = """subsection cmpm
  set enabled = false
end
subsection grid
  set lower corner = -0.11, -0.01
  set upper corner = 2.51, 0.81
  set cell size    = 0.02
  set kernel       = quadratic
end
subsection boundaries
  set wall layers = 10
end
subsection body 0
  set particles per cell = 2
end
subsection body 1
  set particles per cell = 2
end
"""

BEAM_3D = """set dimension        = 3
set number of bodies = 1
subsection run
  set name     = cmpm_beam_3d
  set end time = {end_time}
end
subsection grid
  set lower corner = -0.1, 0, 0
  set upper corner = 1.3, 0.4, 0.4
  set cell size    = 0.1
end
subsection cmpm
  set enabled                  = true
  set coarse element type      = boundary B-spline
  set coarse node span         = H/2
  set fine nodes per direction = 7
end
subsection time
  set integrator     = implicit backward Euler
  set time step mode = fixed
  set time step      = 0.025
end
subsection transfer
  set scheme = PIC
end
subsection gravity
  set acceleration = 0, -25, 0
end
subsection boundaries
  set walls          = x-, x+
  set wall condition = sticky
  set wall layers    = 2
end
subsection body 0
  set particles per cell         = 10
  set number of material regions = 4
  subsection primitive 0
    set type         = box
    set lower corner = 0, 0.1, 0.1
    set upper corner = 1.2, 0.3, 0.3
  end
  subsection material
    set model           = neo-Hookean
    set Young's modulus = 1e5
    set Poisson's ratio = 0.3
    set density         = 10
  end
{regions}end
"""

REGION_3D = """  subsection material region {k}
    set type         = ball
    set center       = {x}, 0.2, 0.2
    set outer radius = 0.06
    subsection material
      set model           = neo-Hookean
      set Young's modulus = 1e3
      set Poisson's ratio = 0.3
      set density         = 10
    end
  end
"""

FINE_3D = """subsection cmpm
  set enabled = false
end
subsection grid
  set lower corner = -0.11, -0.01, -0.01
  set upper corner = 1.31, 0.41, 0.41
  set cell size    = 0.02
  set kernel       = quadratic
end
subsection boundaries
  set wall layers = 10
end
subsection body 0
  set particles per cell = 2
end
"""


FULL_NEWTON = """subsection cmpm
  set local solve = full Newton
end
"""


def run(build, folder, name, text, threads=1):
    """Runs one scene (text) as results/<name> in folder on @p threads
    threads (0: all) and returns its diagnostics rows and peak memory."""
    prm = os.path.join(folder, name + ".prm")
    with open(prm, "w") as f:
        f.write(text)
        f.write(f"subsection run\n  set name = {name}\n  set quiet = true\n"
                f"  set threads = {threads}\nend\n"
                "subsection output\n  set directory = results\n"
                "  set interval = 100\n  set write particles = false\n"
                "  set write grid = false\n  set diagnostics interval = 1\nend\n")
    start = time.time()
    process = subprocess.Popen([os.path.join(build, "bfemp"), prm], cwd=folder,
                               stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(process.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"cmpm_step_split: {name} failed")
    elapsed = time.time() - start
    with open(os.path.join(folder, "results", name, "diagnostics.csv")) as f:
        rows = [r for r in csv.DictReader(f)]
    # row 0 is t = 0
    return rows[1:], elapsed, usage.ru_maxrss / 1024.0 / 1024.0


def split(rows):
    """Means per step over the steps after the first, and the first step."""
    steps = rows[1:]
    wall = [float(b["wall_time"]) - float(a["wall_time"])
            for a, b in zip(rows[:-1], rows[1:])]
    first_step = float(rows[0]["wall_time"])
    mean = lambda values: sum(values) / len(values)
    assembly = mean([float(r["assembly_time"]) for r in steps])
    factorization = mean([float(r["factorization_time"]) for r in steps])
    solve = mean([float(r["solve_time"]) for r in steps])
    line_search = mean([float(r["line_search_time"]) for r in steps])
    step = mean(wall)
    counts = lambda column: mean([float(r.get(column, 0)) for r in steps])
    return {
        "unknowns": int(mean([float(r["dofs"]) for r in steps])),
        "newton_iterations": counts("newton_iterations"),
        "modified_newton_iterations": counts("modified_newton_iterations"),
        "factorizations": counts("factorizations"),
        "step_s": step,
        "outside_newton_s": step - assembly - factorization - solve - line_search,
        "assembly_s": assembly,
        "factorization_and_solve_s": factorization + solve,
        "line_search_s": line_search,
        "first_step_s": first_step,
        "step_times_s": [first_step] + wall,
    }


def seed_size_runs():
    """The seed's 3D bending beam, two steps: cMPM, BSMPM-fine with the
    prm's CG + ML AMG and, with enough memory, with CHOLMOD."""
    two_steps = "subsection run\n  set end time = 0.05\nend\n"
    prefix = os.path.join(ROOT, "prm", "cmpm", "bending_beam_3d")
    runs = [("cMPM", f"include {prefix}.prm\n{two_steps}"),
            ("BSMPM-fine CG + ML AMG",
             f"include {prefix}_fine.prm\n{two_steps}")]
    memory = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    if memory > 16e9:
        runs.append(("BSMPM-fine CHOLMOD",
                     f"include {prefix}_fine.prm\n{two_steps}"
                     "subsection solver\n  set linear solver = CHOLMOD\nend\n"))
    return runs


def h3_modes_runs(steps):
    """The seed-size 3D beam with L = H/3 and interior modes, @p steps steps:
    Newton with factorization reuse, modified Newton, BSMPM-fine."""
    window = f"subsection run\n  set end time = {0.025 * steps:g}\nend\n"
    prefix = os.path.join(ROOT, "prm", "cmpm", "bending_beam_3d")
    newton = "subsection solver\n  set modified Newton contraction = 0\nend\n"
    return [("cMPM H/3 modes Newton",
             f"include {prefix}_h3_modes.prm\n{window}{newton}"),
            ("cMPM H/3 modes modified Newton",
             f"include {prefix}_h3_modes.prm\n{window}"),
            ("BSMPM-fine CG + ML AMG",
             f"include {prefix}_fine.prm\n{window}")]


def trade_runs(steps):
    """The seed-size 3D beam in three coarse spaces, each with factorization
    reuse and modified Newton, and BSMPM-fine, @p steps steps."""
    window = f"subsection run\n  set end time = {0.025 * steps:g}\nend\n"
    prefix = os.path.join(ROOT, "prm", "cmpm", "bending_beam_3d")
    levers = ("subsection solver\n  set factorization reuse = 20\n"
              "  set modified Newton contraction = 0.5\nend\n")
    modes = "subsection cmpm\n  set interior modes = body load\nend\n"
    return [("cMPM seed's space Newton", f"include {prefix}.prm\n{window}"),
            ("cMPM seed's space levers",
             f"include {prefix}.prm\n{window}{levers}"),
            ("cMPM H/2 modes levers",
             f"include {prefix}.prm\n{window}{levers}{modes}"),
            ("cMPM H/3 modes levers",
             f"include {prefix}_h3_modes.prm\n{window}"),
            ("BSMPM-coarse", f"include {prefix}_coarse.prm\n{window}"),
            ("BSMPM-fine CG + ML AMG",
             f"include {prefix}_fine.prm\n{window}")]


def lattice_runs():
    """The seed-size 3D lattice bar, three steps, on boundary B-spline and on
    B-spline coarse elements."""
    window = "subsection run\n  set end time = 0.075\nend\n"
    prefix = os.path.join(ROOT, "prm", "cmpm", "lattice_bar_3d")
    return [("cMPM boundary B-spline", f"include {prefix}.prm\n{window}"),
            ("cMPM B-spline", f"include {prefix}_bspline.prm\n{window}")]


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--quick", action="store_true",
                        help="2D only, 3 steps (a smoke run)")
    parser.add_argument("--seed-size", action="store_true",
                        help="also the seed's 3D bending beam (640,000 "
                        "particles, about 25 minutes)")
    parser.add_argument("--h3-modes", action="store_true",
                        help="also the seed-size 3D beam with L = H/3 and "
                        "interior modes, Newton and modified Newton against "
                        "BSMPM-fine (about 15 minutes)")
    parser.add_argument("--h3-steps", type=int, default=3,
                        help="time steps of the --h3-modes and --trade runs (at least 2: "
                        "the means are over the steps after the first)")
    parser.add_argument("--trade", action="store_true",
                        help="the seed-size 3D beam in the seed's space, at "
                        "L = H/2 with interior modes and at L = H/3 with "
                        "interior modes, all with factorization reuse and "
                        "modified Newton, against BSMPM-fine, --h3-steps "
                        "steps each (about 50 minutes for 8 steps)")
    parser.add_argument("--lattice", action="store_true",
                        help="also the seed-size 3D lattice bar on boundary "
                        "B-spline and on B-spline coarse elements")
    parser.add_argument("--output",
                        default=os.path.join(ROOT, "benchmarks", "results",
                                             "cmpm_step_split.json"))
    arguments = parser.parse_args()
    if arguments.h3_steps < 2:
        parser.error("--h3-steps: at least 2 (the means are over the steps "
                     "after the first)")

    steps = 3 if arguments.quick else 6
    end_time = 0.025 * steps
    with open(BEAM_2D) as f:
        beam_2d = f.read() + f"subsection run\n  set end time = {end_time}\nend\n"
    regions = "".join(REGION_3D.format(k=k, x=0.3 + 0.2 * k) for k in range(4))
    beam_3d = BEAM_3D.format(end_time=end_time, regions=regions)
    methods = (("cMPM", ""), ("cMPM full Newton", FULL_NEWTON))
    scenes = [("2d", 1, [(m, beam_2d + e) for m, e in methods] +
               [("BSMPM-fine", beam_2d + FINE_2D)])]
    if not arguments.quick:
        scenes.append(("3d", 1, [(m, beam_3d + e) for m, e in methods] +
                       [("BSMPM-fine", beam_3d + FINE_3D)]))
    if arguments.seed_size:
        scenes.append(("3d seed size", 0, seed_size_runs()))
    if arguments.h3_modes:
        # all cores, named: 'run/threads' > 1 also lets CHOLMOD's large
        # factorizations use them (doc/performance.md "BLAS threads")
        scenes.append(("3d seed size H/3 modes", os.cpu_count(),
                       h3_modes_runs(arguments.h3_steps)))
    if arguments.trade:
        scenes.append(("3d seed size trade", os.cpu_count(),
                       trade_runs(arguments.h3_steps)))

    if arguments.lattice:
        scenes.append(("3d lattice bar", os.cpu_count(), lattice_runs()))

    results = []
    with tempfile.TemporaryDirectory() as folder:
        for label, threads, runs in scenes:
            for method, text in runs:
                name = f"{label}_{method}".replace(" ", "_").replace(
                    "+", "").replace("/", "")
                rows, elapsed, memory = run(arguments.build, folder, name,
                                            text, threads)
                entry = {"scene": label, "method": method, "steps": len(rows),
                         "threads": threads or os.cpu_count(),
                         "run_s": elapsed, "peak_memory_gb": memory}
                entry.update(split(rows))
                results.append(entry)
                print(json.dumps(entry), flush=True)

    commit = subprocess.run(["git", "-C", ROOT, "describe", "--always", "--dirty"],
                            capture_output=True, text=True).stdout.strip()
    with open("/proc/cpuinfo") as f:
        cpu = next((line.split(":", 1)[1].strip() for line in f
                    if line.startswith("model name")), platform.processor())
    os.makedirs(os.path.dirname(arguments.output), exist_ok=True)
    with open(arguments.output + ".tmp", "w") as f:
        json.dump({"benchmark": "cmpm_step_split",
                   "date": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
                   "commit": commit, "cpu": cpu,
                   "quick": arguments.quick, "results": results}, f, indent=1)
    os.replace(arguments.output + ".tmp", arguments.output)


if __name__ == "__main__":
    sys.exit(main())
