"""The command line that bfemp's one-parameter studies share
(cmpm_lattice_struts.py, cmpm_cube_inclusions.py): --bfemp, a list of the
parameter's values, --out and --quiet; each value's row is computed (or read
back, so that a study resumes) by the study's own function, and the rows go
to one table, complete or absent."""

import argparse
import os
import sys

from run_data import run_units, write_table

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))


def main(doc, script, option, unit, default, bounds, why, study, describe,
         table, columns, error_type):
    """Runs study(bfemp, folder, value) for each value of --@p option (in
    [bounds[0], bounds[1]], @p why says why) in folder
    <out>/@p unit_<value>, prints describe(value, row) per value unless
    --quiet, and writes the rows to <out>/@p table. An @p error_type raised
    by the study ends the script with its message."""
    parser = argparse.ArgumentParser(description=doc.split("\n")[0])
    parser.add_argument("--bfemp", default=os.path.join(ROOT, "build", "bfemp"))
    parser.add_argument(f"--{option}", default=default)
    parser.add_argument("--out")
    parser.add_argument("--quiet", action="store_true")
    args = parser.parse_args()
    text = getattr(args, option)
    try:
        values = [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        sys.exit(f"{script}: --{option} '{text}': expected numbers separated "
                 "by commas")
    if not values or any(not bounds[0] <= v <= bounds[1] for v in values):
        sys.exit(f"{script}: --{option} '{text}': each value must lie in "
                 f"[{bounds[0]:g}, {bounds[1]:g}] ({why})")
    if not os.access(args.bfemp, os.X_OK):
        sys.exit(f"{script}: --bfemp {args.bfemp}: no such executable (build "
                 "bfemp first: ./setup.sh build)")
    out = os.path.abspath(args.out or os.path.join(
        ROOT, "output", os.path.splitext(script)[0]))
    os.makedirs(out, exist_ok=True)
    try:
        rows = run_units(values, lambda v: study(
            args.bfemp, os.path.join(out, f"{unit}_{v:.4f}"), v), describe,
            args.quiet)
    except error_type as error:
        sys.exit(f"{script}: {error}")
    path = os.path.join(out, table)
    write_table(path, columns, rows)
    print(f"table in {path}")
