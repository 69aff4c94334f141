#!/bin/bash
# Strong and weak scaling of the MPI runs (doc/mpi.md), printed as markdown
# tables from each run's summary.json. 1 thread per process; 4 processes
# oversubscribe a 2-core machine (labelled). ctest mpi_scaling (label
# performance) runs it with STEPS=20.
#
# Usage: mpi_scaling.sh <fsgmpm> <source dir> [STEPS]
set -eu
exe=$1
src=$2
steps=${3:-200}
source "$src/tests/mpi/mpi_launch.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cores=$(nproc)

report() { # name np: one table row from the run's summary.json
  /usr/bin/python3 - "$work/$1/summary.json" "$2" "$cores" "$1" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
np, cores = int(sys.argv[2]), int(sys.argv[3])
st = s["stage_seconds"]
print("| %s | %d%s | %d | %.2f | %.2f | %.3f | %.2f | %.3f |" % (
    sys.argv[4], np, " (oversubscribed)" if np > cores else "", s["particles"],
    s["wall_seconds"], s["particle_updates_per_second"] / 1e6,
    st.get("mpi_points", 0) / max(s["wall_seconds"], 1e-12),
    s["mpi_imbalance"], s["mpi_halo_fraction"]))
PY
}

run() { # name np prm --set arguments...: run on np processes, then report
  local name=$1 np=$2 prm=$3
  shift 3
  local args=("$src/$prm"
    --set "Simulation/Maximum number of steps=$steps"
    --set "Simulation/Number of threads=1"
    --set "Output/Directory=$work/$name" --set "Output/Write particles=false"
    --set "Output/Quiet=true" "$@")
  if [ "$np" = 1 ]; then "$exe" "${args[@]}" > "$work/log" 2>&1
  else mpi_launch "$np" "$exe" "${args[@]}" > "$work/log" 2>&1; fi \
    || { echo "run $name failed:"; tail -5 "$work/log"; exit 1; }
  report "$name" "$np"
}

header="| case | processes | points | wall (s) | M updates/s | mpi_points share | imbalance | halo fraction |
|---|---|---|---|---|---|---|---|"
echo "Strong scaling: default dam break at 2.85 mm (240 x 100 squares), 16 points per cell, $steps steps"
echo "$header"
for np in 1 2 4; do
  run "strong_$np" $np prm/default_dam_break.prm \
    --set "Grid/Subdivisions=240, 100" --set "Bodies/Body 0/Particles per cell=16"
done
echo
echo "Weak scaling: the same cells and points per process (tank and column N times wider), $steps steps"
echo "$header"
for np in 1 2 4; do
  run "weak_$np" $np prm/default_dam_break.prm \
    --set "Grid/Subdivisions=$((120 * np)), 50" \
    --set "Grid/Upper corner=$(python3 -c "print(0.684 * $np)"), 0.285" \
    --set "Bodies/Body 0/Box upper corner=$(python3 -c "print(0.114 * $np)"), 0.228" \
    --set "Bodies/Body 0/Particles per cell=16"
done
echo
echo "3D halo: tests/mpi/dam_break_3d.prm at 48 x 20 x 4 hexahedra (6 tetrahedra each), 8 points per cell, $steps steps"
echo "$header"
for np in 1 2 4; do
  run "3d_$np" $np tests/mpi/dam_break_3d.prm --set "Grid/Subdivisions=48, 20, 4"
done
