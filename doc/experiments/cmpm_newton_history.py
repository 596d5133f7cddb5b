#!/usr/bin/python3
"""Seed 002 Fig. 26(a, b): the strain energy over the Newton iterations of
the heterogeneous cube's global coarse solve (Section 8.1.4) at t = 0.01 s
and t = 0.05 s, with the first Newton step and with full Newton in the
local problem, and the same of BSMPM-fine, the benchmark.

    /usr/bin/python3 doc/experiments/cmpm_newton_history.py [options]

options:
  --bfemp PATH   the bfemp executable (default: build/bfemp)
  --dim 2|3      the cube (default 2: prm/cmpm/heterogeneous_cube_2d*.prm,
                 seconds; 3: the seed's size, about 4 min)
  --out DIR      work folder (default: output/cmpm_newton_history); the
                 table goes to DIR/newton_history.csv
  --plot PNG     also draw the figure (matplotlib)
  --quiet        no progress lines

Each run is prm/cmpm/heterogeneous_cube_<dim>d{,_full_newton,_fine}.prm
with 'solver/log iterations = true', which prints one line per Newton
iteration with the energy of every term of the incremental potential; the
'MPM elasticity' term is the strain energy sum_p V_p^0 Psi(F_p) that the
seed draws. One row per iteration: run, step, time, pass ('first' for the
solve with the first-Newton-step maps, 'full' for the second solve of
'local solve = full Newton' with the maps of the converged local problems,
doc/cmpm.md "Full Newton"), iteration, the increment ||p||/dt, E and the
strain energy. The CSV is written complete or not at all; a run whose log
is complete is not run again. doc/cmpm.md ("Heterogeneous cube") discusses
the result; doc/experiments/data/cmpm_heterogeneous_cube_3d_newton_history.csv
and doc/images/cmpm_newton_history_3d.png are one run of
    cmpm_newton_history.py --dim 3 --plot doc/images/cmpm_newton_history_3d.png
(2026-12-07, 9 min on the 2-core machine next to other runs)."""

import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
from cmpm_beam_layouts import run_bfemp  # noqa: E402
import particle_error  # noqa: E402
from run_data import write_atomically, write_table  # noqa: E402

RUNS = (("first", ""), ("full", "_full_newton"), ("fine", "_fine"))
LABELS = {"first": "cMPM, first Newton step",
          "full": "cMPM, full Newton",
          "fine": "BSMPM-fine (benchmark)"}
TIMES = (0.01, 0.05)  # the seed's Fig. 26(a) and (b)
COLUMNS = ["run", "step", "time", "pass", "iteration", "increment",
           "energy", "strain_energy"]
STRAIN_TERM = "MPM elasticity"
LINE = re.compile(
    r"^\s+step (?P<step>\d+), t = (?P<time>[\d.e+-]+)"
    r"(?P<full>, full-Newton pass)?: iteration (?P<iteration>\d+), "
    r"\|\|p\|\|/dt (?P<increment>\S+) m/s .*?, E (?P<energy>\S+) J, "
    r".*, terms: (?P<terms>.*)$")


ToolError = particle_error.ToolError


def terms_of(text):
    """{name: value} of a log line's "name value J; ..." list."""
    values = {}
    for entry in text.split("; "):
        name, value, unit = entry.rsplit(" ", 2)
        if unit != "J":
            raise ToolError(f"unexpected term entry '{entry}'")
        values[name] = value
    return values


def parse_log(path, run):
    """The rows of one run's iteration log."""
    rows = []
    with open(path) as log:
        for line in log:
            match = LINE.match(line)
            if not match:
                continue
            terms = terms_of(match["terms"])
            if STRAIN_TERM not in terms:
                raise ToolError(f"{path}: no '{STRAIN_TERM}' term in "
                                f"'{line.strip()}'")
            rows.append({"run": run, "step": match["step"],
                         "time": match["time"],
                         "pass": "full" if match["full"] else "first",
                         "iteration": match["iteration"],
                         "increment": match["increment"],
                         "energy": match["energy"],
                         "strain_energy": terms[STRAIN_TERM]})
    if not rows:
        raise ToolError(f"{path}: no iteration lines (was 'solver/log "
                        "iterations' set?)")
    return rows


def run(bfemp, folder, dim, run_name, suffix, quiet):
    """Runs one variant (unless its log is complete) and returns its rows."""
    wrapper = os.path.join(folder, f"{run_name}.prm")
    log = wrapper + ".log"  # where run_bfemp() writes it
    done = log + ".done"
    if not os.path.exists(done):
        prm = os.path.join(ROOT, "prm", "cmpm",
                           f"heterogeneous_cube_{dim}d{suffix}.prm")
        write_atomically(wrapper, f"""include {prm}
subsection run
  set quiet = true
end
subsection solver
  set log iterations = true
end
subsection output
  set directory       = {os.path.join(folder, "output")}
  set write particles = false
end
""")
        if not quiet:
            print(f"cmpm_newton_history.py: running {LABELS[run_name]} "
                  f"({dim}D)", flush=True)
        run_bfemp(bfemp, folder, wrapper)
        write_atomically(done, "")
    return parse_log(log, run_name)


def converged(rows, run_name, time):
    """The strain energy at the last iteration of @p run_name's step at
    @p time (its last pass)."""
    at = [r for r in rows if r["run"] == run_name
          and abs(float(r["time"]) - time) < 1e-9]
    if not at:
        raise ToolError(f"{run_name}: no step at t = {time}")
    return float(at[-1]["strain_energy"])


def plot(rows, target, dim):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(2, 2, figsize=(10, 6.4))
    styles = {"first": ("o-", "black"), "full": ("s--", "tab:blue"),
              "fine": ("^:", "tab:red")}
    for column, time in enumerate(TIMES):
        top, bottom = axes[0][column], axes[1][column]
        for run_name, _ in RUNS:
            at = [r for r in rows if r["run"] == run_name
                  and abs(float(r["time"]) - time) < 1e-9]
            # iterations counted over the passes of the step
            k = list(range(1, len(at) + 1))
            strain = [float(r["strain_energy"]) for r in at]
            style, colour = styles[run_name]
            top.plot(k, strain, style, color=colour, markersize=4,
                     label=LABELS[run_name])
            # each pass against its own converged value
            passes = [r["pass"] for r in at]
            for which in ("first", "full"):
                idx = [i for i, p in enumerate(passes) if p == which]
                if len(idx) < 2:
                    continue
                last = strain[idx[-1]]
                bottom.semilogy([k[i] for i in idx[:-1]],
                                [max(abs(strain[i] - last) / abs(last), 1e-16)
                                 for i in idx[:-1]], style, color=colour,
                                markersize=4,
                                label=LABELS[run_name] if which == "first"
                                else None)
            if "full" in passes:
                for axis in (top, bottom):
                    axis.axvline(passes.index("full") + 0.5, color=colour,
                                 linewidth=0.6, alpha=0.5)
        top.set_title(f"t = {time:g} s", fontsize=10)
        top.set_ylabel("strain energy [J]")
        bottom.set_xlabel("Newton iteration of the step")
        bottom.set_ylabel("|strain energy - pass's last| / |last|")
        for axis in (top, bottom):
            axis.grid(alpha=0.3)
            axis.legend(fontsize=7)
            axis.xaxis.get_major_locator().set_params(integer=True)
    figure.suptitle(f"Heterogeneous cube ({dim}D), seed 002 Fig. 26(a, b): "
                    "strain energy over the global Newton iterations\n(thin "
                    "blue line: full Newton's second solve, with the maps of "
                    "the converged local problems)",
                    fontsize=10)
    figure.tight_layout()
    figure.savefig(target, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bfemp", default=os.path.join(ROOT, "build", "bfemp"))
    parser.add_argument("--dim", type=int, default=2)
    parser.add_argument("--out", default=os.path.join("output",
                                                      "cmpm_newton_history"))
    parser.add_argument("--plot")
    parser.add_argument("--quiet", action="store_true")
    args = parser.parse_args()
    if args.dim not in (2, 3):
        sys.exit(f"cmpm_newton_history.py: --dim {args.dim}: must be 2 or 3")
    if not os.access(args.bfemp, os.X_OK):
        sys.exit(f"cmpm_newton_history.py: --bfemp {args.bfemp}: no such "
                 "executable (build bfemp first: ./setup.sh build)")
    os.makedirs(args.out, exist_ok=True)
    try:
        rows = []
        for run_name, suffix in RUNS:
            rows += run(args.bfemp, os.path.abspath(args.out), args.dim,
                        run_name, suffix, args.quiet)
        write_table(os.path.join(args.out, "newton_history.csv"), COLUMNS,
                    rows)
        if not args.quiet:
            for time in TIMES:
                print(f"t = {time:g} s: converged strain energy " + ", ".join(
                    f"{LABELS[r]} {converged(rows, r, time):.6g} J"
                    for r, _ in RUNS))
        if args.plot:
            plot(rows, args.plot, args.dim)
    except (ToolError, OSError) as error:
        sys.exit(f"cmpm_newton_history.py: {error}")


if __name__ == "__main__":
    main()
