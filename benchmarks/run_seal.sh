#!/bin/bash
# run_seal.sh [BUILD_DIR] [seal_scenario.py options...]
# Times a coupled run of the fractured seal that seal_scenario.py writes (by default about
# 1,000 blocks over about 2 x 10^5 triangles, 3 passes of 20 DDA steps) with the real program,
# and prints its size, each pass's seconds of porosity, flow (with whether it factored afresh or
# ran CG on the kept factor) and mechanics, the seconds of each phase from summary.json, and
# the run's peak memory (/usr/bin/time -v). The scale benchmark's seal (docs/performance.md), 10,100 blocks over about 10^6
# triangles, 10 passes:
#   benchmarks/run_seal.sh build --columns 100 --beds 99 --mesh-size 0.07 --tilt 1 --joint-sets --passes 10
set -euo pipefail
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
BUILD=${1:-build}
shift || true
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

python3 "$HERE/seal_scenario.py" "$@" > "$WORK/seal.toml"
start=$(date +%s.%N)
/usr/bin/time -v -o "$WORK/time" "$BUILD/bin/hydrodda" -v run "$WORK/seal.toml" -o "$WORK/out" 2> "$WORK/log" ||
  { cat "$WORK/log" >&2; exit 1; }
end=$(date +%s.%N)
grep -E "^(geometry|mesh):|blocks|triangles" "$WORK/log" | head -n 6 || true
grep -oE "iteration [0-9]+: head change.*mechanics [0-9.]+ s" "$WORK/log" || true
python3 - "$WORK/out/summary.json" "$start" "$end" "$WORK/time" <<'EOF'
import json, re, sys
summary = json.load(open(sys.argv[1]))
wall = float(sys.argv[3]) - float(sys.argv[2])
usage = open(sys.argv[4]).read()
cpu = sum(float(re.search(rf"{kind} time \(seconds\): ([0-9.]+)", usage).group(1)) for kind in ("User", "System"))
peak_kb = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", usage).group(1))
t = summary["timings"]
passes = summary["iterations"]
print(f"passes {passes}, converged {summary['converged']}, mass balance {summary['flow']['balance']:.1e}")
print("| phase | seconds | seconds per pass |")
print("| --- | ---: | ---: |")
for phase in ("mesh", "porosity", "flow", "forces", "mechanics"):
    per_pass = "" if phase == "mesh" else f"{t[phase] / passes:.3f}"
    print(f"| {phase} | {t[phase]:.3f} | {per_pass} |")
print(f"| whole run (wall) | {wall:.2f} | |")
print(f"| whole run (CPU, user + system) | {cpu:.2f} | |")
print(f"peak memory {peak_kb / 1024:.0f} MiB")
EOF
