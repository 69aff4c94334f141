#!/bin/bash
# Cost of checkpoints with MPI (doc/checkpoint_and_hdf5.md): the 2D dam break
# at 960 x 400 squares (409 600 points), 10 steps with a checkpoint after every
# step, one thread per process; then a restart from the last checkpoint for one
# more step. For each number of processes: the time spent writing checkpoints
# (summary.json's checkpoint_seconds, rank 0's, which includes waiting for the
# other processes), the checkpoint's size, the largest resident memory of each
# process in the run and in the restart, and the restart's wall time (setup and
# reading included).
# Usage: mpi_checkpoint_cost.sh <fsgmpm> <source dir> [processes...]
set -u
exe=$1
src=$2
shift 2
nps=("$@")
[ ${#nps[@]} = 0 ] && nps=(1 2)
source "$src/tests/mpi/mpi_launch.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# launch <np> <rss file> <arguments...>
launch() {
  local np=$1 rss=$2
  shift 2
  if [ "$np" = 1 ]; then
    /usr/bin/time -f "RSS %M" -o "$rss" "$exe" "$@"
  else
    mpi_launch "$np" /usr/bin/time -f "RSS %M" -a -o "$rss" "$exe" "$@"
  fi
}
megabytes() { grep -o "RSS [0-9]*" "$1" | awk '{printf "%s%.0f", (NR>1?", ":""), $2/1024}'; }
printf "| processes | writing 10 checkpoints (s) | checkpoint (MB) | max RSS per process, run (MB) | restart wall (s) | max RSS per process, restart (MB) |\n|---|---|---|---|---|---|\n"
for np in "${nps[@]}"; do
  dir="$work/run_$np"
  args=("$src/prm/default_dam_break.prm" --set "Grid/Subdivisions=960, 400"
    --set "Simulation/Number of threads=1" --set "Output/Output interval=0"
    --set "Output/Write particles=false" --set "Output/Checkpoint interval=1e-9"
    --set "Output/Quiet=true" --set "Output/Directory=$dir")
  launch "$np" "$work/rss_run" "${args[@]}" --set "Simulation/Maximum number of steps=10" \
    > "$work/log" 2>&1 || { echo "run failed ($np)"; tail -5 "$work/log"; exit 1; }
  cp "$dir/summary.json" "$work/summary_run.json"
  start=$(date +%s%N)
  launch "$np" "$work/rss_restart" "${args[@]}" --set "Simulation/Maximum number of steps=11" \
    --restart "$dir" > "$work/log" 2>&1 || { echo "restart failed ($np)"; tail -5 "$work/log"; exit 1; }
  restart_ms=$((($(date +%s%N) - start) / 1000000))
  size=$(ls -l "$dir"/checkpoints/*.h5 | tail -1 | awk '{printf "%.1f", $5/1e6}')
  /usr/bin/python3 - "$work/summary_run.json" "$np" "$size" "$(megabytes "$work/rss_run")" \
    "$restart_ms" "$(megabytes "$work/rss_restart")" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print("| %s | %.2f | %s | %s | %.2f | %s |" % (sys.argv[2], s["checkpoint_seconds"],
      sys.argv[3], sys.argv[4], float(sys.argv[5]) / 1000, sys.argv[6]))
PY
  rm -f "$work"/rss_*
done
