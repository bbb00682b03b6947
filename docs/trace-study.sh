#!/usr/bin/env bash
# The discretization study of docs/experiments.md: the error of the linear-system solution
# against a converged backward Monte Carlo reference as patch_size and K are refined, on the
# Cornell and glossy Cornell boxes, with unknowns, memory and time. Run from the repository
# root after `make build` (UGO=path/to/ugo to use another binary, SPP=n for the reference's
# paths per pixel); writes into out/trace-study/. About 35 minutes on two cores.
set -euo pipefail
ugo=${UGO:-./target/release/ugo}
out=out/trace-study
spp=${SPP:-16384}
mkdir -p "$out"

source docs/study-case.sh
measure() { /usr/bin/time -f "  wall %e s, peak memory %M KiB" "$@"; }
solve_and_agree() { # case, name, extra solve options...
  local case=$1 name=$2
  shift 2
  measure $ugo solve "$out/$case.toml" "$@" -o "$out/$name.h5" 2>&1 |
    grep -E "patches N|cells K|unknowns|non-zeros|assembly|  solve|^  wall"
  for shading in flat smooth gather; do
    echo "#### $shading shading"
    measure $ugo agree "$out/$name.h5" "$out/$case-study-trace.exr" --camera study --shading $shading --gather-rays 2048 2>&1 |
      grep -E "rms z|relative difference|L2,|noise|^  wall"
  done
}

for case in cornell-box glossy-cornell; do
  study_case $case
  echo "## reference: $case, $spp paths per pixel"
  measure $ugo trace "$out/$case.toml" --camera study --spp "$spp" -o "$out" 2>&1 | grep -E "time|relative|^  wall"
done

echo "## Cornell box, K = 1, patch size h"
for h in 0.1 0.07 0.05 0.035 0.025; do
  echo "### h = $h"
  solve_and_agree cornell-box "cornell-box-$h" --patch-size "$h"
done

echo "## glossy Cornell box, patch size 0.055, K cells"
for k in 16 64 144 256; do
  echo "### K = $k"
  solve_and_agree glossy-cornell "glossy-cornell-k$k" --patch-size 0.055 --directions "$k"
done

echo "## glossy Cornell box, K = 64, patch size h"
for h in 0.1 0.075 0.04; do
  echo "### h = $h"
  solve_and_agree glossy-cornell "glossy-cornell-$h" --patch-size "$h" --directions 64
done
