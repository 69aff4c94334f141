#!/bin/bash
# Geotube mesh study (doc/membrane_validation.md): the three fillings at the
# given cell sizes with the weakly compressible fill (p_max/K_f <= 1e-3),
# relaxed for End time seconds; then the table rows (monitors averaged over
# the last quarter of the run) and the shape figures.
# Usage: doc/scripts/geotube_study.sh <build dir> <output dir> <end time> <cell sizes (m)...>
set -euo pipefail
build=$1 out=$2 end=$3
shift 3
here=$(cd "$(dirname "$0")/../.." && pwd)
rows=()
for area in 5.56 3.36 6.45; do
  K=2.7e7
  [ "$area" = 6.45 ] && K=5.6e7
  for h in "$@"; do
    dir=$out/A${area}_h${h}
    "$build/fsgmpm" "$here/prm/geotube_A${area}.prm" \
      --set "Grid/Cell size=$h" \
      --set "Bodies/Body 0/Newtonian fluid/Bulk modulus=$K" \
      --set "Simulation/End time=$end" \
      --set "Output/Directory=$dir" --set "Output/Write particles=false" \
      --set "Output/Output interval=$end" > "$dir.log" 2>&1 || true
    tail -n 1 "$dir.log"
    rows+=("$area:$(python3 -c "print(round($h*100))"):$dir")
  done
done
python3 "$here/doc/scripts/geotube_table.py" "$build/tests/geotube_shape" \
  "$(python3 -c "print(0.75*$end)")" "${rows[@]}"
