#!/usr/bin/env python3
"""Terzaghi's consolidation: a run folder of scenarios/verification/terzaghi_consolidation.toml
(or one edited from it) against the series solution (Verruijt, Theory and Problems of
Poroelasticity, ch. 2): the pressure at each probe and the settlement of the top at the four
output times, and their errors relative to p0 and to the final settlement s_inf - s_0.

  scripts/terzaghi_consolidation_error.py RUN_FOLDER [--blocks N] [--height H] ...
"""
import argparse
import csv
import math
import sys


def series_pressure(depth, t, p0, cv, height, terms=400):
    T = cv * t / height ** 2
    total = 0.0
    for m in range(terms):
        M = (2 * m + 1) * math.pi / 2
        total += 2 / M * math.sin(M * depth / height) * math.exp(-M * M * T)
    return p0 * total


def degree_of_consolidation(t, cv, height, terms=400):
    T = cv * t / height ** 2
    return 1 - sum(2 / ((2 * m + 1) * math.pi / 2) ** 2 * math.exp(-((2 * m + 1) * math.pi / 2) ** 2 * T)
                   for m in range(terms))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("folder")
    ap.add_argument("--height", type=float, default=10.0)
    ap.add_argument("--young", type=float, default=1.0e9)
    ap.add_argument("--poisson", type=float, default=0.25)
    ap.add_argument("--storage", type=float, default=1.0e-10)
    ap.add_argument("--permeability", type=float, default=1.0e-15)
    ap.add_argument("--load", type=float, default=1.0e6)
    ap.add_argument("--times", default="4667,9333,28000,93330")
    a = ap.parse_args()
    E, nu, H = a.young, a.poisson, a.height
    Kv = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    cv = a.permeability / 1e-3 / (a.storage + 1 / Kv)
    p0 = a.load / (1 + a.storage * Kv)
    s0 = a.load * H * (1 - p0 / a.load) / Kv
    sinf = a.load * H / Kv
    times = [float(t) for t in a.times.split(",")]
    probes = {}
    with open(f"{a.folder}/probes.csv") as f:
        for row in csv.DictReader(f):
            probes[(float(row["time"]), row["name"])] = float(row["pressure"])
    settle = {}
    with open(f"{a.folder}/measure.csv") as f:
        for row in csv.DictReader(f):
            settle[float(row["time"])] = -float(row["uy"])
    worst_p = worst_s = 0.0
    print("| t (s) | T | probe | p (MPa) | series (MPa) | error / p0 |")
    print("| --- | --- | --- | --- | --- | --- |")
    for t in times:
        tt = min(settle, key=lambda x: abs(x - t))
        for (time, name), p in sorted(probes.items()):
            if time != tt:
                continue
            depth = H - {"z2.5": 7.5, "z5": 5.0, "z10": 0.0}[name]
            ref = series_pressure(depth, tt, p0, cv, H)
            err = (p - ref) / p0
            worst_p = max(worst_p, abs(err))
            print(f"| {tt:g} | {cv*tt/H**2:.3f} | {name} | {p/1e6:.5f} | {ref/1e6:.5f} | {err:+.4f} |")
    print()
    print("| t (s) | settlement (mm) | series (mm) | error / (s_inf - s_0) |")
    print("| --- | --- | --- | --- |")
    for t in times:
        tt = min(settle, key=lambda x: abs(x - t))
        ref = s0 + (sinf - s0) * degree_of_consolidation(tt, cv, H)
        err = (settle[tt] - ref) / (sinf - s0)
        worst_s = max(worst_s, abs(err))
        print(f"| {tt:g} | {settle[tt]*1e3:.4f} | {ref*1e3:.4f} | {err:+.4f} |")
    print(f"\nworst pressure error {worst_p:.4f} of p0, worst settlement error {worst_s:.4f} of s_inf - s_0")


if __name__ == "__main__":
    sys.exit(main())
