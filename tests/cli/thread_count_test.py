#!/usr/bin/env python3
"""A coupled run gives the same run folder, byte for byte, on 1, 2, 3 and 8 threads.

    thread_count_test.py PROGRAM SCENARIO

Runs SCENARIO with HYDRODDA_THREADS=1, 2, 3 and 8 (8 on a machine of fewer cores: the threads
take turns, which changes nothing), and once with --threads 3 over HYDRODDA_THREADS=1, and
compares every run folder with the one-thread run by the rules of
scripts/compare_run_folders.py (summary.json without its timings, every other file byte for
byte, figures included). The log must say how many threads each run used. Exit code 0 when all
agree.
"""

import os
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
from compare_run_folders import compare_folders  # noqa: E402


def run(program, scenario, folder, threads_variable, arguments=()):
    env = dict(os.environ, HYDRODDA_THREADS=str(threads_variable))
    env.pop("OMP_NUM_THREADS", None)
    result = subprocess.run([program, "-v", "run", str(scenario), "-o", str(folder), *arguments],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    if result.returncode != 0:
        sys.exit(f"{folder.name}: exit code {result.returncode}\n{result.stdout}")
    return result.stdout


def main():
    program, scenario = sys.argv[1], Path(sys.argv[2])
    problems = []
    with tempfile.TemporaryDirectory(prefix="hydrodda-threads-") as work:
        work = Path(work)
        runs = {"threads-1": (1, ()), "threads-2": (2, ()), "threads-3": (3, ()), "threads-8": (8, ()),
                "option-3": (1, ("--threads", "3"))}
        for name, (variable, arguments) in runs.items():
            log = run(program, scenario, work / name, variable, arguments)
            expected = int(arguments[1]) if arguments else variable
            if f"{expected} thread(s), as chosen" not in log:
                problems.append(f"{name}: the log does not say {expected} thread(s)\n{log}")
        for name in runs:
            if name == "threads-1":
                continue
            count = compare_folders(work / "threads-1", work / name, name, problems)
            if count < 5:
                problems.append(f"{name}: only {count} files written")
    for problem in problems:
        print(problem)
    print("same run folders on 1, 2, 3 and 8 threads" if not problems else f"{len(problems)} difference(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
