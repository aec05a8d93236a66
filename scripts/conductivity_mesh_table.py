#!/usr/bin/env python3
"""K_eff/K_m of each paper scenario at four fracture element sizes, with both permeability laws.

For each scenario the reference aperture a is its geometry.initial_aperture, or, where the joints
start closed, the widest opening its own run reaches (history.csv's largest_opening, last pass,
rounded up to 0.1 mm). The fracture element size (mesh.fracture_size) is then a, 2a, 5a and 10a
(or the multiples of a that --factors lists), for "cubic" and "kozeny-carman", each case a
`hydrodda sweep` case; the table gives the first flow region's normalised_conductivity and the
change between the two finest sizes.

    python3 scripts/conductivity_mesh_table.py [--hydrodda build/bin/hydrodda] [--out out/mesh-table]
        [--laws cubic,kozeny-carman] [--factors 1,2,5,10] [--set KEY=VALUE ...]
        [scenarios/paper/six_block_lr_rl.toml ...]

--set passes a key to every case (e.g. --laws cubic --set mesh.refine_tips=true); --factors 0.5,1,2,5,10
adds a size finer than the aperture.

Prints a Markdown table (the one in docs/coupling.md).
"""
import argparse
import csv
import glob
import math
import os
import subprocess
import sys
import tomllib

FACTORS = "1,2,5,10"
LAWS = ("cubic", "kozeny-carman")


def run(cmd, check=True):
    subprocess.run(cmd, check=check, stdout=subprocess.DEVNULL)


def reference_aperture(hydrodda, scenario, data, out):
    a = data.get("geometry", {}).get("initial_aperture", 0.0)
    if a > 0:
        return a, "initial"
    folder = os.path.join(out, "reference")
    run([hydrodda, "-q", "run", scenario, "-o", folder, "--overwrite"])
    with open(os.path.join(folder, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    opening = float(rows[-1]["largest_opening"])
    return math.ceil(opening / 1e-4) * 1e-4, "opening"


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scenarios", nargs="*")
    p.add_argument("--hydrodda", default="build/bin/hydrodda")
    p.add_argument("--out", default="out/mesh-table")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--laws", default=",".join(LAWS), help="the permeability laws, comma-separated")
    p.add_argument("--factors", default=FACTORS, help="the element sizes as multiples of a, comma-separated")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="a key for every case")
    args = p.parse_args()
    laws = args.laws.split(",")
    factors = sorted(float(k) for k in args.factors.split(","))
    if len(factors) < 2:
        sys.exit("--factors needs two sizes or more")
    scenarios = args.scenarios or sorted(glob.glob("scenarios/paper/*.toml"))
    names = [("" if k == 1 else f"{k:g}") + "a" for k in factors]
    print("| scenario | a (mm) | law | " + " | ".join(names) + f" | {names[0]} vs {names[1]} |")
    print("| --- | ---: | --- | " + "---: | " * len(names) + "---: |")
    for scenario in scenarios:
        name = os.path.splitext(os.path.basename(scenario))[0]
        with open(scenario, "rb") as f:
            data = tomllib.load(f)
        region = data["flow"]["region"][0]["name"]
        out = os.path.join(args.out, name)
        a, source = reference_aperture(args.hydrodda, scenario, data, out)
        sizes = ",".join(f"{k * a:.6g}" for k in factors)
        folder = os.path.join(out, "sweep")
        column = f"flow.regions.{region}.normalised_conductivity"
        run([args.hydrodda, "-q", "sweep", scenario, "--set", f"mesh.fracture_size={sizes}",
             "--set", "flow.permeability_law=" + ",".join(laws), "--set", "output.figures=[]",
             *[arg for kv in args.set for arg in ("--set", kv)],
             "--column", column, "--jobs", str(args.jobs), "-o", folder, "--overwrite"], check=False)
        # A sweep with a failed case exits 1 but still writes sweep.csv: the case is marked.
        values = {}
        with open(os.path.join(folder, "sweep.csv")) as f:
            for row in csv.DictReader(f):
                size = float(row["mesh.fracture_size"])
                value = row[column]
                values[(row["flow.permeability_law"], size)] = (float(value) if value else float("nan"),
                                                               row["converged"] == "true")
        for law in laws:
            cells, numbers = [], []
            for k in factors:
                v, converged = values[(law, float(f"{k * a:.6g}"))]
                numbers.append(v)
                cells.append(f"{v:.4g}" + ("" if converged else "*"))
            change = f"{100 * (numbers[0] - numbers[1]) / numbers[1]:+.1f}%"
            label = f"{1e3 * a:.3g}" + (" (opening)" if source == "opening" else "")
            print(f"| `{name}` | {label} | {law} | " + " | ".join(cells) + f" | {change} |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
