#!/usr/bin/env python3
"""Print a coupled run's passes as a markdown table: each measure point's vertical displacement
(measure.csv) beside history.csv's load factor, largest opening, joint crossings switched,
contacts changed and the two changes. Passes 1-8 and every fifth after.

Usage: scripts/pass_table.py RUN_FOLDER
"""
import csv
import sys


def main(folder):
    uy = {}
    names = []
    with open(f"{folder}/measure.csv") as handle:
        for row in csv.DictReader(handle):
            uy.setdefault(int(row["iteration"]), {})[row["name"]] = float(row["uy"]) * 1e3
            if row["name"] not in names:
                names.append(row["name"])
    print("| pass | load | " + " | ".join(f"{n} uy (mm)" for n in names) +
          " | largest opening (mm) | crossings switched | contacts changed | head change | displacement change |")
    print("| ---: " * (len(names) + 7) + "|")
    with open(f"{folder}/history.csv") as handle:
        for row in csv.DictReader(handle):
            k = int(row["iteration"])
            if k > 8 and k % 5 != 0:
                continue
            cells = [str(k), f"{float(row['load_factor']):.2f}"] + [f"{uy[k][n]:.2f}" for n in names]
            cells += [f"{float(row['largest_opening']) * 1e3:.3f}", row["joint_crossings_switched"],
                      row["contact_state_changes"], f"{float(row['head_change']):.2g}",
                      f"{float(row['displacement_change']):.2g}"]
            print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
