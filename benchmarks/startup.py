#!/usr/bin/env python3
"""The program's start-up: `hydrodda --version` and a whole run of one block on a fixed base
(5 static steps, its run folder written), each a fresh process, ROUNDS times; prints the
median wall time and CPU time (user + system, from the children's rusage) of each and the load
average before and after. With more build folders after ROUNDS, each round runs every build in
turn, so that a loaded machine's swings fall on all of them alike.

    benchmarks/startup.py [BUILD_DIR] [ROUNDS] [OTHER_BUILD_DIR...]
    benchmarks/startup.py build 21
    benchmarks/startup.py build 21 ../old/build
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
    builds = [Path(sys.argv[1] if len(sys.argv) > 1 else "build").resolve()]
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 21
    builds += [Path(b).resolve() for b in sys.argv[3:]]
    work = Path(tempfile.mkdtemp())
    try:
        scenario = work / "one.toml"
        scenario.write_text(ONE_BLOCK)
        folder = work / "one"
        print("load average before: " + " ".join(f"{x:.2f}" for x in os.getloadavg()))
        times = {(b, name): [] for b in builds for name in ("--version", "run, one block")}
        for _ in range(rounds):
            for build in builds:
                program = str(build / "bin" / "hydrodda")
                times[(build, "--version")].append(timed([program, "--version"]))
                shutil.rmtree(folder, ignore_errors=True)
                times[(build, "run, one block")].append(timed([program, "run", "-q", str(scenario), "-o", str(folder)]))
        print("load average after: " + " ".join(f"{x:.2f}" for x in os.getloadavg()))
        for (build, name), rows in times.items():
            wall = statistics.median(r[0] for r in rows) * 1e3
            cpu = statistics.median(r[1] for r in rows) * 1e3
            label = f"{build}: " if len(builds) > 1 else ""
            print(f"{label}{name}: median wall {wall:.1f} ms, CPU {cpu:.1f} ms ({rounds} runs)")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
