/* Counts the collective MPI calls of a program (LD_PRELOAD, through the
 * PMPI profiling interface) and prints them at MPI_Finalize, on rank 0:
 *   COLLECTIVES allreduce=<n> barrier=<n> ibarrier=<n> other=<n>
 * Built and used by doc/scripts/mpi_collectives.sh. */
#include <mpi.h>
#include <stdio.h>

static long n_allreduce = 0, n_barrier = 0, n_ibarrier = 0, n_other = 0;

int MPI_Allreduce(const void *s, void *r, int n, MPI_Datatype t, MPI_Op o,
                  MPI_Comm c)
{
  ++n_allreduce;
  return PMPI_Allreduce(s, r, n, t, o, c);
}

int MPI_Barrier(MPI_Comm c)
{
  ++n_barrier;
  return PMPI_Barrier(c);
}

int MPI_Ibarrier(MPI_Comm c, MPI_Request *q)
{
  ++n_ibarrier;
  return PMPI_Ibarrier(c, q);
}

int MPI_Bcast(void *b, int n, MPI_Datatype t, int root, MPI_Comm c)
{
  ++n_other;
  return PMPI_Bcast(b, n, t, root, c);
}

int MPI_Allgather(const void *s, int sn, MPI_Datatype st, void *r, int rn,
                  MPI_Datatype rt, MPI_Comm c)
{
  ++n_other;
  return PMPI_Allgather(s, sn, st, r, rn, rt, c);
}

int MPI_Alltoall(const void *s, int sn, MPI_Datatype st, void *r, int rn,
                 MPI_Datatype rt, MPI_Comm c)
{
  ++n_other;
  return PMPI_Alltoall(s, sn, st, r, rn, rt, c);
}

int MPI_Gather(const void *s, int sn, MPI_Datatype st, void *r, int rn,
               MPI_Datatype rt, int root, MPI_Comm c)
{
  ++n_other;
  return PMPI_Gather(s, sn, st, r, rn, rt, root, c);
}

int MPI_Reduce(const void *s, void *r, int n, MPI_Datatype t, MPI_Op o,
               int root, MPI_Comm c)
{
  ++n_other;
  return PMPI_Reduce(s, r, n, t, o, root, c);
}

int MPI_Exscan(const void *s, void *r, int n, MPI_Datatype t, MPI_Op o,
               MPI_Comm c)
{
  ++n_other;
  return PMPI_Exscan(s, r, n, t, o, c);
}

int MPI_Finalize(void)
{
  int rank = 0;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    fprintf(stderr, "COLLECTIVES allreduce=%ld barrier=%ld ibarrier=%ld "
                    "other=%ld\n",
            n_allreduce, n_barrier, n_ibarrier, n_other);
  return PMPI_Finalize();
}
