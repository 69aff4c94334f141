#!/bin/bash
# The geocontainer doc figures' scripts run on real output:
# a 4 cm polygon drop for 0.05 s with output every 0.01 s, then
# doc/scripts/plot_geocontainer.py and plot_geocontainer_snapshots.py must
# each write a non-empty PNG; doc/scripts/water_compaction.py must find
# the water filling its squares exactly at t = 0 (1.000: the body filler's
# regular points) and within 1% at 0.05 s (measured 1.000, before the
# compaction of doc/geocontainer_validation.md section 6 sets in);
# doc/scripts/geocontainer_audit.py must read the bag sinking at 0.30-0.42
# m/s at 0.05 s (measured 0.358) with the water's centre of mass not yet
# moved (|rise| < 0.2 mm, measured 0.00: the tip has barely entered);
# doc/scripts/pressure_pattern.py must find the projected pressure near
# hydrostatic far from the bag (mean within 0.2 kPa, measured at most 0.11
# as the entry's pressure wave passes; standard deviation below 0.1 kPa,
# measured 0.06) and smoother than the points' own at 0.05 s (measured
# 0.06 against 0.18 kPa); doc/scripts/entry_cavity.py must find no air
# cavity yet (below 0.001 m^2, measured 0). Uses
# Debian's python3-matplotlib.
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
/usr/bin/python3 "$src/doc/scripts/water_compaction.py" "$work/run" \
  > "$work/compaction"
cat "$work/compaction"
awk 'NR == 2 && ($3 < 0.9995 || $3 > 1.0005) { bad = 1 }
     NR > 2 && ($3 < 0.99 || $3 > 1.01) { bad = 1 }
     END { exit bad || NR != 7 }' "$work/compaction" \
  || { echo "water_compaction.py: unexpected values"; exit 1; }
/usr/bin/python3 "$src/doc/scripts/geocontainer_audit.py" "$work/run" 0.05 \
  > "$work/audit"
cat "$work/audit"
awk 'NR == 2 && $2 > 0.30 && $2 < 0.42 && $6 > -0.2 && $6 < 0.2 { ok = 1 }
     END { exit !ok || NR != 2 }' "$work/audit" \
  || { echo "geocontainer_audit.py: unexpected values"; exit 1; }
/usr/bin/python3 "$src/doc/scripts/pressure_pattern.py" "$work/run" \
  > "$work/pattern"
cat "$work/pattern"
awk 'NR > 1 { rows++; if ($6 > 0.1 || $5 < -0.2 || $5 > 0.2) bad = 1
             last_own = $4; last_projected = $6 }
     END { exit bad || rows != 6 || last_projected >= last_own }' \
  "$work/pattern" \
  || { echo "pressure_pattern.py: unexpected values"; exit 1; }
/usr/bin/python3 "$src/doc/scripts/entry_cavity.py" polygon "$work/run" \
  > "$work/cavity"
cat "$work/cavity"
awk 'NR > 2 { rows++; if ($3 > 0.001) bad = 1 }
     END { exit bad || rows != 5 }' "$work/cavity" \
  || { echo "entry_cavity.py: unexpected values"; exit 1; }
for f in v.png s.png; do
  [ -s "$work/$f" ] || { echo "missing $f"; exit 1; }
done
echo "geocontainer plots: ok"
