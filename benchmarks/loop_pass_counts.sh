#!/usr/bin/env bash
# Passes the staggered loop takes on every shipped coupled scenario, for each acceleration and
# load ramp: one sweep per scenario over coupling.acceleration × coupling.ramp_passes, then a
# Markdown table (a count with * ran out of passes, not converged).
# Usage: benchmarks/loop_pass_counts.sh [hydrodda binary] [output folder]
set -euo pipefail
program=${1:-build/bin/hydrodda}
out=${2:-out/loop-pass-counts}
accelerations=${ACCELERATIONS:-none,aitken}
ramps=${RAMPS:-1,3}
mkdir -p "$out"
scenarios=(scenarios/paper/*.toml scenarios/verification/coupled_*.toml scenarios/examples/*.toml)
for file in "${scenarios[@]}"; do
  name=$(basename "$file" .toml)
  "$program" -q sweep "$file" --set "coupling.acceleration=$accelerations" --set "coupling.ramp_passes=$ramps" \
      --jobs 2 --overwrite -o "$out/$name" > /dev/null
done
python3 - "$out" "${scenarios[@]}" <<'PY'
import csv, os, sys
out, files = sys.argv[1], sys.argv[2:]
rows, header = [], None
for f in files:
    name = os.path.basename(f)[:-5]
    with open(os.path.join(out, name, "sweep.csv")) as table:
        cases = list(csv.DictReader(table))
    if header is None:
        header = [f"{c['coupling.acceleration']}, ramp {c['coupling.ramp_passes']}" for c in cases]
        print("| scenario | " + " | ".join(header) + " |")
        print("| --- |" + " ---: |" * len(header))
    cells = [c["iterations"] + ("" if c["converged"] == "true" else "*") for c in cases]
    print(f"| `{name}` | " + " | ".join(cells) + " |")
PY
