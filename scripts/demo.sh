#!/usr/bin/env bash
# `make demo`: runs the main shipped scenario and says where its results are.
set -euo pipefail
build_dir=${1:-build}
scenario=${DEMO_SCENARIO:-scenarios/paper/six_block_lr_rl.toml}
out=out/demo
"$build_dir/bin/hydrodda" run "$scenario" -o "$out" --overwrite
echo
echo "Results of $scenario are in $out/:"
echo "  summary.json       what converged, block displacements and stresses, boundary flows"
echo "  history.csv        the coupling loop's residuals, one row per iteration"
echo "  *.pvd              open in ParaView (fluid mesh and blocks over the iterations)"
if [ -d "$out/figures" ]; then
  echo "  figures/           $(ls "$out/figures" | tr '\n' ' ')"
fi
