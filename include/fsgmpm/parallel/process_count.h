#ifndef fsgmpm_parallel_process_count_h
#define fsgmpm_parallel_process_count_h

#include <deal.II/base/mpi.h>

namespace fsgmpm
{
  namespace Parallel
  {
    /// Number of processes of @p communicator; 1 in a program started
    /// without an MPI launcher, which never initialises MPI (asking MPI
    /// then would abort).
    inline unsigned int
    n_processes(const MPI_Comm communicator)
    {
      return dealii::Utilities::MPI::job_supports_mpi()
               ? dealii::Utilities::MPI::n_mpi_processes(communicator)
               : 1;
    }
  } // namespace Parallel
} // namespace fsgmpm

#endif
