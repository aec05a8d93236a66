#!/bin/bash
# wall_vs_ntdda.sh [BUILD_DIR] [NTDDA_BENCH] [ROUNDS]
# The whole program against ntdda's whole run on the 1,601-block brick wall of
# shared/peers/brickwall.py (40 rows × 40 columns, 20 static steps): each round runs
# `hydrodda run -q wall.toml -o DIR` at default settings (no closed contact pulls: the tension
# cutoff), the same with `tension_cutoff = false` (the band of tension Shi's open–close rule,
# and ntdda's, allow a closed contact) and then `ntdda_bench w.txt`, each a fresh process timed
# by /usr/bin/time; prints every round, then the medians of wall and CPU (user + system) time
# and the ratios, and the load average before and after.
#   benchmarks/wall_vs_ntdda.sh build /tmp/ntdda-build/ntdda_bench 7
set -euo pipefail
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
BUILD=$(cd "${1:-build}" && pwd)
NTDDA=${2:-/tmp/ntdda-build/ntdda_bench}
ROUNDS=${3:-7}
# The peers folder (brickwall.py, ntdda) beside the project's checkout, or HYDRODDA_PEERS.
PEERS=${HYDRODDA_PEERS:-$HERE/../../shared/peers}
if [ ! -f "$PEERS/brickwall.py" ]; then
  echo "wall_vs_ntdda.sh: no brickwall.py in $PEERS; set HYDRODDA_PEERS to the peers folder" >&2
  exit 2
fi
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"
python3 "$PEERS/brickwall.py" 40 40 --format toml > wall.toml
python3 "$PEERS/brickwall.py" 40 40 --format ntdda > w.txt
sed 's/^\[mechanics\]$/[mechanics]\ntension_cutoff = false/' wall.toml > wall_band.toml
grep -q '^tension_cutoff = false$' wall_band.toml
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for round in $(seq "$ROUNDS"); do
  rm -rf wall wall_band
  /usr/bin/time -f "%e %U %S" -o hydrodda.time "$BUILD/bin/hydrodda" run -q wall.toml -o wall
  /usr/bin/time -f "%e %U %S" -o band.time "$BUILD/bin/hydrodda" run -q wall_band.toml -o wall_band
  /usr/bin/time -f "%e %U %S" -o ntdda.time "$NTDDA" w.txt > /dev/null 2>&1
  echo "round $round: hydrodda $(cat hydrodda.time), with the band $(cat band.time), ntdda $(cat ntdda.time)  (wall, user, system s)"
  cat hydrodda.time >> hydrodda.all
  cat band.time >> band.all
  cat ntdda.time >> ntdda.all
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - hydrodda.all band.all ntdda.all <<'PY'
import statistics, sys
def medians(path):
    rows = [list(map(float, line.split())) for line in open(path)]
    return statistics.median(r[0] for r in rows), statistics.median(r[1] + r[2] for r in rows)
theirs = medians(sys.argv[3])
for name, path in (("hydrodda", sys.argv[1]), ("hydrodda, band", sys.argv[2])):
    ours = medians(path)
    print(f"median wall: {name} {ours[0]:.3f} s, ntdda {theirs[0]:.3f} s, ntdda / ours {theirs[0] / ours[0]:.1f}x")
    print(f"median CPU:  {name} {ours[1]:.3f} s, ntdda {theirs[1]:.3f} s, ntdda / ours {theirs[1] / ours[1]:.1f}x")
PY
