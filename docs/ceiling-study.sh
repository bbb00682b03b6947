#!/usr/bin/env bash
# The office ceiling study of docs/hierarchy.md ("The two Monte Carlo estimators agree on
# the ceiling"): a copy of cases/office.toml whose probes are 3,072 points on the ceiling,
# the centres of a 0.125 m grid (four inside every 0.25 m patch), read by backward Monte
# Carlo, by forward Monte Carlo binned into the 0.25 m patches, and by the uniform kernel
# on those patches; docs/ceiling-study.py compares them bin by bin, grouped by distance
# from the walls. Run from the repository root after `make build` (UGO=path/to/ugo for
# another binary); writes into out/ceiling-study/. About 8 minutes on two cores.
set -euo pipefail
ugo=${UGO:-./target/release/ugo}
out=out/ceiling-study
mkdir -p "$out"
cp cases/office-downlight.ies "$out/"
python3 - "$out/ceiling.toml" <<'PY'
import sys
text = open("cases/office.toml").read()
head = text[: text.index("[[light_scene]]")]
probes = [f'[[probe]]\nname = "f {i} {j}"\nposition = [{0.0625 + 0.125 * i}, 2.8, {0.0625 + 0.125 * j}]\n'
          "normal = [0, -1, 0]\n" for i in range(64) for j in range(48)]
open(sys.argv[1], "w").write(head + "\n".join(probes))
PY
measure() { # name, command...: its output to name.log, its timing (not its warnings) shown
  local name=$1
  shift
  /usr/bin/time -f "  $name: wall %e s, peak memory %M KiB" "$@" > "$out/$name.log" 2> "$out/$name.err"
  grep -v "^ugo: \(warning\|progress\)" "$out/$name.err"
}
measure backward $ugo trace "$out/ceiling.toml" --probe-samples 3000 --seed 31 -o "$out"
measure forward $ugo trace "$out/ceiling.toml" --forward --patch-size 0.25 --photons 50000000 \
  --seed 3 -o "$out/forward.h5"
measure uniform $ugo solve "$out/ceiling.toml" --kernel uniform --patch-size 0.25 -o "$out/uniform.h5"
/usr/bin/python3 docs/ceiling-study.py "$out"
