#!/bin/bash
# The README's default scene (fsgmpm without a file runs the embedded
# prm/default_dam_break.prm, a coarse water-column collapse) runs, writes
# ParaView output, monitors.csv with the dam-break columns and summary.json,
# and loses no particle; the same scene from the prm file gives the same
# monitors, as does the parameters.prm the run writes beside its output
# (with command_line.txt). Shortened to 0.05 s of simulated time for ctest.
# Usage: default_scene.sh <fsgmpm> <source dir>
set -eu
exe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$exe" --set "Simulation/End time=0.05" --set "Output/Directory=out"
test -s out/monitors.csv
head -1 out/monitors.csv | grep -q "free_surface_fraction,front_position,column_height"
test -s out/particles.pvd
ls out/particles_*.vtu >/dev/null
grep -q '"termination": "end_time"' out/summary.json
grep -q '"lost_particles": 0' out/summary.json
# The measured memory: the process's peak resident set (the libraries
# alone are some 150 MB), and per point that peak over the points.
/usr/bin/python3 - out/summary.json <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
peak, per_point = s["peak_resident_bytes"], s["resident_bytes_per_particle"]
assert 50e6 < peak < 2e9, peak
assert abs(per_point * s["particles"] - peak) < 1e-9 * peak, (per_point, peak)
PY
"$exe" "$2/prm/default_dam_break.prm" --set "Simulation/End time=0.05" \
  --set "Output/Directory=out2" --set "Output/Quiet=true"
cmp out/monitors.csv out2/monitors.csv
# The run explains itself: its resolved parameters run as a scene file and
# give the same monitors; the command line and version are beside them.
test -s out/parameters.prm
grep -q "^fsgmpm [0-9.]* (git [0-9a-z-]*)$" out/command_line.txt
"$exe" --version | grep -q "^fsgmpm [0-9.]* (git [0-9a-z-]*)$"
grep -q '"git_commit": "' out/summary.json
grep -q "'Simulation/End time=0.05'" out/command_line.txt
"$exe" out/parameters.prm --set "Output/Directory=out3" --set "Output/Quiet=true"
cmp out/monitors.csv out3/monitors.csv
# A rerun into a directory with an earlier run's results says so.
"$exe" --set "Simulation/End time=0.001" --set "Output/Directory=out3" \
  --set "Output/Quiet=true" 2> rerun.err
grep -q "out3 holds the results of an earlier run" rerun.err
! ls out/*.tmp.* 2>/dev/null
echo "default scene: 1 passed, 0 failed"
