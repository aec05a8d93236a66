#!/usr/bin/env python3
"""Mandel's problem: a run folder of scenarios/verification/mandel.toml (or one edited from it)
against Mandel's series (Abousleiman, Cheng, Cui, Detournay & Roegiers 1996; Cheng & Detournay
1988): each probe's pressure at the output times and its error relative to p0, then the centre's
first step, its highest pressure and the Mandel-Cryer rise against the series'.

  scripts/mandel_error.py RUN_FOLDER [--times 9.33,46.67,93.3,466.7]

The probes are named `centre` (x = 0) and `xX` (x = X m); the material is the scenario's
(E = 1 GPa, nu = 0.25, alpha = 1, S = 1e-10 1/Pa, k = 1e-15 m2, mu = 1e-3 Pa s, a = 1 m,
sigma0 = 1 MPa).
"""
import argparse
import csv
import math

E, NU, ALPHA, S, K, MU, A, SIGMA0 = 1e9, 0.25, 1.0, 1e-10, 1e-15, 1e-3, 1.0, 1e6
M = 1 / S
BULK = E / (3 * (1 - 2 * NU))
SHEAR = E / (2 * (1 + NU))
BULK_U = BULK + ALPHA ** 2 * M
B = ALPHA * M / BULK_U
NU_U = (3 * BULK_U - 2 * SHEAR) / (2 * (3 * BULK_U + SHEAR))
C = 2 * (K / MU) * B ** 2 * SHEAR * (1 - NU) * (1 + NU_U) ** 2 / (9 * (1 - NU_U) * (NU_U - NU))
P0 = SIGMA0 * B * (1 + NU_U) / 3


def roots(count=200):
    """The roots of tan a = (1 - nu)/(nu_u - nu) a, one in each (n pi, n pi + pi/2)."""
    slope = (1 - NU) / (NU_U - NU)
    out = []
    for n in range(count):
        lo, hi = n * math.pi + 1e-12, n * math.pi + math.pi / 2 - 1e-12
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if math.tan(mid) - slope * mid > 0:
                hi = mid
            else:
                lo = mid
        out.append(0.5 * (lo + hi))
    return out


ROOTS = roots()


def series_pressure(x, t):
    return 2 * P0 * sum(math.sin(a) / (a - math.sin(a) * math.cos(a)) * (math.cos(a * x / A) - math.cos(a)) *
                        math.exp(-a * a * C * t / A ** 2) for a in ROOTS)


def position(name):
    return 0.0 if name == "centre" else float(name[1:])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run_folder")
    parser.add_argument("--times", default="9.33,46.67,93.3,466.7")
    args = parser.parse_args()
    times = [float(v) for v in args.times.split(",")]
    rows = list(csv.DictReader(open(f"{args.run_folder}/probes.csv")))
    print(f"B {B:.4f}, nu_u {NU_U:.4f}, c {C:.4e} m2/s, a2/c {A * A / C:.1f} s, p0 {P0:.1f} Pa")
    print("| t (s) | t* | probe | pressure (Pa) | series (Pa) | error (of p0) |")
    print("| --- | --- | --- | --- | --- | --- |")
    worst = 0.0
    for row in rows:
        t = float(row["time"])
        if not any(abs(t - target) <= 1e-9 * max(target, 1.0) for target in times):
            continue
        reference = series_pressure(position(row["name"]), t)
        error = (float(row["pressure"]) - reference) / P0
        worst = max(worst, abs(error))
        print(f"| {t:g} | {C * t / A ** 2:.3f} | {row['name']} | {float(row['pressure']):.0f} | {reference:.0f} | "
              f"{100 * error:+.2f}% |")
    print(f"worst {100 * worst:.2f}% of p0")
    centre = [(float(r["time"]), float(r["pressure"])) for r in rows if r["name"] == "centre" and float(r["time"]) > 0]
    first_t, first_p = centre[0]
    peak_t, peak_p = max(centre, key=lambda v: v[1])
    series_peak_t, series_peak_p = max(((0.5 * i, series_pressure(0.0, 0.5 * i)) for i in range(1, 600)),
                                       key=lambda v: v[1])
    print(f"centre, first step t = {first_t:g} s: {first_p / P0:.4f} p0 (series {series_pressure(0.0, first_t) / P0:.4f})")
    print(f"centre, highest: {peak_p / P0:.4f} p0 at {peak_t:g} s (series {series_peak_p / P0:.4f} p0 at {series_peak_t:g} s)")
    rise, series_rise = (peak_p - first_p) / P0, (series_peak_p - series_pressure(0.0, first_t)) / P0
    print(f"Mandel-Cryer rise: {rise:.4f} p0 (series {series_rise:.4f}, error {100 * (rise - series_rise):+.2f}% of p0)")


if __name__ == "__main__":
    main()
