#!/usr/bin/env bash
# Re-measures the figures of docs/experiments.md: norms against reflectance, predicted and
# observed Neumann iterations, the time of iteration against direct solution as N grows.
# Run from the repository root after `make build`; writes into out/experiments/.
set -euo pipefail
ugo=./target/release/ugo
out=out/experiments
mkdir -p "$out"

echo "## norms against reflectance (Cornell box geometry, every surface of reflectance r, patch 0.05 m)"
for r in 0.3 0.5 0.7 0.9 0.95; do
  sed -E "s/^reflectance = .*/reflectance = $r/" cases/cornell-box.toml > "$out/cornell-r$r.toml"
  echo "### r = $r"
  $ugo norms "$out/cornell-r$r.toml" --patch-size 0.05 --tolerance 1e-8 -o "$out/cornell-r$r-norms.h5" | grep -E "‖K‖|ρ\(K\)|cond|Neumann iterations|n = "
done

echo "## closed box (furnace), reflectance r"
for r in 0.5 0.8 0.95; do
  sed -E "s/^reflectance = .*/reflectance = $r/" cases/furnace-box.toml > "$out/furnace-r$r.toml"
  echo "### r = $r"
  $ugo norms "$out/furnace-r$r.toml" --patch-size 0.1 --tolerance 1e-8 -o "$out/furnace-r$r-norms.h5" | grep -E "ρ\(K\)|cond|Neumann iterations"
done

echo "## iteration against direct solution as N grows (Cornell box)"
for h in 0.1 0.07 0.05 0.04 0.03; do
  echo "### patch size $h"
  $ugo compare cases/cornell-box.toml --patch-size "$h" --methods neumann,gmres,bicgstab,direct \
    -o "$out/cornell-$h-compare.h5" --plot "$out/cornell-$h-compare.png" | grep -E "patches N|assembly|^  (neumann|gmres|bicgstab|direct)"
done

echo "## factored angular bases against the full angular solution (glossy Cornell box, K = 64)"
for n in 10 50 200; do
  sed -E "s/^exponent = .*/exponent = $n/" cases/glossy-cornell.toml > "$out/glossy-n$n.toml"
  echo "### Phong floor exponent $n"
  $ugo compare "$out/glossy-n$n.toml" --methods gmres --tolerance 1e-10 \
    --bases full,sh:0,sh:1,sh:2,sh:3,sh:4,sh:5,sh:6,sh:7,svd:1,svd:4,svd:9,svd:16,svd:25,svd:36,svd:49,svd:64 \
    --plot "$out/glossy-n$n-bases.png" | tail -n +2
done
