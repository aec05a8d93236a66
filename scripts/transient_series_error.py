#!/usr/bin/env python3
"""Backward Euler's error on the 1D diffusion verification, against Carslaw & Jaeger's series.

Runs scenarios/verification/transient_diffusion_1d.toml (a closed strip 10 m long, c = 0.1 m²/s,
its end's head stepped from 10 to 11 m) with each given first step, largest step and mesh size,
and prints a Markdown table of the largest error of its four probes at each output time, as a
share of the head change:

    scripts/transient_series_error.py build/bin/hydrodda 0.05,5,0.1 0.01,1,0.1 0.01,1,0.025

Each case is TIME_STEP,MAX_TIME_STEP,MESH_SIZE (s, s, m).
"""

import csv
import math
import re
import subprocess
import sys
import tempfile
from pathlib import Path

SCENARIO = Path(__file__).resolve().parent.parent / "scenarios" / "verification" / "transient_diffusion_1d.toml"
PROBES = {"x1": 1.0, "x2.5": 2.5, "x5": 5.0, "x10": 10.0}
TIMES = (20.0, 100.0, 300.0, 1000.0)


def series(x, t, c=0.1, length=10.0):
    """h − h0 over H: Carslaw & Jaeger (1959) §3.3, the slab with one face closed."""
    total = 0.0
    for n in range(2000):
        m = 2 * n + 1
        total += 4 / (m * math.pi) * math.sin(m * math.pi * x / (2 * length)) * math.exp(
            -m * m * math.pi ** 2 * c * t / (4 * length * length))
    return 1.0 - total


def run_case(binary, first, largest, size, folder):
    text = SCENARIO.read_text()
    text = re.sub(r"^time_step = .*$", f"time_step = {first}", text, flags=re.M)
    text = re.sub(r"^max_time_step = .*$", f"max_time_step = {largest}", text, flags=re.M)
    text = re.sub(r"^size = .*$", f"size = {size}", text, flags=re.M)
    text = re.sub(r'^figures = .*$', "figures = []", text, flags=re.M)
    scenario = folder / f"case_{first}_{largest}_{size}.toml"
    scenario.write_text(text)
    out = folder / scenario.stem
    subprocess.run([binary, "run", str(scenario), "-o", str(out), "--threads", "1", "-q"], check=True)
    worst = {t: 0.0 for t in TIMES}
    for row in csv.DictReader(open(out / "probes.csv")):
        t = float(row["time"])
        if t in worst:
            worst[t] = max(worst[t], abs(float(row["head"]) - 10.0 - series(PROBES[row["name"]], t)))
    steps = sum(1 for _ in open(out / "history.csv")) - 2
    return worst, steps


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    binary = sys.argv[1]
    print("| time_step (s) | max_time_step (s) | mesh.size (m) | steps | " +
          " | ".join(f"t = {t:g} s" for t in TIMES) + " |")
    print("| --- " * (4 + len(TIMES)) + "|")
    with tempfile.TemporaryDirectory() as folder:
        for case in sys.argv[2:]:
            first, largest, size = case.split(",")
            worst, steps = run_case(binary, first, largest, size, Path(folder))
            print(f"| {first} | {largest} | {size} | {steps} | " +
                  " | ".join(f"{100 * worst[t]:.3f}%" for t in TIMES) + " |")


if __name__ == "__main__":
    main()
