#!/usr/bin/env bash
# The image study of docs/experiments.md ("The image study with the hierarchy"): the study
# camera's 64×64 image of the Cornell and glossy Cornell boxes, solved with the uniform and
# the hierarchical kernel and rendered flat, smooth and with a final gather, each against a
# converged backward Monte Carlo reference; per run the wall clock, CPU time and peak memory
# of the solve and of the render, and the error beyond the reference's noise (`ugo agree`).
#
# The peer is measured in the same run: a short backward trace of the same image (SPP_PEER
# paths per pixel) gives the Monte Carlo cost of any accuracy, `t(e) = t_peer · (e_peer/e)²`,
# on this machine at this load. Run from the repository root after `make build`
# (UGO=path/to/ugo for another binary). Reuses out/trace-study's references when they exist
# (docs/trace-study.sh), else traces them (SPP paths per pixel, 16384 by default: about 4
# and 3 minutes on two idle cores). Writes docs/img/image-study.csv; about 6 minutes more.
set -euo pipefail
ugo=${UGO:-./target/release/ugo}
out=out/trace-study
spp=${SPP:-16384}
peer=${SPP_PEER:-1024}
csv=docs/img/image-study.csv
mkdir -p "$out" docs/img

source docs/study-case.sh

# The error beyond the reference's noise of `ugo agree`'s log.
error_of() { awk '/error beyond noise/ {print $4}' "$1"; }

# The peer: a backward trace of `peer` paths per pixel and its time. Its error is its noise
# `‖σ‖/‖m‖` (an unbiased estimate), which `ugo agree` prints as the reference noise when the
# peer stands as the reference of a solution (`peer_noise`).
trace_peer() {
  local case=$1
  mkdir -p "$out/peer"
  /usr/bin/time -o "$out/peer/$case.time" -f "%e,%U,%M" \
    $ugo trace "$out/$case.toml" --camera study --spp "$peer" --seed 7 -o "$out/peer" > "$out/peer/$case.log" 2>&1
}
peer_noise() { # case, a solution of it
  $ugo agree "$2" "$out/peer/$1-study-trace.exr" --camera study | awk '/reference noise/ {print $3}'
}

# One row: tag, case, gather rays ('' for flat and smooth only), then solve's options.
run() {
  local tag=$1 case=$2 rays=$3
  shift 3
  local load
  load=$(cut -d' ' -f1 /proc/loadavg)
  /usr/bin/time -o "$out/$tag.time" -f "%e,%U,%M" \
    $ugo solve "$out/$case.toml" "$@" -o "$out/$tag.h5" > "$out/$tag.log" 2>&1
  local leaves
  leaves=$(grep -oE "→ [0-9]+ leaves" "$out/$tag.log" | grep -oE "[0-9]+" || grep -E "patches N " "$out/$tag.log" | grep -oE "[0-9]+$")
  local shadings=(flat smooth)
  [[ -n "$rays" ]] && shadings+=(gather)
  for shading in "${shadings[@]}"; do
    /usr/bin/time -o "$out/$tag-$shading.time" -f "%e,%U" \
      $ugo agree "$out/$tag.h5" "$out/$case-study-trace.exr" --camera study --shading "$shading" \
      --gather-rays "${rays:-2048}" > "$out/$tag-$shading.agree" 2>&1
    local used=0
    [[ $shading == gather ]] && used=$rays
    echo "$case,\"$*\",$leaves,$(cat "$out/$tag.time"),$shading,$used,$(cat "$out/$tag-$shading.time"),$(error_of "$out/$tag-$shading.agree"),$load" >> "$csv"
  done
}

echo "case,solve options,leaves,solve wall s,solve CPU s,solve peak KiB,shading,gather rays,render wall s,render CPU s,error,load" > "$csv"
for case in cornell-box glossy-cornell; do
  study_case $case
  if [[ ! -f "$out/$case-study-trace.exr" ]]; then
    $ugo trace "$out/$case.toml" --camera study --spp "$spp" -o "$out"
  fi
  trace_peer $case
done

h="--kernel hierarchical --root-size 0.25"
run cornell-h-1e-2 cornell-box 2048 $h --patch-size 0.05
run cornell-h-1e-2-4096 cornell-box 4096 $h --patch-size 0.05
run cornell-h-3e-3 cornell-box 4096 $h --patch-size 0.05 --link-tolerance 3e-3
run cornell-h-0.035 cornell-box 4096 $h --patch-size 0.035
run cornell-e-0.05 cornell-box 4096 --kernel uniform --patch-size 0.05
run cornell-e-0.035 cornell-box 4096 --kernel uniform --patch-size 0.035
run glossy-h-64 glossy-cornell 4096 $h --patch-size 0.05
run glossy-h-144 glossy-cornell 4096 $h --patch-size 0.05 --directions 144
run glossy-h-256 glossy-cornell 4096 $h --patch-size 0.05 --directions 256
run glossy-e-64 glossy-cornell 4096 --kernel uniform --patch-size 0.055

# The Monte Carlo peer of each case: paths per pixel, wall s, CPU s, peak KiB, noise.
for pair in cornell-box:cornell-h-1e-2 glossy-cornell:glossy-h-64; do
  case=${pair%%:*}
  echo "peer,$case,$peer,$(cat "$out/peer/$case.time"),$(peer_noise "$case" "$out/${pair##*:}.h5")" >> "$csv"
done
