#!/bin/bash
# Cost of the point output with MPI (doc/mpi.md): the 2D dam break at
# 960 x 400 squares (409 600 points), 20 steps, the points written every 5
# steps (5 files), one thread per process; for each format and number of
# processes the output stage's time (rank 0's stage_seconds.output, which
# includes waiting for the other processes), the wall time and the largest
# resident memory of each process.
# Usage: mpi_output_cost.sh <fsgmpm> <source dir> [processes...]
set -u
exe=$1
src=$2
shift 2
nps=("$@")
[ ${#nps[@]} = 0 ] && nps=(1 2)
source "$src/tests/mpi/mpi_launch.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf "| format | processes | output (s) | wall (s) | max RSS per process (MB) |\n|---|---|---|---|---|\n"
for format in vtu hdf5; do
  for np in "${nps[@]}"; do
    dir="$work/${format}_$np"
    args=("$src/prm/default_dam_break.prm" --set "Grid/Subdivisions=960, 400"
      --set "Simulation/Maximum number of steps=20" --set "Simulation/Number of threads=1"
      --set "Output/Output interval=0" --set "Output/Output every n steps=5"
      --set "Output/Format=$format" --set "Output/Quiet=true" --set "Output/Directory=$dir")
    if [ "$np" = 1 ]; then
      /usr/bin/time -f "RSS %M" -o "$work/rss" "$exe" "${args[@]}" > "$work/log" 2>&1
    else
      mpi_launch "$np" /usr/bin/time -f "RSS %M" -a -o "$work/rss" "$exe" "${args[@]}" > "$work/log" 2>&1
    fi || { echo "run failed ($format, $np)"; tail -5 "$work/log"; exit 1; }
    rss=$(grep -o "RSS [0-9]*" "$work/rss" | awk '{printf "%s%.0f", (NR>1?", ":""), $2/1024}')
    rm -f "$work/rss"
    /usr/bin/python3 - "$dir/summary.json" "$format" "$np" "$rss" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print("| %s | %s | %.2f | %.2f | %s |" % (sys.argv[2], sys.argv[3],
      s["stage_seconds"]["output"], s["wall_seconds"], sys.argv[4]))
PY
  done
done
