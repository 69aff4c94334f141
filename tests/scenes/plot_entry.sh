#!/bin/bash
# doc/scripts/plot.py, the one plotting entry point, on real output: the
# default scene for 0.05 s is told as a dam break (--list), drawn against
# Martin & Moyce with a warning that the run ends before the reference's
# range (the errors over the points inside the run, nothing extrapolated);
# a missing run directory and a scene option of another scene give a
# one-line message and exit status 2; prm/elastic_block_drop.prm (no scene
# monitors) gets the generic energy plot, and with Output/Report = true the
# run writes it as report.png itself. About 15 s.
# Usage: plot_entry.sh <fsgmpm> <source dir>
set -eu
exe=$1
plot=$2/doc/scripts/plot.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$exe" --set "Simulation/End time=0.05" --set "Output/Directory=out" \
  --set "Output/Quiet=true"
"$plot" out --list > list.txt
cat list.txt
grep -q "^scene: dam_break " list.txt
grep -q "^columns: time\[s\], front_position\[m\], column_height\[m\]$" list.txt
"$plot" out -o f.png > plot.out 2> plot.err
cat plot.out plot.err
test -s f.png
head -c 8 f.png | od -c | grep -q "P   N   G"
grep -q "warning: out ends at t = 0.05 s .*before the end of Martin & Moyce's front data" plot.err
grep -q "the curve is not extrapolated" plot.err
# The front error is over the two experimental points before 0.05 s.
grep -q "front RMS error in Z (T <= 0.656) = 0.0[0-9]* over 2 of 15 points" plot.out
# No RUN_DIR, no monitors.csv: a message and exit status 2.
status=0
"$plot" missing_dir -o m.png 2> missing.err || status=$?
cat missing.err
test "$status" = 2
grep -q "^plot.py: missing_dir is not a directory" missing.err
test "$(wc -l < missing.err)" = 1
test ! -e m.png
mkdir empty
status=0
"$plot" empty 2> empty.err || status=$?
test "$status" = 2
grep -q "^plot.py: empty holds no monitors.csv" empty.err
# An option of another scene names the detected one.
status=0
"$plot" out --L0 0.2 2> wrong.err || status=$?
cat wrong.err
test "$status" = 2
grep -q "^plot.py: --L0 is an option of the deposit plot; the run in out is scene dam_break" wrong.err
# No scene monitors: the energies, the booked losses and the balance.
"$exe" "$2/prm/elastic_block_drop.prm" --set "Simulation/End time=0.05" \
  --set "Output/Directory=block" --set "Output/Quiet=true"
"$plot" block --list > block_list.txt
cat block_list.txt
grep -q "^scene: energy " block_list.txt
grep -q "kinetic_energy\[J/m\], strain_energy\[J/m\], potential_energy\[J/m\], external_work\[J/m\], dissipated_energy\[J/m\]" block_list.txt
"$plot" block > block.out 2> block.err
cat block.out block.err
test -s block/plot.png
grep -q "energy balance residual at t = 0.05 s" block.out
if grep -q warning block.err; then echo "unexpected warning"; exit 1; fi
# Output/Report = true: the run draws report.png itself and says so (in its
# log too).
"$exe" "$2/prm/elastic_block_drop.prm" --set "Simulation/End time=0.05" \
  --set "Output/Directory=report" --set "Output/Quiet=true" \
  --set "Output/Report=true" 2> report.err
cat report.err
head -c 8 report/report.png | od -c | grep -q "P   N   G"
grep -q "^fsgmpm: report written to report/report.png$" report.err
grep -q "^fsgmpm: report written to report/report.png$" report/log.txt
echo "plot entry point: ok"
