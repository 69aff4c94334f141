#!/bin/bash
# MPI runs reproduce the serial run (issue 15 §1): each scene runs STEPS
# steps on one process and with mpirun on 2 and 3 processes (3 oversubscribes
# a 2-core machine), monitors every step, particles written every 50 steps;
# compare_monitors.py compares every column of monitors.csv with the serial
# one (worst difference relative to the column's largest magnitude) against
# RTOL. The motion is meant to be the serial arithmetic bit for bit; only
# the energy sums over processes may differ in the last bits; the last
# particle file must hold the same bytes as the serial one (compare_vtu.py,
# every field). Also checked:
# summary.json reports the processes and the same particle count, and the
# particle files are written once per output step.
#
# Usage: mpi_reproduces_serial.sh <fsgmpm> <source dir> [scene ...]
set -u
exe=$1
src=$2
shift 2
scenes=("$@")
if [ ${#scenes[@]} = 0 ]; then
  scenes=(default_dam_break water_column_collapse_n1 granular_column_collapse
    ../tests/mpi/dam_break_3d)
fi
STEPS=${MPI_STEPS:-200}
RTOL=${MPI_RTOL:-1e-12}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
for scene in "${scenes[@]}"; do
  for np in 1 2 3; do
    dir="$work/$(basename "$scene")_$np"
    args=("$src/prm/$scene.prm"
      --set "Simulation/Maximum number of steps=$STEPS"
      --set "Simulation/Number of threads=1"
      --set "Output/Directory=$dir" --set "Output/Output interval=0"
      --set "Output/Output every n steps=50"
      --set "Output/Monitor every n steps=1" --set "Output/Quiet=true")
    start=$(date +%s%N)
    if [ $np = 1 ]; then
      "$exe" "${args[@]}" > "$work/log" 2>&1
    else
      mpirun --oversubscribe -np $np "$exe" "${args[@]}" > "$work/log" 2>&1
    fi
    status=$?
    wall=$((($(date +%s%N) - start) / 1000000))
    if [ $status != 0 ] || [ ! -s "$dir/monitors.csv" ]; then
      echo "$scene ($np processes): run failed (status $status)"
      tail -5 "$work/log"
      failed=1
      continue
    fi
    echo "$scene ($np processes, ${wall} ms):"
    grep -q "\"mpi_ranks\": $np," "$dir/summary.json" \
      || { echo "  summary.json does not report $np processes"; failed=1; }
    [ $np = 1 ] && continue
    for key in particles lost_particles steps; do
      a=$(grep -o "\"$key\": [0-9]*" "$work/$(basename "$scene")_1/summary.json")
      b=$(grep -o "\"$key\": [0-9]*" "$dir/summary.json")
      [ "$a" = "$b" ] || { echo "  summary.json $key: serial <$a>, MPI <$b>"; failed=1; }
    done
    a=$(ls "$work/$(basename "$scene")_1" | grep -c '\.vtu$')
    b=$(ls "$dir" | grep -c '\.vtu$')
    [ "$a" = "$b" ] && [ "$a" -gt 0 ] \
      || { echo "  particle files: serial $a, MPI $b"; failed=1; }
    # The points' state and vorticity, bit for bit (as written, float32).
    last=$(ls "$dir" | grep '\.vtu$' | sort | tail -1)
    /usr/bin/python3 "$src/tests/mpi/compare_vtu.py" \
      "$work/$(basename "$scene")_1/$last" "$dir/$last" \
      || failed=1
    /usr/bin/python3 "$src/tests/golden/compare_monitors.py" \
      "$work/$(basename "$scene")_1/monitors.csv" "$dir/monitors.csv" --rtol "$RTOL" \
      || failed=1
  done
done
# Repartitioning (nearly) every step moves the points between processes
# all the time; the results must not change.
scene=${scenes[0]}
dir="$work/repartitioned"
mpirun --oversubscribe -np 3 "$exe" "$src/prm/$scene.prm" \
  --set "Simulation/Maximum number of steps=$STEPS" \
  --set "Simulation/Number of threads=1" \
  --set "Simulation/Repartition imbalance=1" \
  --set "Output/Directory=$dir" --set "Output/Output interval=0" \
  --set "Output/Output every n steps=50" \
  --set "Output/Monitor every n steps=1" --set "Output/Quiet=true" \
  > "$work/log" 2>&1
status=$?
repartitions=$(grep -o '"mpi_repartitions": [0-9]*' "$dir/summary.json" 2>/dev/null | grep -o '[0-9]*$')
echo "$scene (3 processes, repartitioned ${repartitions:-?} times):"
if [ $status != 0 ] || [ "${repartitions:-0}" -lt 10 ]; then
  echo "  run failed (status $status) or did not repartition"
  tail -5 "$work/log"
  failed=1
else
  /usr/bin/python3 "$src/tests/golden/compare_monitors.py" \
    "$work/$(basename "$scene")_1/monitors.csv" "$dir/monitors.csv" \
    --rtol "$RTOL" || failed=1
  last=$(ls "$dir" | grep '\.vtu$' | sort | tail -1)
  /usr/bin/python3 "$src/tests/mpi/compare_vtu.py" \
    "$work/$(basename "$scene")_1/$last" "$dir/$last" || failed=1
fi

# What is not distributed yet is refused with a clear error on every
# process and a non-zero exit, not a hang.
timeout 120 mpirun --oversubscribe -np 2 "$exe" "$src/prm/geotube_A6.45.prm" \
  --set "Output/Directory=$work/refused" > "$work/log" 2>&1
status=$?
if [ $status = 0 ] || [ $status = 124 ] \
  || ! grep -q "does not run on more than one MPI process yet" "$work/log"; then
  echo "geotube on 2 processes: expected a clear refusal, got status $status:"
  tail -5 "$work/log"
  failed=1
else
  echo "geotube on 2 processes: refused (status $status)"
fi
if [ $failed = 0 ]; then echo "mpi: all passed"; else echo "mpi: FAILED"; fi
exit $failed
