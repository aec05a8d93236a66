#!/usr/bin/env python3
"""Scenarios of many short random fracture traces in a 100 m square, for timing the cut.

For each count N, writes OUT/traces_N.csv (rows x1,y1,x2,y2) and OUT/traces_N.toml (a
mechanics-only scenario that reads it), the same files on every machine for the same seed:
each trace has its middle uniform in the square, a direction uniform in [0°, 180°) and a length
uniform in [2, 6] m × √(10,000 / N) (or in --length MIN MAX), and is clipped to the square
(those that cross its sides join the network to the boundary; the cut drops what is joined to
nothing). The scaled lengths make networks alike, finer as N grows: their blocks grow as N
(some 40,000 at N = 10,000), where fixed lengths would make them grow as N².

    python3 benchmarks/random_traces.py [--out out/random-traces] [--seed 1] 10000 20000 100000
    time build/bin/hydrodda check out/random-traces/traces_10000.toml

Standard library only (random.Random is the Mersenne Twister, the same on every platform).
"""
import argparse
import math
import os
import random

SCENARIO = """# {count} random short traces in a 100 m square (benchmarks/random_traces.py, seed {seed})
[geometry]
domain = [[0.0, 0.0], [100.0, 0.0], [100.0, 100.0], [0.0, 100.0]]
fractures_file = "traces_{count}.csv"
[material.rock]
density = 2500.0
young = 1.0e10
poisson = 0.25
[mechanics]
analysis = "dynamic"
steps = 10
"""


def clip_to_square(x1, y1, x2, y2, side=100.0):
    """The part of the segment inside [0, side]² (Liang–Barsky), or None."""
    t0, t1 = 0.0, 1.0
    for p, q in ((x1 - x2, x1), (x2 - x1, side - x1), (y1 - y2, y1), (y2 - y1, side - y1)):
        if p == 0.0:
            if q < 0.0:
                return None
            continue
        t = q / p
        if p < 0.0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
    if t1 - t0 <= 1e-6:
        return None
    dx, dy = x2 - x1, y2 - y1
    return x1 + t0 * dx, y1 + t0 * dy, x1 + t1 * dx, y1 + t1 * dy


def write_traces(path, count, seed, shortest, longest):
    rng = random.Random(seed)
    with open(path, "w", newline="\n") as out:
        out.write("x1,y1,x2,y2\n")
        written = 0
        while written < count:
            x, y = rng.uniform(0.0, 100.0), rng.uniform(0.0, 100.0)
            angle = rng.uniform(0.0, math.pi)
            half = 0.5 * rng.uniform(shortest, longest)
            dx, dy = half * math.cos(angle), half * math.sin(angle)
            clipped = clip_to_square(x - dx, y - dy, x + dx, y + dy)
            if clipped is None:
                continue
            out.write("{:.6f},{:.6f},{:.6f},{:.6f}\n".format(*clipped))
            written += 1


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("counts", type=int, nargs="+")
    parser.add_argument("--out", default="out/random-traces")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--length", type=float, nargs=2, metavar=("MIN", "MAX"), help="fixed trace lengths (m)")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for count in args.counts:
        lengths = args.length or [length * math.sqrt(10000 / count) for length in (2.0, 6.0)]
        write_traces(os.path.join(args.out, f"traces_{count}.csv"), count, args.seed, *lengths)
        with open(os.path.join(args.out, f"traces_{count}.toml"), "w", newline="\n") as out:
            out.write(SCENARIO.format(count=count, seed=args.seed))
        print(os.path.join(args.out, f"traces_{count}.toml"))


if __name__ == "__main__":
    main()
