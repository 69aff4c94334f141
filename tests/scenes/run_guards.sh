#!/bin/bash
# Run guards of the executable on the default scene:
#  - 1 and 2 threads give bit-identical monitors.csv (deterministic scatters
#    and reductions);
#  - a fixed time step just below the stability limit runs to the end; one
#    above the limit at the start is refused before anything is written
#    (exit status 1); one above it only at the impact stops there with
#    termination "unstable", exit status 3, a diagnosis, and no NaN in
#    monitors.csv or the VTU files;
#  - USL on a falling block (small-mass nodes) is detected as unstable the
#    same way, never producing NaN output;
#  - a body resolved by a few cells gets a warning.
# Usage: run_guards.sh <fsgmpm> <source dir>
set -u
exe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
passed=0
failed=0
check() { # check <name> <command...>: the command must succeed
  local name=$1; shift
  if "$@"; then echo "ok   $name"; passed=$((passed + 1)); else echo "FAIL $name"; failed=$((failed + 1)); fi
}
no_nan() { ! grep -qi "nan" "$1"/monitors.csv && ! grep -qi '"nan"\|NaN' "$1"/summary.json; }

scene="$2/prm/elastic_block_drop.prm"
common=("$scene" --set "Output/Quiet=true" --set "Simulation/End time=0.3")

"$exe" "${common[@]}" --set "Simulation/Number of threads=1" --set "Output/Directory=t1"
"$exe" "${common[@]}" --set "Simulation/Number of threads=2" --set "Output/Directory=t2"
check "1 and 2 threads give identical monitors" cmp -s t1/monitors.csv t2/monitors.csv
check "threads recorded" grep -q '"threads": 2' t2/summary.json

# The stability limit of this scene is h/(c + |v|): 4.8e-4 s at rest, 4.39e-4 s
# at the impact.
"$exe" "${common[@]}" --set "Simulation/Fixed time step=4.2e-4" --set "Output/Directory=below"
status=$?
check "fixed dt just below the limit runs (exit 0)" test $status -eq 0
check "fixed dt just below the limit ends at end_time" grep -q '"termination": "end_time"' below/summary.json
check "no NaN below the limit" no_nan below

# Above the limit at rest: refused before anything is written.
"$exe" "${common[@]}" --set "Simulation/Fixed time step=6e-4" --set "Output/Directory=above" 2>above.err
status=$?
check "fixed dt above the limit at the start exits 1" test $status -eq 1
check "refusal names the time step" grep -q "error: Simulation/Fixed time step = 0.0006 s exceeds the explicit stability limit" above.err
check "nothing written for the refused run" test ! -e above

# Below the limit at rest, above it at the impact: stopped there as unstable.
"$exe" "${common[@]}" --set "Simulation/Fixed time step=4.6e-4" --set "Output/Directory=impact" 2>impact.err
status=$?
check "fixed dt above the limit at the impact exits 3" test $status -eq 3
check "fixed dt above the limit at the impact is unstable" grep -q '"termination": "unstable"' impact/summary.json
check "diagnosis names the time step" grep -q "Fixed time step" impact.err
check "no NaN above the limit" no_nan impact

"$exe" "${common[@]}" --set "Simulation/Update scheme=USL" --set "Output/Directory=usl" --set "Output/Output every n steps=10" --set "Output/Output interval=0" 2>usl.err
status=$?
check "USL small-mass instability exits 3" test $status -eq 3
check "USL diagnosis says unstable" grep -q "unstable at step" usl.err
check "no NaN in USL monitors" no_nan usl
# The stability check runs before any output of a step, so the VTU files
# written before the stop hold finite fields.
check "no half-written files" bash -c '! ls usl/*.tmp.* 2>/dev/null'

# A body a few cells across is warned about (the default scene's 0.114 m
# column at Cell size 0.5 is 2 points in 1 cell); the block as shipped is
# not.
"$exe" --set "Grid/Cell size=0.5" --set "Simulation/End time=0.01" --set "Output/Quiet=true" --set "Output/Directory=coarse" 2>coarse.err
check "a body in a few cells is warned about" grep -q "warning: Bodies/Body 0 is resolved by only 2 points in 1 cells" coarse.err
check "the shipped block is not" bash -c '! grep -q "warning: Bodies" usl.err'

echo "run guards: $passed passed, $failed failed"
[ $failed -eq 0 ]
