# Sourced by the scripts that start fsgmpm with mpirun (the MPI tests and
# doc/scripts/mpi_scaling.sh).
#
# mpi_launch <processes> <program> [arguments...]: mpirun as root, allowed to
# place more processes than cores. Open MPI polls for messages; with more
# processes than cores a waiting process must give up its core
# (mpi_yield_when_idle: the 200-step dam break on 3 processes of a 2-core
# machine, 41.5 s polling, 1.7 s yielding). Only then: beside another busy
# program, yielding processes lose the core to it (the 2-process dam break to
# 0.04 s beside a 2-thread run: 14 s polling, over 120 s yielding), so with as
# many cores as processes they poll.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi_launch() {
  local np=$1
  shift
  local yield=()
  if [ "$np" -gt "$(nproc)" ]; then yield=(--mca mpi_yield_when_idle 1); fi
  mpirun --oversubscribe "${yield[@]}" -np "$np" "$@"
}
