#!/bin/bash
# Every scene shipped in prm/ runs as shipped (doc/stability.md). The
# files are found by globbing, so a new scene is covered automatically.
#
# Default run (mode "short"): each scene runs its first 0.2 s of simulated
# time or 2000 steps (3D scenes: 500; geocontainers half of that),
# whichever comes first, with its own
# Courant number and every other parameter as shipped; only the output
# directory and the VTU output (kept, but every 500 steps) are changed. Validation run (mode
# "full"): each scene runs to its own End time. Long run (mode "long"):
# each scene runs on to three times its End time (doc/stability.md, "Past
# the shipped window"), without VTU output; hours for the geotubes.
# Asserts for each scene: exit status 0, termination end_time, max_steps (short mode), dr_converged
# or at_rest in summary.json, finite values in every monitors.csv row
# (no nan/inf), no lost points (lost_particles 0; in the long mode a scene
# whose tank is open at the top may lose the points that leave through it,
# booked as outflow: their number is printed), no leftover temporary
# file. Prints the wall time of each run and the stability guard's largest
# reading (energy created over its energy scale).
# Usage: shipped_scenes.sh <fsgmpm> <source dir> short|full|long [filter]
set -u
exe=$1
src=$2
mode=${3:-short}
filter=${4:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0

for prm in "$src"/prm/*.prm; do
  name=$(basename "$prm" .prm)
  if [ -n "$filter" ] && [[ "$name" != *$filter* ]]; then continue; fi
  out="$work/$name"
  args=("$prm" --set "Output/Directory=$out" --set "Output/Quiet=true")
  end=$(sed -n 's/^ *set End time *= *\([^ #]*\).*/\1/p' "$prm" | head -1)
  end=${end:-0.6}
  open_top=false
  if grep -Eq '^ *set Boundary conditions *=.*3: *free' "$prm"; then
    open_top=true
  fi
  if [ "$mode" = long ]; then
    args+=(--set "Simulation/End time=$(python3 -c "print(3 * float('$end'))")"
           --set "Output/Output interval=0"
           --set "Output/Write particles=false")
  fi
  if [ "$mode" = short ]; then
    short=$(python3 -c "print(min(float('$end'), 0.2))")
    # 3D scenes 500 steps: the 3D geocontainer at 2 cm took 144 s for 2000.
    # The geocontainers (1 cm membrane elements, 10 ms per step in 2D)
    # half of that: 1000 and 250 steps (the validation run takes them to
    # their end).
    max_steps=2000
    if [[ "$name" == *_3d ]]; then max_steps=500; fi
    if [[ "$name" == geocontainer* ]]; then max_steps=$((max_steps / 2)); fi
    args+=(--set "Simulation/End time=$short"
           --set "Simulation/Maximum number of steps=$max_steps"
           --set "Output/Output interval=0"
           --set "Output/Output every n steps=500")
  fi
  start=$(date +%s.%N)
  "$exe" "${args[@]}" > "$work/$name.log" 2>&1
  status=$?
  wall=$(python3 -c "print(f'{$(date +%s.%N) - $start:.1f}')")
  why=""
  if [ $status -ne 0 ]; then
    why="exit status $status: $(tail -n 2 "$work/$name.log" | tr '\n' ' ')"
  elif ! grep -Eq '"termination": "(end_time|max_steps|dr_converged|at_rest)"' "$out/summary.json"; then
    why="termination: $(grep termination "$out/summary.json")"
  elif ! grep -q '"lost_particles": 0' "$out/summary.json" \
       && ! { [ "$mode" = long ] && $open_top; }; then
    why="lost points: $(grep lost_particles "$out/summary.json")"
  elif tail -n +2 "$out/monitors.csv" | grep -qi 'nan\|inf'; then
    why="non-finite monitor values"
  elif [ "$(wc -l < "$out/monitors.csv")" -lt 2 ]; then
    why="no monitor rows"
  elif ls "$out"/*.tmp.* > /dev/null 2>&1; then
    why="temporary files left in the output directory"
  fi
  steps=$(sed -n 's/.*"steps": \([0-9]*\).*/\1/p' "$out/summary.json" 2>/dev/null)
  simt=$(sed -n 's/.*"simulated_time": \([0-9.e+-]*\).*/\1/p' "$out/summary.json" 2>/dev/null)
  lost=$(sed -n 's/.*"lost_particles": \([0-9]*\).*/\1/p' "$out/summary.json" 2>/dev/null | head -n 1)
  termination=$(sed -n 's/.*"termination": "\([a-z_]*\)".*/\1/p' "$out/summary.json" 2>/dev/null)
  created=$(sed -n 's/.*"energy_created_largest_share": \([0-9.e+-]*\).*/\1/p' "$out/summary.json" 2>/dev/null)
  if [ -z "$why" ]; then
    echo "ok   $name: ${termination}, ${steps} steps, ${simt} s simulated, ${wall} s wall, largest energy created ${created} of the guard's scale, ${lost} points lost (outflow)"
    passed=$((passed + 1))
  else
    echo "FAIL $name ($wall s wall): $why"
    failed=$((failed + 1))
  fi
done

echo "shipped scenes ($mode): $passed passed, $failed failed"
[ $failed -eq 0 ] && [ $passed -gt 0 ]
