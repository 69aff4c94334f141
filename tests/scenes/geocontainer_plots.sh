#!/bin/bash
# The geocontainer doc figures' scripts run on real output (issue 12):
# a 4 cm polygon drop for 0.05 s with output every 0.01 s, then
# doc/scripts/plot_geocontainer.py and plot_geocontainer_snapshots.py must
# each write a non-empty PNG. Uses Debian's python3-matplotlib.
set -euo pipefail
exe=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$exe" "$src/prm/geocontainer_polygon.prm" \
  --set "Grid/Cell size=0.04" --set "Simulation/End time=0.05" \
  --set "Output/Output interval=0.01" --set "Output/Directory=$work/run" \
  --set "Output/Quiet=true" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
/usr/bin/python3 "$src/doc/scripts/plot_geocontainer.py" "$work/v.png" \
  "polygon 4 cm=$work/run/monitors.csv"
/usr/bin/python3 "$src/doc/scripts/plot_geocontainer_snapshots.py" \
  "$work/s.png" "$work/run" 0.01,0.05
for f in v.png s.png; do
  [ -s "$work/$f" ] || { echo "missing $f"; exit 1; }
done
echo "geocontainer plots: ok"
