#!/usr/bin/env bash
# Fuzzes the scenario reader with libFuzzer for a bounded time.
#   scripts/fuzz.sh BUILD_DIR [SECONDS]
# Builds the reader with clang (coverage, AddressSanitizer, UndefinedBehaviorSanitizer) in
# BUILD_DIR, seeds the corpus with every shipped and test scenario, and fails on any finding.
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
build_dir=$1
seconds=${2:-60}
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -g -O1"
cmake -S "$source_dir" -B "$build_dir" -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DHYDRODDA_FUZZ=ON -DHYDRODDA_BUILD_TESTS=OFF -DHYDRODDA_BUILD_BENCHMARKS=OFF > "$build_dir.log" 2>&1 \
  || { cat "$build_dir.log"; exit 1; }
cmake --build "$build_dir" --target fuzz_scenario_reader -j "$(nproc)" >> "$build_dir.log" 2>&1 \
  || { tail -50 "$build_dir.log"; exit 1; }
corpus="$build_dir/corpus"
mkdir -p "$corpus"
find "$source_dir/scenarios" "$source_dir/tests" -name '*.toml' -exec cp {} "$corpus/" \;
cd "$build_dir"
./tests/fuzz/fuzz_scenario_reader -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
  -print_final_stats=1 "$corpus"
