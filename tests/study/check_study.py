#!/usr/bin/python3
"""Checks tools/bfemp-study end to end (tests/study/CMakeLists.txt):

    check_study.py BFEMP_STUDY BFEMP STUDY.toml

1. The quick bar study runs: every variant finishes, the period error falls
   with the cell size, and the fitted order lies in [1.8, 2.2] (the
   B-spline MPM bar converges at second order,
   tests/physics/bar_vibration_2d).
2. Run again, it runs nothing and reports the same table.
3. Bad study files are refused with exit 1 and a message naming the key:
   an unknown prm entry (refused by bfemp --validate), an empty sweep, a
   missing reference, an unknown error quantity, a missing script.
   A measuring script's number (quantity = "script") is read.
Prints the measured numbers; exits non-zero on the first failed check.
"""
import csv
import os
import subprocess
import sys
import tempfile

failures = []


def check(condition, what):
    print(("OK   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


def main():
    tool, bfemp, study = sys.argv[1:4]
    with tempfile.TemporaryDirectory() as scratch:
        folder = os.path.join(scratch, "bar")
        command = ["/usr/bin/python3", tool, study, "--bfemp", bfemp,
                   "--output", folder, "--jobs", "2"]
        first = subprocess.run(command, capture_output=True, text=True)
        print(first.stdout + first.stderr)
        check(first.returncode == 0, "the study runs (exit 0)")
        with open(os.path.join(folder, "results.csv")) as f:
            rows = list(csv.DictReader(f))
        for row in rows:
            print(f"cell size {row['grid/cell size']}: period "
                  f"{float(row['quantity']):.5f} s, relative error "
                  f"{float(row['error']):.2e}, steps {row['steps']}")
        check(len(rows) == 3 and all(r["status"] == "finished"
                                     for r in rows),
              "three variants, all finished")
        errors = [float(r["error"]) for r in rows]
        check(errors[0] > errors[1] > errors[2],
              "the period error falls with the cell size")
        order = [line for line in first.stdout.splitlines()
                 if "fitted order of 'grid/cell size'" in line]
        value = float(order[0].split(":")[-1].split()[0]) if order else 0.
        check(1.8 <= value <= 2.2,
              f"fitted order {value:.2f} in [1.8, 2.2]")
        for name in ("results.md", "error_vs_cost.png",
                     "error_vs_grid_cell_size.png"):
            check(os.path.isfile(os.path.join(folder, name)),
                  f"{name} written")

        second = subprocess.run(command, capture_output=True, text=True)
        check(second.returncode == 0 and
              "3 of 3 variants finished earlier" in second.stdout and
              "variant 1/" not in second.stdout,
              "a finished study is resumed without running any variant")
        with open(os.path.join(folder, "results.csv")) as f:
            again = list(csv.DictReader(f))
        check([r["error"] for r in again] == [r["error"] for r in rows],
              "the resumed study reports the same errors")

        base = os.path.join(os.path.dirname(os.path.abspath(study)),
                            "bar_base.prm")
        # quantity = "script": a measuring script of the user's, here the
        # time of the last diagnostics row, which must be the end time.
        script = os.path.join(scratch, "last_time.py")
        with open(script, "w") as f:
            f.write("import csv, os, sys\n"
                    "rows = list(csv.DictReader(open(os.path.join("
                    "sys.argv[1], 'diagnostics.csv'))))\n"
                    "print(rows[-1]['time'])\n")
        scripted = os.path.join(scratch, "scripted.toml")
        with open(scripted, "w") as f:
            f.write(f'name = "scripted"\nbase = "{base}"\n[sweep]\n'
                    '"grid/cell size" = [0.125]\n[error]\n'
                    f'quantity = "script"\nscript = "{script}"\n'
                    'exact = "0.145465"\n')
        done = subprocess.run(
            ["/usr/bin/python3", tool, scripted, "--bfemp", bfemp,
             "--output", os.path.join(scratch, "scripted"), "--quiet"],
            capture_output=True, text=True)
        with open(os.path.join(scratch, "scripted", "results.csv")) as f:
            row = next(csv.DictReader(f))
        print(f"script quantity: {row['quantity']}, error {row['error']}")
        check(done.returncode == 0 and float(row["error"]) < 1e-9,
              "quantity 'script' reads the number a script prints "
              "(the end time, 0.145465 s)")

        head = f'name = "bad"\nbase = "{base}"\n'
        error = ('[error]\nquantity = "period"\nsignal = "kinetic_energy"\n'
                 'exact = "1"\n')
        bad = {
            "unknown entry": (head + '[sweep]\n"grid/cell sise" = [0.1]\n' +
                              error, "no such entry"),
            "empty sweep": (head + "[sweep]\n" + error,
                            "'sweep': the sweep is empty"),
            "missing reference": (
                head + '[sweep]\n"grid/cell size" = [0.125]\n[error]\n'
                'quantity = "series"\nsignal = "momentum_x"\n'
                'reference = "finest"\n', "'error.reference' = 'finest'"),
            "unknown quantity": (
                head + '[sweep]\n"grid/cell size" = [0.125]\n[error]\n'
                'quantity = "speed"\n', "'error.quantity' = 'speed'"),
            "missing script": (
                head + '[sweep]\n"grid/cell size" = [0.125]\n[error]\n'
                'quantity = "script"\nscript = "no_such_measure.py"\n'
                'exact = "1"\n', "'error.script': no such file"),
        }
        for what, (text, fragment) in bad.items():
            path = os.path.join(scratch, what.replace(" ", "_") + ".toml")
            with open(path, "w") as f:
                f.write(text)
            done = subprocess.run(
                ["/usr/bin/python3", tool, path, "--bfemp", bfemp,
                 "--output", os.path.join(scratch, "bad")],
                capture_output=True, text=True)
            print(done.stderr.strip())
            check(done.returncode == 1 and fragment in done.stderr and
                  not os.path.isdir(os.path.join(scratch, "bad", "runs",
                                                 "v000_base")),
                  f"refused: {what}, naming {fragment!r}, nothing run")
    if failures:
        print(f"check_study: {len(failures)} checks failed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
