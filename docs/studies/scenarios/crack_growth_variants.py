#!/usr/bin/env python3
"""Writes variants of crack_growth.toml for the softening-bonds study
(docs/studies/2026-11-29-softening-bonds.md): a crack of half-length a (m), the tip's refined
region and path moved with it, the remote tension rising from 0.8 to 1.2 sigma_c(a) in 40 steps
of 1% sigma_c, and with --coarse the sub-blocks twice as large (0.05, 0.12, 0.35, 0.6 m).

  docs/studies/scenarios/crack_growth_variants.py --coarse 0.75 1 1.25 -o growth
  build/bin/hydrodda run growth/coarse_1.toml -o growth/out_1 --threads 1 -v
"""
import argparse
import math
import pathlib
import re

E, NU, G_F, W = 1.0e10, 0.25, 36.0, 6.0  # as in crack_growth.toml


def sigma_c(a):
    """Irwin, Feddersen (1966): sqrt(E' G_f) / sqrt(pi a) / sqrt(sec(pi a / W))."""
    return math.sqrt(E / (1 - NU**2) * G_F) / math.sqrt(math.pi * a) / math.sqrt(1 / math.cos(math.pi * a / W))


def variant(text, a, coarse):
    def sub(old, new):
        nonlocal text
        if old not in text:
            raise SystemExit(f"crack_growth.toml no longer has: {old}")
        text = text.replace(old, new)

    sub("cracks = [[[0.0, 0.0], [1.0, 0.0]]]", f"cracks = [[[0.0, 0.0], [{a:g}, 0.0]]]")
    sub("region = [[0.0, -0.06], [1.65, -0.06], [1.65, 0.06], [0.0, 0.06]]",
        f"region = [[0.0, -0.06], [{a + 0.65:g}, -0.06], [{a + 0.65:g}, 0.06], [0.0, 0.06]]")
    sub("paths = [[[0.0, 0.0], [1.6, 0.0]]]", f"paths = [[[0.0, 0.0], [{a + 0.6:g}, 0.0]]]")
    sub("region = [[0.8, -0.15], [1.6, -0.15], [1.6, 0.15], [0.8, 0.15]]",
        f"region = [[{a - 0.2:g}, -0.15], [{a + 0.6:g}, -0.15], [{a + 0.6:g}, 0.15], [{a - 0.2:g}, 0.15]]")
    s = sigma_c(a)
    sub("normal = [[0.0, 0.0], [1.0, 2.0e5], [80.0, 4.57e5]]",
        f"normal = [[0.0, 0.0], [1.0, {0.8 * s:.6g}], [41.0, {1.2 * s:.6g}]]")
    sub("end_time = 80.0", "end_time = 41.0")
    if coarse:
        text = text.replace("size = 0.025", "size = 0.05").replace("size = 0.07", "size = 0.12")
        text = re.sub(r"^size = 0.2$", "size = 0.35", text, flags=re.M)
    return text


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("lengths", nargs="+", type=float, help="half-lengths a (m)")
    parser.add_argument("--coarse", action="store_true")
    parser.add_argument("-o", "--output", default=".")
    args = parser.parse_args()
    here = pathlib.Path(__file__).parent
    text = (here / "crack_growth.toml").read_text()
    out = pathlib.Path(args.output)
    out.mkdir(parents=True, exist_ok=True)
    for a in args.lengths:
        name = out / f"{'coarse' if args.coarse else 'fine'}_{a:g}.toml"
        name.write_text(variant(text, a, args.coarse))
        print(f"{name}: sigma_c = {sigma_c(a):.6g} Pa")


if __name__ == "__main__":
    main()
