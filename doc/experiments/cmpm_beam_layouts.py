#!/usr/bin/python3
"""How much the bending beam's max r_u (seed 002 Section 8.1.2, eq. 38)
depends on where its 40 soft inclusions lie.

The seed gives the beam's size, its materials and "40 softer elliptical
column inclusions of varied shapes", not their places. bfemp draws them at
random, two rows of 20 (doc/experiments/make_cmpm_prms.py, layout seed 2002
in prm/cmpm/). This study draws other layouts the same way, runs cMPM,
BSMPM-fine (the reference) and BSMPM-coarse on each, and writes one row per
layout: the max r_u of cMPM and of BSMPM-coarse over the 24 steps, when
cMPM's maximum occurs, and where its error is at that time (the share of
the squared error, int |u - u_ref|^2 dV, carried by the soft inclusions and
by the particles within 3 m of the clamped ends). A row "homogeneous" is
the beam without inclusions.

    /usr/bin/python3 doc/experiments/cmpm_beam_layouts.py [options]

options:
  --bfemp PATH     the bfemp executable (default: build/bfemp)
  --dim 2|3        the beam (default 2; 3D needs hours per layout)
  --seeds LIST     layout seeds, comma separated (default 2002,1,...,11)
  --no-homogeneous leave out the beam without inclusions
  --interior-modes also run cMPM with `cmpm/interior modes = body load`
                   (bfemp's addition, doc/cmpm.md) on every layout: two
                   more columns, max_r_u_modes and time_of_max_modes
  --h3-modes       also run cMPM with L = H/3 and interior modes (the
                   _h3_modes variant of make_cmpm_prms.py): columns
                   max_r_u_h3_modes and time_of_max_h3_modes
  --out DIR        work folder (default: output/cmpm_beam_layouts_<dim>d);
                   the table goes to DIR/layouts.csv, each layout's r_u
                   at every output time to DIR/layout_<label>/series.csv
  --quiet          no progress lines

The study is resumable: a layout whose DIR/<label>/result.csv exists is not
run again (delete DIR to measure again after bfemp has changed). Every CSV
is written complete or not at all. About 25 s per layout in 2D on a 2-core
machine. doc/cmpm.md ("Bending beam") discusses the
result; doc/experiments/data/cmpm_beam_layouts_2d.csv is a copy of one run.

Needs numpy and the vtk Python module (Debian: python3-numpy,
python3-vtk9)."""

import argparse
import os
import subprocess
import sys
import time
from typing import NamedTuple

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_cmpm_prms  # noqa: E402
import particle_error  # noqa: E402
from run_data import write_atomically  # noqa: E402

ROOT = make_cmpm_prms.ROOT
CLAMP_ZONE = 3.0  # m from each end: "near the clamps"
COLUMNS = ["layout", "max_r_u_cmpm", "time_of_max", "r_u_cmpm_end",
           "max_r_u_coarse", "soft_share", "clamp_share", "soft_volume"]


class Variant(NamedTuple):
    """An optional cMPM variant run on every layout besides the three runs."""
    key: str          # columns max_r_u_<key>, time_of_max_<key>; run name
    option: str       # its command-line flag, as argparse names it
    label: str        # what the summary and the progress line call it
    prm_variant: str  # the make_cmpm_prms.py variant its wrapper includes
    entries: str      # prm text its wrapper adds

    def columns(self):
        return [f"max_r_u_{self.key}", f"time_of_max_{self.key}"]

    def run_name(self, dim):
        return f"cmpm_bending_beam_{dim}d_{self.key}"


VARIANTS = [
    Variant("modes", "interior_modes", "cMPM with interior modes", "",
            "subsection cmpm\n  set interior modes = body load\nend\n"),
    Variant("h3_modes", "h3_modes", "L = H/3 with interior modes",
            "h3_modes", ""),
]


def chosen_variants(args):
    """The entries of VARIANTS whose flag is set in @p args."""
    return [v for v in VARIANTS if getattr(args, v.option)]


def columns_of(variants):
    return COLUMNS + [c for v in variants for c in v.columns()]


def write_scene(folder, dim, seed, variants=()):
    """The prm files of one layout in @p folder (seed None: no
    inclusions), as make_cmpm_prms.py writes them for prm/cmpm/, and the
    wrappers that run them: cMPM, BSMPM-fine, BSMPM-coarse, then each of
    @p variants (entries of VARIANTS). Returns (run name, wrapper) pairs in
    that order."""
    os.makedirs(folder, exist_ok=True)
    name = make_cmpm_prms.name_of
    files = {name("bending_beam", dim, ""):
             make_cmpm_prms.bending_beam(dim, seed)}
    for variant in ["fine", "coarse"] + [v.prm_variant for v in variants
                                         if v.prm_variant]:
        files[name("bending_beam", dim, variant)] = \
            make_cmpm_prms.bending_beam_variant(dim, variant)
    for file, text in files.items():
        write_atomically(os.path.join(folder, file), text)
    runs = []
    for variant in ("", "fine", "coarse"):
        suffix = f"_{variant}" if variant else ""
        wrapper = os.path.join(folder, f"run{suffix}.prm")
        write_atomically(wrapper, f"include {name('bending_beam', dim, variant)}"
                         "\nsubsection run\n  set quiet = true\nend\n")
        runs.append((f"cmpm_bending_beam_{dim}d{suffix}", wrapper))
    for v in variants:
        wrapper = os.path.join(folder, f"run_{v.key}.prm")
        write_atomically(wrapper,
                         f"include {name('bending_beam', dim, v.prm_variant)}"
                         "\nsubsection run\n  set quiet = true\n"
                         f"  set name = {v.run_name(dim)}\nend\n" + v.entries)
        runs.append((v.run_name(dim), wrapper))
    return runs


def run_bfemp(bfemp, folder, wrapper):
    with open(wrapper + ".log", "w") as log:
        status = subprocess.call([bfemp, os.path.basename(wrapper)],
                                 cwd=folder, stdout=log,
                                 stderr=subprocess.STDOUT)
    if status != 0:
        raise particle_error.ToolError(
            f"{wrapper}: bfemp stopped with status {status} (see "
            f"{wrapper}.log)")


def snapshot_at(path, when):
    for t, vtu in particle_error.series(path):
        if abs(t - when) <= particle_error.TIME_TOLERANCE:
            return particle_error.snapshot(vtu)
    raise particle_error.ToolError(f"{path}: no snapshot at t = {when:g}")


def where(reference_path, run_path, when):
    """Shares of the squared displacement error of @p run_path at @p when
    in the soft inclusions and within CLAMP_ZONE of the ends, and the soft
    inclusions' share of the volume."""
    reference = snapshot_at(reference_path, when)
    run = snapshot_at(run_path, when)
    p = particle_error.match(reference, run, f"{run_path} (t = {when:g})")
    weight = reference["J"] * reference["volume"]
    error = weight * np.sum(
        (run["displacement"][p] - reference["displacement"])**2, axis=1)
    soft = reference["material_id"] > 0
    x = reference["X"][:, 0]
    clamps = (x < CLAMP_ZONE) | (x > make_cmpm_prms.LENGTH - CLAMP_ZONE)
    return (error[soft].sum() / error.sum(), error[clamps].sum() / error.sum(),
            weight[soft].sum() / weight.sum())


def write_series(path, series):
    """r_u of every variant at the output times they share with the
    reference: one column per variant (r_u_cmpm, r_u_coarse, r_u_modes,
    r_u_h3_modes)."""
    names = list(series)
    by_time = [{round(t, 9): r_u for t, r_u, _ in series[n]} for n in names]
    times = sorted(set(by_time[0]).intersection(*by_time[1:]))
    write_atomically(path, "time," + ",".join(f"r_u_{n}" for n in names) +
                     "\n" + "".join(f"{t:.9g}," + ",".join(
                         f"{b[t]:.9e}" for b in by_time) + "\n"
                         for t in times))


def read_result(path, columns):
    """The row of a finished study unit's one-row CSV @p path (what a
    resumed study takes instead of running the unit again), or None if the
    file is missing or lacks one of @p columns."""
    if not os.path.isfile(path):
        return None
    with open(path) as f:
        lines = f.read().split("\n")
    row = dict(zip(lines[0].split(","), lines[1].split(",")))
    return row if all(c in row for c in columns) else None


def study_layout(bfemp, folder, dim, seed, label, variants=()):
    """Runs one layout (or reads its result.csv) and returns its row."""
    result = os.path.join(folder, "result.csv")
    columns = columns_of(variants)
    row = read_result(result, columns)
    if row is not None and os.path.isfile(os.path.join(folder, "series.csv")):
        return row
    runs = write_scene(folder, dim, seed, variants)
    for _, wrapper in runs:
        run_bfemp(bfemp, folder, wrapper)
    out = os.path.join(folder, "output")
    cmpm, fine, coarse = (os.path.join(out, name) for name, _ in runs[:3])
    cmpm_rows = particle_error.compare(fine, cmpm)
    coarse_rows = particle_error.compare(fine, coarse)
    worst = max(cmpm_rows, key=lambda row: row[1])
    soft, clamp, volume = where(fine, cmpm, worst[0])
    row = {"layout": label, "max_r_u_cmpm": f"{worst[1]:.5f}",
           "time_of_max": f"{worst[0]:.3f}",
           "r_u_cmpm_end": f"{cmpm_rows[-1][1]:.5f}",
           "max_r_u_coarse": f"{max(r[1] for r in coarse_rows):.5f}",
           "soft_share": f"{soft:.3f}", "clamp_share": f"{clamp:.3f}",
           "soft_volume": f"{volume:.3f}"}
    series = {"cmpm": cmpm_rows, "coarse": coarse_rows}
    for v in variants:
        variant_rows = particle_error.compare(
            fine, os.path.join(out, v.run_name(dim)))
        worst_variant = max(variant_rows, key=lambda r: r[1])
        row[f"max_r_u_{v.key}"] = f"{worst_variant[1]:.5f}"
        row[f"time_of_max_{v.key}"] = f"{worst_variant[0]:.3f}"
        series[v.key] = variant_rows
    write_series(os.path.join(folder, "series.csv"), series)
    write_atomically(result, ",".join(columns) + "\n" +
                     ",".join(row[c] for c in columns) + "\n")
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bfemp", default=os.path.join(ROOT, "build", "bfemp"))
    parser.add_argument("--dim", type=int, choices=(2, 3), default=2)
    parser.add_argument("--seeds", default=",".join(
        str(s) for s in [make_cmpm_prms.LAYOUT_SEED] + list(range(1, 12))))
    parser.add_argument("--no-homogeneous", action="store_true")
    parser.add_argument("--interior-modes", action="store_true")
    parser.add_argument("--h3-modes", action="store_true")
    parser.add_argument("--out")
    parser.add_argument("--quiet", action="store_true")
    args = parser.parse_args()
    try:
        seeds = [int(s) for s in args.seeds.split(",") if s.strip()]
    except ValueError:
        sys.exit(f"cmpm_beam_layouts.py: --seeds '{args.seeds}': expected "
                 "integers separated by commas")
    if not os.access(args.bfemp, os.X_OK):
        sys.exit(f"cmpm_beam_layouts.py: --bfemp {args.bfemp}: no such "
                 "executable (build bfemp first: ./setup.sh build)")
    out = os.path.abspath(args.out or os.path.join(
        ROOT, "output", f"cmpm_beam_layouts_{args.dim}d"))
    os.makedirs(out, exist_ok=True)
    layouts = [(str(s), s) for s in seeds]
    if not args.no_homogeneous:
        layouts.append(("homogeneous", None))
    variants = chosen_variants(args)
    rows, start = [], time.time()
    try:
        for i, (label, seed) in enumerate(layouts):
            rows.append(study_layout(args.bfemp, os.path.join(
                out, f"layout_{label}"), args.dim, seed, label, variants))
            if not args.quiet:
                elapsed = time.time() - start
                left = elapsed / (i + 1) * (len(layouts) - i - 1)
                r = rows[-1]
                print(f"layout {label} ({i + 1}/{len(layouts)}): max r_u cMPM "
                      f"{r['max_r_u_cmpm']} at t = {r['time_of_max']}, "
                      f"BSMPM-coarse {r['max_r_u_coarse']}"
                      + "".join(f", {v.label} {r[f'max_r_u_{v.key}']}"
                                for v in variants)
                      + f"; about {left:.0f} s left", flush=True)
    except particle_error.ToolError as error:
        sys.exit(f"cmpm_beam_layouts.py: {error}")
    table = os.path.join(out, "layouts.csv")
    columns = columns_of(variants)
    write_atomically(table, ",".join(columns) + "\n" + "".join(
        ",".join(r[c] for c in columns) + "\n" for r in rows))
    drawn = [float(r["max_r_u_cmpm"]) for r in rows
             if r["layout"] != "homogeneous"]
    print(f"{len(drawn)} layouts: max r_u of cMPM from {min(drawn):.4f} to "
          f"{max(drawn):.4f}, median {np.median(drawn):.4f}; table in {table}")
    for v in variants:
        drawn = [float(r[f"max_r_u_{v.key}"]) for r in rows
                 if r["layout"] != "homogeneous"]
        print(f"{v.label}: from {min(drawn):.4f} to {max(drawn):.4f}, "
              f"median {np.median(drawn):.4f}")


if __name__ == "__main__":
    main()
