#!/usr/bin/env python3
"""The program's start-up: `hydrodda --version` and a whole run of one block on a fixed base
(5 static steps, its run folder written), each a fresh process, ROUNDS times; prints the
median wall time and CPU time (user + system, from the children's rusage) of each and the load
average before and after.

    benchmarks/startup.py [BUILD_DIR] [ROUNDS]
    benchmarks/startup.py build 21
"""

import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ONE_BLOCK = """title = "one block on a base"
[[geometry.block]]
vertices = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
[[geometry.block]]
vertices = [[-1.0, -1.0], [2.0, -1.0], [2.0, 0.0], [-1.0, 0.0]]
fixed = true
[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25
[joint]
friction_angle = 30.0
[mechanics]
analysis = "static"
gravity = [0.0, -9.81]
time_step = 1.0e-3
steps = 5
"""


def timed(command):
    """Wall and CPU seconds of one child process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def main():
    build = Path(sys.argv[1] if len(sys.argv) > 1 else "build").resolve()
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 21
    program = build / "bin" / "hydrodda"
    work = Path(tempfile.mkdtemp())
    try:
        scenario = work / "one.toml"
        scenario.write_text(ONE_BLOCK)
        folder = work / "one"
        print("load average before: " + " ".join(f"{x:.2f}" for x in os.getloadavg()))
        times = {"--version": [], "run, one block": []}
        for _ in range(rounds):
            times["--version"].append(timed([str(program), "--version"]))
            shutil.rmtree(folder, ignore_errors=True)
            times["run, one block"].append(timed([str(program), "run", "-q", str(scenario), "-o", str(folder)]))
        print("load average after: " + " ".join(f"{x:.2f}" for x in os.getloadavg()))
        for name, rows in times.items():
            wall = statistics.median(r[0] for r in rows) * 1e3
            cpu = statistics.median(r[1] for r in rows) * 1e3
            print(f"{name}: median wall {wall:.1f} ms, CPU {cpu:.1f} ms ({rounds} runs)")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
