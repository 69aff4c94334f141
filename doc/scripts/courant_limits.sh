#!/bin/bash
# Largest stable Courant number of each shipped scene (doc/stability.md).
# Each run is the scene as shipped with Simulation/Courant number = C, for
# its first 0.5 s of simulated time (or End time if shorter), at most
# 30 000 steps; stable = exit status 0 (a run the stability guards stop
# exits 3). C = 1 (the parameter's maximum) is tried first; if it fails,
# bisection between the shipped value and 1 to 0.05.
# Usage: courant_limits.sh <fsgmpm> <source dir> [filter] [extra --set ...]
# Prints one line per scene: name, shipped C, largest stable C, first
# unstable C (or "-"), the dt at the shipped C.
set -u
exe=$1
src=$2
filter=${3:-}
shift 3 2> /dev/null
extra=("$@")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

stable() { # stable <prm> <C>: 0 if the run completes
  local prm=$1 c=$2 end
  end=$(sed -n 's/^ *set End time *= *\([^ #]*\).*/\1/p' "$prm" | head -1)
  end=$(python3 -c "print(min(float('${end:-0.6}'), 0.5))")
  "$exe" "$prm" --set "Output/Directory=$work/out" --set "Output/Quiet=true" \
    --set "Output/Write particles=false" \
    --set "Simulation/Courant number=$c" --set "Simulation/End time=$end" \
    --set "Simulation/Maximum number of steps=30000" "${extra[@]}" \
    > "$work/log" 2>&1
}

printf "%-28s %8s %10s %10s %12s\n" scene shipped stable_C unstable_C dt_shipped
for prm in "$src"/prm/*.prm; do
  name=$(basename "$prm" .prm)
  if [ -n "$filter" ] && [[ "$name" != *$filter* ]]; then continue; fi
  shipped=$(sed -n 's/^ *set Courant number *= *\([^ #]*\).*/\1/p' "$prm" | head -1)
  shipped=${shipped:-0.5}
  stable "$prm" "$shipped"
  ok_shipped=$?
  dt=$(sed -n 's/.*"dt_min": \([0-9.e+-]*\).*/\1/p' "$work/out/summary.json")
  if [ $ok_shipped -ne 0 ]; then
    printf "%-28s %8s %10s %10s %12s\n" "$name" "$shipped" "<$shipped" "$shipped" "$dt"
    continue
  fi
  if stable "$prm" 1; then
    printf "%-28s %8s %10s %10s %12s\n" "$name" "$shipped" ">=1" "-" "$dt"
    continue
  fi
  lo=$shipped
  hi=1
  while python3 -c "import sys; sys.exit(0 if $hi - $lo > 0.05 + 1e-9 else 1)"; do
    mid=$(python3 -c "print(round(($lo + $hi) / 2 / 0.05) * 0.05)")
    if python3 -c "import sys; sys.exit(0 if $mid <= $lo + 1e-9 or $mid >= $hi - 1e-9 else 1)"; then
      mid=$(python3 -c "print(round($lo + 0.05, 2))")
    fi
    if stable "$prm" "$mid"; then lo=$mid; else hi=$mid; fi
  done
  printf "%-28s %8s %10s %10s %12s\n" "$name" "$shipped" "$lo" "$hi" "$dt"
done
