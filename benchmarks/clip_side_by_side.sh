#!/bin/bash
# clip_side_by_side.sh BUILD_DIR PEER_DIR [ROUNDS]
# The porosity mapping beside the peer clipping benchmark (shared/peers/clip) on the same
# triangles and blocks: the peer's clipbench builds a structured mesh of T triangles under B
# rotated bricks; bench_porosity's BM_PeerBricks/T/B builds the same mesh and bricks from the
# same seed and maps them. Both run on one thread, in alternation, ROUNDS times (default 5);
# the medians of their times and their ratio are printed, with the porosity each found (the
# same inputs give the same porosity to round-off).
#   needs: g++ and libboost-dev (the peer's oracle), build/bin/bench_porosity
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 BUILD_DIR PEER_DIR [ROUNDS]   (PEER_DIR: the folder holding clipbench.cpp)" >&2
  exit 2
fi
BUILD=$1
PEER=$2
ROUNDS=${3:-5}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# The peer at its own best flags (run.sh's first build), ours as the project builds it (-O3).
g++ -std=c++17 -O3 -march=native -o "$WORK/clipbench" "$PEER/clipbench.cpp"

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "| triangles | blocks | peer (s) | ours (s) | ours / peer time | peer porosity | our porosity |"
echo "| ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
for size in "100000 1000" "1000000 10000" "4000000 10000"; do
  read -r t b <<< "$size"
  : > "$WORK/peer" ; : > "$WORK/ours"
  for ((round = 0; round < ROUNDS; ++round)); do
    # The peer: best of 5 runs and at least 1 s (its own rule), without its Boost pass.
    "$WORK/clipbench" "$t" "$b" sub=0 > "$WORK/peer.out"
    awk '/^SH/ { print $2 }' "$WORK/peer.out" >> "$WORK/peer"
    peer_porosity=$(awk '/^porosity/ { print $2 }' "$WORK/peer.out")
    triangles=$(awk '/^T / { print $2 }' "$WORK/peer.out")
    blocks=$(awk '/^B / { print $2 }' "$WORK/peer.out")
    # Ours: the least of 5 repetitions, as the peer keeps its best run.
    OMP_NUM_THREADS=1 "$BUILD/bin/bench_porosity" --benchmark_filter="BM_PeerBricks/$t/$b\$" \
      --benchmark_repetitions=5 --benchmark_min_time=0.2 --benchmark_format=json > "$WORK/ours.json" 2> /dev/null
    python3 - "$WORK/ours.json" >> "$WORK/ours" <<'EOF'
import json, sys
runs = [r for r in json.load(open(sys.argv[1]))["benchmarks"] if r.get("run_type") == "iteration"]
scale = {"ms": 1e-3, "us": 1e-6, "ns": 1e-9, "s": 1.0}[runs[0]["time_unit"]]
print(min(r["real_time"] for r in runs) * scale, runs[0]["porosity"], int(runs[0]["elements"]), int(runs[0]["blocks"]))
EOF
  done
  peer_time=$(median < "$WORK/peer")
  ours_time=$(cut -d' ' -f1 "$WORK/ours" | median)
  read -r _ our_porosity our_triangles our_blocks < <(tail -1 "$WORK/ours")
  if [[ "$our_triangles" != "$triangles" || "$our_blocks" != "$blocks" ]]; then
    echo "different inputs: the peer made $triangles triangles and $blocks blocks, ours $our_triangles and $our_blocks" >&2
    exit 1
  fi
  ratio=$(awk -v a="$ours_time" -v b="$peer_time" 'BEGIN { printf "%.2f", a / b }')
  printf "| %s | %s | %.4f | %.4f | %s | %s | %.6f |\n" "$triangles" "$blocks" "$peer_time" "$ours_time" "$ratio" \
    "$peer_porosity" "$our_porosity"
done
