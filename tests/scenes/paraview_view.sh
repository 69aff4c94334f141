#!/bin/bash
# doc/scripts/paraview_view.py renders a run to PNG with ParaView: the
# default scene for 0.05 s coloured by pressure, and the coarse 2D geotube
# (points and membrane) by velocity; each picture is written and is not
# blank (many colours); a missing field and a missing run directory give a
# message and exit status 2. Skipped (exit 77) where ParaView's pvbatch is
# not installed (Debian: paraview, python3-paraview; without a display it
# runs under xvfb-run).
# Usage: paraview_view.sh <fsgmpm> <source dir>
set -eu
exe=$1
script=$2/doc/scripts/paraview_view.py
if ! command -v pvbatch > /dev/null; then
  echo "pvbatch not found (Debian: paraview): skipped"
  exit 77
fi
# Without a display, the whole test runs under one virtual X server of
# 24-bit colour that does not reset when a client leaves (pvbatch connects
# more than once; a reset between its connections aborted it now and then).
if [ -z "${DISPLAY:-}" ]; then
  if ! command -v xvfb-run > /dev/null; then
    echo "no display and no xvfb-run (Debian: xvfb): skipped"
    exit 77
  fi
  exec xvfb-run -a -s "-ac -noreset -screen 0 1280x1024x24" bash "$0" "$@"
fi
pvbatch=(pvbatch)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$exe" --set "Simulation/End time=0.05" --set "Output/Directory=out" \
  --set "Output/Quiet=true"
"${pvbatch[@]}" "$script" out -o p.png | tee p.txt
grep -q "coloured by pressure -> p.png" p.txt
"$exe" "$2/prm/geotube_A5.56.prm" --set "Grid/Cell size=0.2" \
  --set "Simulation/Maximum number of steps=200" \
  --set "Output/Output every n steps=100" --set "Output/Output interval=0" \
  --set "Output/Directory=tube" --set "Output/Quiet=true"
"${pvbatch[@]}" "$script" tube --field velocity -o t.png | tee t.txt
grep -q "coloured by velocity -> t.png" t.txt
/usr/bin/python3 - p.png t.png <<'PY'
import sys
import matplotlib.image as image
import numpy as np
for name in sys.argv[1:]:
    pixels = image.imread(name)
    colours = len(np.unique(pixels.reshape(-1, pixels.shape[-1]), axis=0))
    print(name, pixels.shape, colours, "colours")
    assert pixels.shape[0] > 100 and colours > 20, (name, colours)
PY
status=0
"${pvbatch[@]}" "$script" out --field no_such_field -o n.png 2> field.err || status=$?
test "$status" = 2
grep -q "the points have no field no_such_field" field.err
status=0
"${pvbatch[@]}" "$script" missing 2> missing.err || status=$?
test "$status" = 2
echo "paraview view: ok"
