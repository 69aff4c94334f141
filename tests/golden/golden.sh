#!/bin/bash
# Golden-output regression of every scene shipped in prm/: a short run
# (Maximum number of steps = STEPS, monitors every step, no particle
# output) on 1 and on 2
# threads, each compared with the stored tests/golden/<scene>.csv by
# compare_monitors.py (worst relative difference per column, relative to
# the column's largest magnitude; tolerance 1e-9: results are meant to be
# identical for any number of threads, and the stored files were written by
# this build on this machine, so only round-off of a different compiler or
# library may show).
#
# Usage: golden.sh <fsgmpm> <source dir> [--regenerate] [scene ...]
#   --regenerate   rewrite tests/golden/<scene>.csv from a 1-thread run
#                  (needed after any intended change of results, e.g. the
#                  time-step bound; review the diff before committing)
#   scene          only these scenes (names without .prm)
set -u
exe=$1
src=$2
shift 2
regenerate=0
scenes=()
for a in "$@"; do
  if [ "$a" = --regenerate ]; then regenerate=1; else scenes+=("$a"); fi
done
if [ ${#scenes[@]} = 0 ]; then
  for f in "$src"/prm/*.prm; do scenes+=("$(basename "$f" .prm)"); done
fi
STEPS=${GOLDEN_STEPS:-100}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
for scene in "${scenes[@]}"; do
  golden="$src/tests/golden/$scene.csv"
  for threads in 1 2; do
    [ $regenerate = 1 ] && [ $threads = 2 ] && continue
    dir="$work/${scene}_$threads"
    start=$(date +%s%N)
    "$exe" "$src/prm/$scene.prm" \
      --set "Simulation/Maximum number of steps=$STEPS" \
      --set "Simulation/Number of threads=$threads" \
      --set "Output/Directory=$dir" --set "Output/Write particles=false" \
      --set "Output/Monitor every n steps=1" --set "Output/Quiet=true" \
      > "$work/log" 2>&1
    status=$?
    wall=$((($(date +%s%N) - start) / 1000000))
    if [ $status != 0 ] || [ ! -s "$dir/monitors.csv" ]; then
      echo "$scene ($threads threads): run failed (status $status)"
      tail -5 "$work/log"
      failed=1
      continue
    fi
    if [ $regenerate = 1 ]; then
      cp "$dir/monitors.csv" "$golden"
      echo "$scene: wrote $golden ($(($(wc -l < "$golden") - 1)) rows, ${wall} ms)"
      continue
    fi
    echo "$scene ($threads threads, ${wall} ms):"
    if [ ! -f "$golden" ]; then
      echo "  no golden file $golden (run with --regenerate)"
      failed=1
      continue
    fi
    /usr/bin/python3 "$src/tests/golden/compare_monitors.py" "$golden" \
      "$dir/monitors.csv" || failed=1
  done
done
if [ $failed = 0 ]; then echo "golden: all passed"; else echo "golden: FAILED"; fi
exit $failed
