#!/usr/bin/env python3
"""The table of docs/studies/2026-11-29-brazilian-disc.md: the Brazilian disc of
scenarios/verification/brazilian_disc.toml (D = 1 m, flats 2b = 0.1 m, bonds of T = 1 MPa) at
three sizes of its triangle sub-blocks and in Voronoi cells: the Brazilian tension
sigma_t = 2 P / (pi D t) at its first break over T, the breaks by the run's end, where they lie,
and how the run ended.

    scripts/brazilian_disc_study.py build/bin/hydrodda [--end-time 400]
"""
import argparse
import csv
import json
import math
import pathlib
import re
import subprocess
import tempfile

SCENARIO = pathlib.Path(__file__).resolve().parent.parent / "scenarios/verification/brazilian_disc.toml"
STRENGTH = 1.0e6
FLAT = 0.1


def pressure_at(t):
    """The scenario's table: 0 to 12 MPa over 100 s, then 20 kPa a second."""
    return 1.2e5 * t if t <= 100.0 else 1.2e7 + 2.0e4 * (t - 100.0)


def brazilian(t):
    return 2.0 * pressure_at(t) * FLAT / math.pi


def variant(text, size, kind, end_time):
    text = re.sub(r"^size = .*$", f"size = {size}", text, count=1, flags=re.M)
    text = re.sub(r'^kind = ".*"$', f'kind = "{kind}"', text, count=1, flags=re.M)
    text = re.sub(r"^end_time = .*$", f"end_time = {end_time}", text, count=1, flags=re.M)
    # the pressure's table carried on at 20 kPa a second to the end
    return text.replace("[400.0, -1.8e7]", f"[{end_time}, {-pressure_at(end_time):.6g}]")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("program")
    parser.add_argument("--end-time", type=float, default=400.0)
    parser.add_argument("--cases", default="triangles:0.1,triangles:0.05,triangles:0.025,voronoi:0.05")
    args = parser.parse_args()
    print("| kind | size | sub-blocks | first break: 2P/(pi D t) / T | its face's midpoint x | breaks by the end | within D/10 of the diameter | end |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(tmp)
        for case in args.cases.split(","):
            kind, size = case.split(":")
            (folder / "case.toml").write_text(variant(SCENARIO.read_text(), size, kind, args.end_time))
            out = folder / "out"
            subprocess.run([args.program, "run", str(folder / "case.toml"), "-o", str(out), "--threads", "1", "-q", "--overwrite"],
                           check=False, capture_output=True)
            summary = json.loads((out / "summary.json").read_text())
            rows = list(csv.DictReader((out / "fractures.csv").open()))
            mids = [0.5 * (float(r["x1"]) + float(r["x2"])) for r in rows]
            first = f"{brazilian(float(rows[0]['time'])) / STRENGTH:.3f}" if rows else "none"
            first_x = f"{mids[0]:.3f}" if rows else ""
            near = sum(1 for x in mids if abs(x) < 0.1)
            end = f"held at {brazilian(args.end_time) / STRENGTH:.2f} T"
            if summary["status"] != "ok":  # its message says when: "... (t = 530.479 s) ..."
                when = re.search(r"t = ([0-9.e+-]+) s", summary["message"])
                at = f" at {brazilian(float(when.group(1))) / STRENGTH:.2f} T (t = {when.group(1)} s)" if when else ""
                end = f"{summary['status']}{at}: {summary['message'].split(':')[-1].strip()}"
            print(f"| {kind} | {size} | {len(summary['blocks'])} | {first} | {first_x} | {len(rows)} | {near} | {end} |", flush=True)


if __name__ == "__main__":
    main()
