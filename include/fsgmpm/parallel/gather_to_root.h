#ifndef fsgmpm_parallel_gather_to_root_h
#define fsgmpm_parallel_gather_to_root_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  namespace Parallel
  {
    /**
     * Values of a whole-grid array that each process holds a few of (its
     * window's), brought to process 0 only: each process sends the
     * whole-grid numbers @p index and the values @p values (plain data) of
     * its entries, and process 0 returns an array of @p n_global values in
     * which @p combine(result[index[k]], values[k]) has run for every entry
     * sent, in the order of the processes; the others return an empty
     * array. No process but 0 holds a whole-grid-sized array. The counts
     * are ints: at most 2^31 - 1 entries (and bytes of values) per
     * process.
     */
    template <typename T, typename Combine>
    std::vector<T>
    gather_to_root(const std::vector<unsigned int> &index,
                   const std::vector<T>            &values,
                   const unsigned int               n_global,
                   const MPI_Comm                  &comm,
                   const Combine                   &combine)
    {
      AssertDimension(index.size(), values.size());
      const bool       root = Utilities::MPI::this_mpi_process(comm) == 0;
      const int        n    = index.size();
      std::vector<int> n_of(root ? Utilities::MPI::n_mpi_processes(comm) : 0);
      int ierr = MPI_Gather(&n, 1, MPI_INT, n_of.data(), 1, MPI_INT, 0, comm);
      AssertThrowMPI(ierr);
      std::vector<int> start(n_of.size() + 1, 0), byte_count, byte_start;
      for (unsigned int q = 0; q < n_of.size(); ++q)
        {
          start[q + 1] = start[q] + n_of[q];
          byte_count.push_back(n_of[q] * sizeof(T));
          byte_start.push_back(start[q] * sizeof(T));
        }
      std::vector<unsigned int> all_index(start.back());
      std::vector<T>            all_values(start.back());
      ierr = MPI_Gatherv(index.data(),
                         n,
                         MPI_UNSIGNED,
                         all_index.data(),
                         n_of.data(),
                         start.data(),
                         MPI_UNSIGNED,
                         0,
                         comm);
      AssertThrowMPI(ierr);
      ierr = MPI_Gatherv(values.data(),
                         n * sizeof(T),
                         MPI_BYTE,
                         all_values.data(),
                         byte_count.data(),
                         byte_start.data(),
                         MPI_BYTE,
                         0,
                         comm);
      AssertThrowMPI(ierr);
      if (!root)
        return {};
      std::vector<T> result(n_global);
      for (unsigned int k = 0; k < all_index.size(); ++k)
        combine(result[all_index[k]], all_values[k]);
      return result;
    }
  } // namespace Parallel
} // namespace fsgmpm

#endif
