#!/bin/bash
# run_coupled_transient_seal.sh [BUILD_DIR] [seal_scenario.py options...]
# Times a coupled transient run of the in-situ seal that `seal_scenario.py --in-situ` writes,
# made transient by coupled_transient_seal.py (its reservoir's head raised by 10 m over 50 s,
# 100 s in steps of 5 s), with the real program on one thread, and prints its size, the time
# steps and fixed-stress iterations it took, each phase's seconds from summary.json (wall
# clock), the CPU seconds of each time step and iteration (the program's /proc/PID/stat sampled
# five times a second against the steps its log shows done), and the run's peak memory
# (/usr/bin/time -v). The 10^4-block seal:
#   benchmarks/run_coupled_transient_seal.sh build --columns 100 --beds 99 --mesh-size 0.07 --tilt 1 --joint-sets
set -euo pipefail
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
BUILD=${1:-build}
shift || true
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

python3 "$HERE/seal_scenario.py" "$@" --in-situ > "$WORK/seal.toml"
python3 "$HERE/coupled_transient_seal.py" "$WORK/seal.toml" > "$WORK/transient.toml"
start=$(date +%s.%N)
/usr/bin/time -v -o "$WORK/time" "$BUILD/bin/hydrodda" -v run --threads 1 "$WORK/transient.toml" -o "$WORK/out" 2> "$WORK/log" &
timer=$!
sleep 0.5
program=$(pgrep -P "$timer" || true)
# The program's CPU seconds (user + system, clock ticks) each second, beside the steps logged so
# far: each step's own CPU time, whatever else the host runs.
while [ -n "$program" ] && read -r -a stat 2>/dev/null < "/proc/$program/stat"; do
  echo "$(( stat[13] + stat[14] )) $(grep -c '^step ' "$WORK/log" || true)" >> "$WORK/cpu"
  sleep 0.2
done
wait "$timer" || { cat "$WORK/log" >&2; exit 1; }
end=$(date +%s.%N)
grep -E "^(geometry|mesh):|blocks|triangles" "$WORK/log" | head -n 6 || true
python3 - "$WORK/out" "$start" "$end" "$WORK/time" "$WORK/cpu" "$(getconf CLK_TCK)" <<'PY'
import csv, json, re, statistics, sys
folder = sys.argv[1]
summary = json.load(open(f"{folder}/summary.json"))
rows = list(csv.DictReader(open(f"{folder}/history.csv")))[1:]  # the row of t = 0 first
wall = float(sys.argv[3]) - float(sys.argv[2])
usage = open(sys.argv[4]).read()
cpu = sum(float(re.search(rf"{kind} time \(seconds\): ([0-9.]+)", usage).group(1)) for kind in ("User", "System"))
peak_kb = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", usage).group(1))
t = summary["timings"]
steps = len(rows)
iterations = sum(int(r["iterations"]) for r in rows)
cuts = sum(int(r["cuts"]) for r in rows)
per_step = sorted(int(r["iterations"]) for r in rows)
print(f"time steps {steps} to t = {summary['time']} s, converged {summary['converged']}, cuts {cuts}, "
      f"fixed-stress iterations {iterations} (each step {per_step[0]}-{per_step[-1]}), "
      f"last mass balance {float(rows[-1]['balance']):.1e}")
print("| phase | seconds | a time step | an iteration |")
print("| --- | ---: | ---: | ---: |")
for phase in ("mesh", "porosity", "flow", "forces", "mechanics", "transient"):
    if phase not in t:
        continue
    share = "" if phase == "mesh" else f"{t[phase] / steps:.3f} | {t[phase] / iterations:.3f}"
    print(f"| {phase} | {t[phase]:.2f} | {share} |" if share else f"| {phase} | {t[phase]:.2f} | | |")
print(f"| whole run (wall) | {wall:.1f} | | |")
print(f"| whole run (CPU, user + system) | {cpu:.1f} | | |")
# Each step's CPU seconds: the program's CPU when the log first shows it done, less the last
# step's (step 1's includes building the model, so it is left out).
ticks = float(sys.argv[6])
done_at = {}
for line in open(sys.argv[5]):
    cpu_ticks, logged = map(int, line.split())
    done_at.setdefault(logged, cpu_ticks / ticks)
per_step = {k: done_at[k] - done_at[k - 1] for k in done_at if k >= 2 and k - 1 in done_at}
if per_step:
    its = {int(r["step"]): int(r["iterations"]) for r in rows}
    seconds = list(per_step.values())
    per_iteration = [per_step[k] / its[k] for k in per_step]
    print(f"CPU a time step (steps {min(per_step)}-{max(per_step)}, sampled five times a second): median "
          f"{statistics.median(seconds):.2f} s ({min(seconds):.2f}-{max(seconds):.2f}); an iteration: median "
          f"{statistics.median(per_iteration):.2f} s ({min(per_iteration):.2f}-{max(per_iteration):.2f})")
    print("each step: " + ", ".join(f"{k}: {per_step[k]:.1f} s / {its[k]}" for k in sorted(per_step)))
print(f"peak memory {peak_kb / 1024:.0f} MiB")
PY
