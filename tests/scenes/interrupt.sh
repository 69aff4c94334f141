#!/bin/bash
# SIGTERM and SIGINT stop a run after its current step: it writes its
# checkpoint (Output/Checkpoint interval > 0), its last monitors.csv row and
# summary.json with termination "interrupted" and a diagnosis, leaves no
# temporary file, and exits 143 (SIGTERM) or 130 (SIGINT). --restart then
# continues it, and the result is the uninterrupted run's byte for byte.
# With MPI (2 processes) a signal to one process stops both (they agree in
# the step's collective) and the restart continues on 2 processes.
# Usage: interrupt.sh <fsgmpm> <source dir>
set -u
exe=$(realpath "$1")
src=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
source "$src/tests/mpi/mpi_launch.sh"
passed=0
failed=0
check() { # check <name> <command...>: the command must succeed
  local name=$1; shift
  if "$@"; then echo "ok   $name"; passed=$((passed + 1)); else echo "FAIL $name"; failed=$((failed + 1)); fi
}
rows() { if [ -f "$1/monitors.csv" ]; then wc -l < "$1/monitors.csv"; else echo 0; fi; }
termination() { grep -q "\"termination\": \"$2\"" "$1/summary.json" 2>/dev/null; }
no_temporary_files() { ! ls "$1" "$1/checkpoints" 2>/dev/null | grep -q '\.tmp'; }
last_row_complete() { [ "$(tail -c 1 "$1/monitors.csv" | od -An -c | tr -d ' ')" = '\n' ]; }
n_checkpoints() { ls "$1"/checkpoints/checkpoint_*.h5 2>/dev/null | wc -l; }

# The coarse dam break, long enough (some seconds) to be stopped while it
# steps: a monitor row every 10 steps.
scene=("$src/prm/default_dam_break.prm" --set "Output/Quiet=true"
  --set "Grid/Cell size=0.02" --set "Simulation/End time=0.15"
  --set "Output/Output interval=0.01" --set "Output/Checkpoint interval=0.01")

# start <directory> <signal> <launcher and arguments...>: run in the
# background, send the signal once the run has written 4 monitor rows (to
# the process, or with MPI to the last rank only), and wait; sets $status.
start() {
  local dir=$1 signal=$2
  shift 2
  "$@" --set "Output/Directory=$dir" >/dev/null 2>"$dir.err" &
  local pid=$!
  while kill -0 $pid 2>/dev/null && [ "$(rows "$dir")" -lt 5 ]; do sleep 0.02; done
  local target=$pid
  for p in $(pgrep -f "Output/Directory=$dir"); do
    [ "$(cat /proc/$p/comm 2>/dev/null)" = fsgmpm ] && target=$p
  done
  kill -"$signal" "$target"
  wait $pid
  status=$?
}

threads=(--set "Simulation/Number of threads=2")
"$exe" "${scene[@]}" "${threads[@]}" --set "Output/Directory=full" >/dev/null
check "uninterrupted run ends at its end time" termination full end_time

start term TERM "$exe" "${scene[@]}" "${threads[@]}"
check "SIGTERM: exit status 143" test $status -eq 143
check "SIGTERM: termination interrupted in summary.json" termination term interrupted
check "SIGTERM: the diagnosis names the signal" grep -q '"diagnosis": "interrupted by SIGTERM at step' term/summary.json
check "SIGTERM: ... and says how to continue" grep -q "continue with --restart term" term/summary.json
check "SIGTERM: stopped before its end" test "$(rows term)" -lt "$(rows full)"
check "SIGTERM: a checkpoint at the stop" test "$(n_checkpoints term)" -ge 1
check "SIGTERM: no temporary file" no_temporary_files term
check "SIGTERM: whole monitors.csv rows" last_row_complete term
"$exe" "${scene[@]}" "${threads[@]}" --restart term >/dev/null
check "SIGTERM: the restart exits 0" test $? -eq 0
check "SIGTERM: ... ends at the end time" termination term end_time
check "SIGTERM: ... and its monitors.csv is the uninterrupted one" cmp -s full/monitors.csv term/monitors.csv

start int INT "$exe" "${scene[@]}" "${threads[@]}" --set "Output/Checkpoint interval=0"
check "SIGINT: exit status 130" test $status -eq 130
check "SIGINT: termination interrupted" termination int interrupted
check "SIGINT: without checkpoints, says so" grep -q "would have written a checkpoint" int/summary.json
check "SIGINT: no checkpoint written" test "$(n_checkpoints int)" -eq 0
check "SIGINT: no temporary file" no_temporary_files int

mpi=(--set "Simulation/Number of threads=1")
mpi_launch 2 "$exe" "${scene[@]}" "${mpi[@]}" --set "Output/Directory=mpi_full" >/dev/null
start mpi_term TERM mpi_launch 2 "$exe" "${scene[@]}" "${mpi[@]}"
check "MPI: SIGTERM to one process stops the run" test $status -ne 0
check "MPI: termination interrupted" termination mpi_term interrupted
check "MPI: no temporary file" no_temporary_files mpi_term
mpi_launch 2 "$exe" "${scene[@]}" "${mpi[@]}" --restart mpi_term >/dev/null
check "MPI: the restart exits 0" test $? -eq 0
check "MPI: ... and its monitors.csv is the uninterrupted one" cmp -s mpi_full/monitors.csv mpi_term/monitors.csv

echo "interrupt: $passed passed, $failed failed"
[ $failed -eq 0 ]
