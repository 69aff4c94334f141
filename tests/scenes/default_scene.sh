#!/bin/bash
# The README's default scene (built-in defaults, an elastic block dropping
# onto the ground) runs to its end time, writes ParaView output, monitors.csv
# and summary.json, and loses no particle. Usage: default_scene.sh <fsgmpm> <source dir>
set -eu
exe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$exe" --set "Output/Directory=out"
test -s out/monitors.csv
test -s out/particles.pvd
ls out/particles_*.vtu >/dev/null
grep -q '"termination": "end_time"' out/summary.json
grep -q '"lost_particles": 0' out/summary.json
# Same scene from the prm file in prm/ gives the same number of steps.
"$exe" "$2/prm/elastic_block_drop.prm" --set "Output/Directory=out2" --set "Output/Quiet=true"
cmp <(grep '"steps"' out/summary.json) <(grep '"steps"' out2/summary.json)
! ls out/*.tmp.* 2>/dev/null
echo "default scene: 1 passed, 0 failed"
