#!/usr/bin/env bash
# `make demo`: runs the main shipped scenario and says where its results are.
set -euo pipefail
build_dir=${1:-build}
scenario=${DEMO_SCENARIO:-scenarios/paper/six_block_lr_rl.toml}
out=out/demo
"$build_dir/bin/hydrodda" run "$scenario" -o "$out" --overwrite
echo
echo "Results of $scenario are in $out/:"
describe() {
  case "$1" in
    summary.json) echo "converged or not, block displacements and stresses, boundary flows" ;;
    history.csv) echo "the coupling loop's convergence norms and flows, one row per iteration (a transient run: per time step)" ;;
    probes.csv) echo "each [[flow.probe]]'s head and pressure, one row per time step" ;;
    measure.csv) echo "measured points, one row per coupling iteration (or DDA step)" ;;
    fractures.csv) echo "each fracture's aperture, open length and flow, one row per iteration" ;;
    checkpoint.bin) echo "the state a stopped run resumes from (run --resume)" ;;
    scenario.toml) echo "the scenario as run" ;;
    *.pvd) echo "open in ParaView" ;;
    figures) echo "$(ls "$out/figures" | tr '\n' ' ')" ;;
    *) echo "" ;;
  esac
}
for entry in $(ls "$out"); do
  case "$entry" in *.vtu) continue ;; esac
  printf '  %-16s %s\n' "$entry" "$(describe "$entry")"
done
