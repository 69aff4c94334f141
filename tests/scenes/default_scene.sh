#!/bin/bash
# The README's default scene (fsgmpm without a file runs the embedded
# prm/default_dam_break.prm, a coarse water-column collapse) runs, writes
# ParaView output, monitors.csv with the dam-break columns and summary.json,
# and loses no particle; the same scene from the prm file gives the same
# monitors, as does the parameters.prm the run writes beside its output
# (with command_line.txt and log.txt, what the terminal showed). Shortened to 0.05 s of simulated time for ctest.
# Usage: default_scene.sh <fsgmpm> <source dir>
set -eu
exe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$exe" --set "Simulation/End time=0.05" --set "Output/Directory=out" > terminal.txt 2>&1
# log.txt holds what the terminal showed, from the first line.
test -s out/log.txt
cmp terminal.txt out/log.txt
test -s out/monitors.csv
# The header gives each column's unit (2D: energies per metre of
# thickness); counts and ratios have none.
head -1 out/monitors.csv | grep -q "^time\[s\],step,dt\[s\],kinetic_energy\[J/m\],strain_energy\[J/m\],"
head -1 out/monitors.csv | grep -q ",lost_particles,grid_kinetic_energy\[J/m\],material_dissipation\[J/m\],numerical_dissipation\[J/m\],outflow_energy\[J/m\],free_surface_fraction,front_position\[m\],column_height\[m\]$"
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
# summary.json explains the end of the run: the last monitors.csv row by
# column (with the units), the energy balance's residual from the first and
# last rows (the booked losses subtracted), and dt_min, the smallest step the stability limit chose, apart
# from the last step (dt_last) shortened to land on the end time.
/usr/bin/python3 - out/summary.json out/monitors.csv "$2/doc/scripts" <<'PY'
import json, sys
sys.path.insert(0, sys.argv[3])
import monitors_csv
s = json.load(open(sys.argv[1]))
rows = list(monitors_csv.DictReader(open(sys.argv[2])))
last, first = rows[-1], rows[0]
final = s["final_monitors"]
assert list(final) == list(last), (list(final), list(last))
for k, v in last.items():
    assert (final[k] is None and v == "") or final[k] == float(v), (k, final[k], v)
assert s["monitor_units"]["kinetic_energy"] == "J/m", s["monitor_units"]
assert s["monitor_units"]["front_position"] == "m", s["monitor_units"]
assert s["monitor_units"]["step"] == "", s["monitor_units"]
f = lambda r, k: float(r[k])
e0 = f(first, "kinetic_energy") + f(first, "strain_energy")
residual = (f(last, "kinetic_energy") + f(last, "strain_energy")
            - (e0 + f(last, "external_work") - f(last, "dissipated_energy")
               - f(last, "material_dissipation")
               - f(last, "numerical_dissipation") - f(last, "outflow_energy")))
scale = max(abs(e0), abs(f(last, "external_work")))
assert abs(s["energy_residual"] - residual) <= 1e-9 * scale, (s["energy_residual"], residual)
assert abs(s["energy_residual_ratio"]) < 0.5, s["energy_residual_ratio"]
assert s["dt_last"] == f(last, "dt"), (s["dt_last"], last["dt"])
# The run ends on 0.05 s with a shortened step: it is not dt_min.
assert s["dt_last"] < s["dt_min"] <= s["dt_max"], (s["dt_last"], s["dt_min"], s["dt_max"])
assert min(f(r, "dt") for r in rows[1:-1]) >= s["dt_min"], s["dt_min"]
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
# The rerun's log replaces the earlier run's.
cmp rerun.err out3/log.txt
test -z "$(ls out/*.tmp.* 2>/dev/null)"
echo "default scene: 1 passed, 0 failed"
