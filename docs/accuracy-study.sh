#!/usr/bin/env bash
# Accuracy against time of docs/performance.md: the Cornell box solved with the uniform
# kernel at several patch sizes and with the hierarchical kernel at several link
# tolerances and smallest sizes; per run the wall clock and peak memory of the whole
# `ugo solve` (mesh, assembly or refinement, solve, writing), and the largest probe error
# against a converged backward Monte Carlo reference. Run from the repository root after
# `make build` (UGO=path/to/ugo for another binary). Writes docs/img/accuracy-vs-time.csv
# and, with python3, docs/img/accuracy-vs-time.svg (docs/accuracy-plot.py). About 4 minutes
# on two cores (add 0.025 m with FINE=1: about 1.5 minutes more).
#
# REFERENCE=1 re-measures the reference first (`ugo trace`, 10^6 paths per probe on a copy
# of the case without cameras, about a minute) and prints it; the figures below are the
# committed reference, as `ugo solve` prints its probe table, cd/m² ± one standard error.
set -euo pipefail
ugo=${UGO:-./target/release/ugo}
out=out/accuracy-study
csv=docs/img/accuracy-vs-time.csv
mkdir -p "$out" docs/img

case=cases/cornell-box.toml
ref_floor=11.9236     # ± 0.0352, floor, centre
ref_back=151.9439     # ± 0.0709, back wall, centre
ref_ceiling=46.7667   # ± 0.0848, ceiling, front

if [[ "${REFERENCE:-0}" == 1 ]]; then
  # The case without its cameras: only the probes are traced.
  awk '/^\[\[camera\]\]/{skip=1; next} /^\[/{skip=0} !skip' "$case" > "$out/cornell-probes.toml"
  $ugo trace "$out/cornell-probes.toml" --probe-samples 1000000 -o "$out"
fi

# One run: label, method, patch size (the roots for the hierarchy), tolerance, smallest
# leaf, then solve's options (its discretization flags). Appends a
# row to the CSV: the probes' luminances, the largest |error| in %, time, memory, load.
run() {
  local method=$1 h=$2 tol=$3 smallest=$4
  shift 4
  local log="$out/$method-$h-$tol-$smallest.log"
  local load
  load=$(cut -d' ' -f1 /proc/loadavg)
  /usr/bin/time -f "wall %e s %M KB" $ugo solve "$case" "$@" -o "$out/x.h5" > "$log" 2>&1
  awk -v m="$method" -v h="$h" -v t="$tol" -v s="$smallest" -v load="$load" \
      -v rf="$ref_floor" -v rb="$ref_back" -v rc="$ref_ceiling" '
    function abs(x) { return x < 0 ? -x : x }
    /patches N/ { n = $3 }
    /floor, centre/ { f = $3 } /back wall, centre/ { b = $4 } /ceiling, front/ { c = $3 }
    /^wall / { secs = $2; kb = $4 }
    END {
      ef = 100 * (f / rf - 1); eb = 100 * (b / rb - 1); ec = 100 * (c / rc - 1)
      e = abs(ef); if (abs(eb) > e) e = abs(eb); if (abs(ec) > e) e = abs(ec)
      printf "%s,%s,%s,%s,%d,%s,%.1f,%s,%s,%s,%.3f,%.3f,%.3f,%.3f,%s\n", m, h, t, s, n, secs, kb / 1024, f, b, c, ef, eb, ec, e, load
    }' "$log" | tee -a "$csv"
}

echo "method,patch_size_m,link_tolerance,smallest_m,leaves,wall_s,peak_MiB,floor_cd_m2,back_cd_m2,ceiling_cd_m2,floor_err_pct,back_err_pct,ceiling_err_pct,max_abs_err_pct,load1" > "$csv"
sizes="0.1 0.07 0.05 0.035"
[[ "${FINE:-0}" == 1 ]] && sizes="$sizes 0.025"
for h in $sizes; do
  run uniform "$h" - - --kernel uniform --patch-size "$h"
done
for ts in 1e-2:0.05 3e-3:0.05 1e-3:0.05 3e-3:0.035 1e-3:0.035 1e-3:0.025; do
  tol=${ts%:*} smallest=${ts#*:}
  run hierarchical 0.25 "$tol" "$smallest" --kernel hierarchical --root-size 0.25 --link-tolerance "$tol" \
    --patch-size "$smallest"
done
uptime
if command -v python3 > /dev/null; then
  python3 docs/accuracy-plot.py "$csv" docs/img/accuracy-vs-time.svg
fi
