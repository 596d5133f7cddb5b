#!/usr/bin/python3
"""BLAS threads under load: bfemp's own choice against OpenBLAS's default.

Runs two implicit scenes that factorize with CHOLMOD:
  * prm/demo_contact.prm (2D, MPM blocks on FEM bodies; 6e5 flops per
    factorization), to its end;
  * prm/experiments/6_7_twist/twist_medium_mu0_2.prm (3D; 1.7e9 flops per
    factorization), 5 steps;
with 'run/BLAS threads' = auto and 'run/threads' = 0 (bfemp's default: one
BLAS thread), auto with 'run/threads' = N (N BLAS threads in factorizations
above 1e9 flops), = 1, and = N (N = the core count: what OpenBLAS does on
its own), each on a quiet machine and next to N busy processes (the
situation of a shared workstation or cluster node), and records the wall
time of each. bfemp's own threads are all cores in every run.

  /usr/bin/python3 benchmarks/blas_threads.py [--build build] [--repeat 1]

writes benchmarks/results/blas_threads.json (see doc/performance.md).
"""

import argparse
import json
import multiprocessing
import os
import platform
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = {
    "demo_contact": (os.path.join(ROOT, "prm", "demo_contact.prm"), None),
    "twist_medium_mu0_2": (os.path.join(ROOT, "prm", "experiments",
                                        "6_7_twist",
                                        "twist_medium_mu0_2.prm"), 0.05),
}


def busy():
    while True:
        pass


def run(binary, folder, scene, name, blas, threads):
    path = os.path.join(folder, name + ".prm")
    scene_file, end_time = SCENES[scene]
    with open(path, "w") as prm:
        prm.write(f"include {scene_file}\n"
                  f"subsection run\n  set name = {name}\n"
                  f"  set quiet = true\n  set BLAS threads = {blas}\n"
                  f"  set threads = {threads}\n")
        if end_time is not None:
            prm.write(f"  set end time = {end_time}\n")
        prm.write("end\n"
                  f"subsection output\n  set directory = {folder}\n"
                  f"  set write particles = false\n"
                  f"  set write grid = false\nend\n")
    env = dict(os.environ)
    env.pop("OPENBLAS_NUM_THREADS", None)
    start = time.perf_counter()
    log = subprocess.run([binary, path], cwd=folder, env=env, check=True,
                         capture_output=True, text=True).stdout
    wall = time.perf_counter() - start
    blas_line = next((line for line in log.splitlines() if "BLAS" in line), "")
    return wall, blas_line


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--output", default=os.path.join(
        ROOT, "benchmarks", "results", "blas_threads.json"))
    args = parser.parse_args()
    binary = os.path.join(args.build, "bfemp")
    cores = os.cpu_count()
    settings = [("auto", "auto", 0),
                (f"auto, run/threads = {cores}", "auto", cores),
                ("1", "1", 0),
                (str(cores), str(cores), 0)]
    runs = []
    with tempfile.TemporaryDirectory() as folder:
        for load in (0, cores):
            workers = [multiprocessing.Process(target=busy, daemon=True)
                       for _ in range(load)]
            for w in workers:
                w.start()
            try:
                for scene in SCENES:
                    for label, blas, threads in settings:
                        walls = []
                        for k in range(args.repeat):
                            wall, line = run(binary, folder, scene,
                                             f"{scene}_{blas}_{load}_{k}",
                                             blas, threads)
                            walls.append(wall)
                        runs.append({"scene": scene, "busy processes": load,
                                     "setting": label,
                                     "wall time [s]": min(walls),
                                     "log": line})
                        print(f"{scene}, {load} busy, {label}: "
                              f"{min(walls):.1f} s", flush=True)
            finally:
                for w in workers:
                    w.terminate()
    record = {
        "benchmark": "blas_threads",
        "scenes": {k: os.path.relpath(v[0], ROOT)
                   for k, v in SCENES.items()},
        "date": time.strftime("%Y-%m-%d"),
        "machine": {"processor": platform.processor() or platform.machine(),
                    "cpus": cores, "system": platform.platform()},
        "repeat": args.repeat,
        "runs": runs,
    }
    for scene in SCENES:
        for load in (0, cores):
            wall = {r["setting"]: r["wall time [s]"] for r in runs
                    if r["scene"] == scene and r["busy processes"] == load}
            for label, _, _ in settings[1:]:
                record[f"{scene}, {load} busy: {label} / auto"] = (
                    wall[label] / wall["auto"])
    os.makedirs(os.path.dirname(args.output), exist_ok=True)
    with open(args.output + ".tmp", "w") as f:
        json.dump(record, f, indent=1)
    os.replace(args.output + ".tmp", args.output)
    print("wrote", args.output)


if __name__ == "__main__":
    main()
