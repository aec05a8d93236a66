#!/usr/bin/env python3
"""Run coupled scenarios at several coupling.ramp_passes and print one markdown table.

Usage:
  scripts/ramp_study.py PROGRAM OUT_DIR SCENARIO... [--ramps 1,3,5] [--set KEY=VALUE]...

Each scenario runs once per ramp (`hydrodda sweep --set coupling.ramp_passes=N`, one case,
`--threads 1`) into OUT_DIR/<scenario stem>[-tag]-ramp<N>. A row a scenario, a cell a ramp: the
run's end (converged or not, its passes), its wall time, and what its summary.json gives of the
quantities its tests read: the K_eff/K_m of each flow region, the largest fracture aperture, the
vertical displacement of each measure point. Extra --set values (e.g. a head) go to every run;
--tag names them in the folder and the row.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time


def run_case(program, scenario, out, ramp, extra_sets, timeout):
    sets = ["--set", f"coupling.ramp_passes={ramp}"]
    for item in extra_sets:
        sets += ["--set", item]
    cmd = [program, "sweep", scenario, *sets, "-o", out, "--jobs", "1", "--threads", "1", "-q", "--overwrite"]
    start = time.monotonic()
    try:
        done = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, timeout=timeout,
                              check=False)
    except subprocess.TimeoutExpired:
        return "timed out", time.monotonic() - start
    wall = time.monotonic() - start
    refused = re.search(r"(coupling\.ramp_passes: must be below [^:]*)", done.stderr)
    if refused:
        return f"refused by check ({refused.group(1)})", wall
    summaries = []
    for root, _dirs, files in os.walk(out):
        if "summary.json" in files:
            summaries.append(os.path.join(root, "summary.json"))
    if len(summaries) != 1:
        return "no summary: " + done.stderr.strip()[:200], wall
    with open(summaries[0]) as handle:
        return json.load(handle), wall


def describe(summary):
    """The cells read from one run's summary.json."""
    if isinstance(summary, str):
        return summary, "", "", ""
    status = summary.get("status", "")
    end = "converged" if summary.get("converged") else ("**not converged**" if status == "ok" else f"**{status}**")
    flow = summary.get("flow", {})
    regions = flow.get("regions", {}) or {}
    conductivities = []
    for name, region in sorted(regions.items()):
        value = region.get("normalised_conductivity")
        if value is not None:
            conductivities.append(f"{name} {value:.6g}")
    fractures = summary.get("fractures", {}) or {}
    aperture = fractures.get("max_aperture")
    aperture_cell = f"{aperture * 1e3:.4g} mm" if isinstance(aperture, (int, float)) else ""
    measures = []
    for name, point in sorted((summary.get("measure") or {}).items()):
        measures.append(f"{name} {point['displacement'][1] * 1e3:.5g} mm")
    return f"{end}, {summary.get('iterations')}", "; ".join(conductivities), aperture_cell, "; ".join(measures)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("program")
    parser.add_argument("out_dir")
    parser.add_argument("scenarios", nargs="+")
    parser.add_argument("--ramps", default="1,3,5")
    parser.add_argument("--set", dest="sets", action="append", default=[])
    parser.add_argument("--tag", default="")
    parser.add_argument("--timeout", type=float, default=900.0)
    args = parser.parse_args()
    ramps = [int(r) for r in args.ramps.split(",")]
    print("| scenario | " + " | ".join(f"ramp_passes = {r}" for r in ramps) + " |")
    print("| --- | " + " | ".join("---" for _ in ramps) + " |")
    for scenario in args.scenarios:
        stem = os.path.splitext(os.path.basename(scenario))[0] + (f"-{args.tag}" if args.tag else "")
        cells = []
        for ramp in ramps:
            out = os.path.join(args.out_dir, f"{stem}-ramp{ramp}")
            summary, wall = run_case(args.program, scenario, out, ramp, args.sets, args.timeout)
            end, conductivity, aperture, measures = describe(summary)
            read = "; ".join(x for x in (conductivity, f"open {aperture}" if aperture not in ("", "0 mm") else "", measures) if x)
            cells.append(f"{end} ({wall:.1f} s){': ' + read if read else ''}")
        print(f"| {stem} | " + " | ".join(cells) + " |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
