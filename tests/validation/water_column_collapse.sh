#!/bin/bash
# Full-size validation of the water-column collapse (label validation; about
# 1.5 hours on 2 cores): n^2 = 2 and 1, real water (K_f = 2.13 GPa) and the
# weakly compressible K_f = 2.5 MPa, at 20 and 40 cells across w0. Prints,
# per run, the errors against Martin & Moyce (n^2 = 2; no time shift), wall
# time, steps and particle-updates per second, and draws the comparison
# (doc/figures/water_column_collapse_n2_validation.png in the work folder).
# Usage: water_column_collapse.sh <fsgmpm> <source dir> [work dir]
set -eu
exe=$1
src=$2
work=${3:-$(mktemp -d)}
mkdir -p "$work"
cd "$work"
runs=()
for n in 2 1; do
  for cells in 20 40; do
    if [ $n = 2 ]; then sub=$((6 * cells)),$((5 * cells / 2)); else sub=$((6 * cells)),$((3 * cells / 2)); fi
    for K in 2.13e9 2.5e6; do
      dir=n${n}_K${K}_${cells}
      "$exe" "$src/prm/water_column_collapse_n$n.prm" --set "Grid/Subdivisions=$sub" \
        --set "Bodies/Body 0/Newtonian fluid/Bulk modulus=$K" \
        --set "Output/Directory=$dir" --set "Output/Write particles=false" \
        --set "Output/Quiet=true"
      echo "$dir: $(grep -E '"(steps|wall_seconds|particle_updates_per_second)"' $dir/summary.json | tr -d '\n ')"
      [ $n = 2 ] && runs+=("$dir:K_f=$K, $cells cells")
    done
  done
done
/usr/bin/python3 "$src/doc/scripts/plot_dam_break.py" water_column_collapse_n2_validation.png \
  --reference "$src/tests/reference/martin_moyce_1952_n2.csv" "${runs[@]}"
