#!/bin/bash
# Collective MPI calls per step (each one costs a latency that grows with
# log P: doc/mpi.md). Builds doc/scripts/mpi_collective_count.c
# with mpicc, preloads it into fsgmpm on 2 processes, runs the default dam
# break for 50 and for 150 steps without output, and prints the calls per
# step (the difference over 100 steps: setup and the end of the run drop
# out).
# Usage: mpi_collectives.sh <fsgmpm> <source dir> [most all-reduces per step]
# With the third argument, exits 1 if a step makes more all-reduces than
# that, or any (blocking or non-blocking) barrier or other collective.
set -u
exe=$1
src=$2
most=${3:-}
source "$src/tests/mpi/mpi_launch.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mpicc -O2 -shared -fPIC "$src/doc/scripts/mpi_collective_count.c" \
  -o "$work/libcount.so" || exit 1
count() {
  mpi_launch 2 -x LD_PRELOAD="$work/libcount.so" "$exe" \
    "$src/prm/default_dam_break.prm" \
    --set "Simulation/Maximum number of steps=$1" \
    --set "Simulation/Number of threads=1" \
    --set "Output/Output interval=0" --set "Output/Write particles=false" \
    --set "Output/Directory=$work/out$1" 2>&1 >/dev/null |
    grep "^COLLECTIVES" | tr ' =' '\n\n'
}
a=($(count 50)) b=($(count 150))
if [ ${#a[@]} != 9 ] || [ ${#b[@]} != 9 ]; then
  echo "FAIL: no counts (did fsgmpm run on 2 processes?)"
  exit 1
fi
status=0
echo "collective MPI calls per step, default dam break, 2 processes"
for k in 2 4 6 8; do
  name=${a[$((k - 1))]}
  per_step=$(awk -v x="${a[$k]}" -v y="${b[$k]}" 'BEGIN {printf "%.2f", (y - x) / 100}')
  echo "$name $per_step"
  if [ -n "$most" ]; then
    limit=0
    [ "$name" = allreduce ] && limit=$most
    if awk -v v="$per_step" -v l="$limit" 'BEGIN {exit !(v > l)}'; then
      echo "FAIL: $per_step $name per step, at most $limit expected"
      status=1
    fi
  fi
done
exit $status
