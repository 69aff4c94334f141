#!/bin/bash
# The added mass of the geocontainers' sections, and the bag released at
# rest under water against it (doc/geocontainer_validation.md, "Released
# under water").
#   added_mass_release.sh <fsgmpm> <source dir> panel
# doc/scripts/added_mass.py's panel method against the closed forms of a
# circle and an ellipse moving along its minor axis (rho pi a^2): within
# 0.2% (measured 0.07% with 2000 panels); doc/scripts/drag_balance.py's
# v(t) starts at the slope a_0 and approaches v_t. About 20 s.
#   added_mass_release.sh <fsgmpm> <source dir> release SHAPE TOL_V TOL_Y
# prm/geocontainer_SHAPE.prm at 2 cm, the water to 1.6 m and the bag's
# lowest point at 0.9 m, released at rest, to 0.12 s: the accelerations
# fitted by doc/scripts/release_acceleration.py to the velocity and to the
# height each within TOL_V and TOL_Y (relative) of the potential-flow
# a_0 = (m_bag - rho V) g / (m_bag + m_a). Measured: ellipse +2.4% and
# +4.9%, polygon in doc/geocontainer_validation.md. About 4 min each.
set -euo pipefail
exe=$1
src=$2
mode=$3
if [ "$mode" = panel ]; then
  /usr/bin/python3 "$src/doc/scripts/added_mass.py" | tee /dev/stderr |
    awk '/circle|ellipse a =/ { n++; e = $NF; sub("%", "", e); e = e < 0 ? -e : e
                                if (e > 0.2) bad = 1 }
         END { exit bad || n != 2 }' ||
    { echo "added_mass.py: the panel method misses the closed forms"; exit 1; }
  # The drag balance released at rest: its slope at the start is a_0, it
  # approaches v_t from below.
  for shape in ellipse polygon; do
    /usr/bin/python3 "$src/doc/scripts/drag_balance.py" "$shape" |
      tee /dev/stderr | awk '
        NR == 1 { split($0, f, "a_0 = "); a0 = f[2] + 0
                  split($0, g, "v_t = "); vt = g[2] + 0 }
        $1 == "0.10" { ok0 = ($2 / 0.1 > 0.97 * a0 && $2 / 0.1 <= a0) }
        $1 == "1.00" { ok1 = ($2 < vt && $2 > 0.9 * vt) }
        END { exit !(ok0 && ok1) }' ||
      { echo "drag_balance.py: v(t) is not the balance's"; exit 1; }
  done
  echo "added mass panel method: ok"
  exit 0
fi
shape=$4
tol_v=$5
tol_y=$6
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
vertices=()
if [ "$shape" = polygon ]; then
  vertices=(--set "Membrane/Polygon vertices=1.0, 0.9; 1.13564, 0.98007; 1.09495, 1.02076; 0.90505, 1.02076; 0.86436, 0.98007")
fi
"$exe" "$src/prm/geocontainer_$shape.prm" --set "Grid/Cell size=0.02" \
  --set "Simulation/End time=0.12" --set "Output/Write particles=false" \
  --set "Output/Monitor every n steps=20" --set "Output/Quiet=true" \
  --set "Bodies/Body 1/Box upper corner=2, 1.6" \
  --set "Membrane/Lowest point=1.0, 0.9" "${vertices[@]}" \
  --set "Output/Directory=$work/run" > "$work/log" 2>&1 ||
  { cat "$work/log"; exit 1; }
/usr/bin/python3 "$src/doc/scripts/release_acceleration.py" "$shape" \
  "$work/run" | tee "$work/fit"
awk -v tv="$tol_v" -v ty="$tol_y" '/^errors/ {
       ev = $2 < 0 ? -$2 : $2; ey = $3 < 0 ? -$3 : $3
       printf "[ measured ] release acceleration errors %s %s\n", $2, $3
       ok = ev <= tv && ey <= ty }
     END { exit !ok }' "$work/fit" ||
  { echo "the released bag's acceleration misses the added mass"; exit 1; }
echo "released under water: ok"
