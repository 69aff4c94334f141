#ifndef fsgmpm_parallel_process_count_h
#define fsgmpm_parallel_process_count_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <utility>

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

    /**
     * Rows split over the processes of @p communicator, process r's after
     * those of processes 0..r-1 (as in one shared file): this process's
     * first row and the rows of all processes, for its @p n_local rows.
     * Collective; {0, n_local} without MPI.
     */
    inline std::pair<unsigned long long, unsigned long long>
    offset_and_total(const unsigned long long n_local,
                     const MPI_Comm           communicator)
    {
      if (n_processes(communicator) == 1)
        return {0, n_local};
      unsigned long long offset = 0;
      const int          ierr   = MPI_Exscan(
        &n_local, &offset, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, communicator);
      AssertThrowMPI(ierr);
      // MPI_Exscan leaves process 0's result undefined.
      if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
        offset = 0;
      return {offset, dealii::Utilities::MPI::sum(n_local, communicator)};
    }
  } // namespace Parallel
} // namespace fsgmpm

#endif
