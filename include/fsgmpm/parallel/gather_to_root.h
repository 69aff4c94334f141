#ifndef fsgmpm_parallel_gather_to_root_h
#define fsgmpm_parallel_gather_to_root_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  namespace Parallel
  {
    /**
     * The displacements of an MPI_Gatherv of @p counts entries from each
     * process (start[q] of process q, start[n] the total): MPI counts and
     * displacements are ints, so the running total is summed in 64 bits and
     * a total above 2^31 - 1 entries is an error (what to do: run on more
     * processes or gather less), not a wrap-around.
     */
    inline std::vector<int>
    gather_displacements(const std::vector<int> &counts)
    {
      std::vector<int> start(counts.size() + 1, 0);
      std::int64_t     total = 0;
      for (unsigned int q = 0; q < counts.size(); ++q)
        {
          AssertThrow(counts[q] >= 0, ExcInternalError());
          total += counts[q];
          AssertThrow(total <= std::numeric_limits<int>::max(),
                      ExcMessage("gather_to_root: the processes send more "
                                 "than 2^31 - 1 entries to process 0 in "
                                 "total."));
          start[q + 1] = total;
        }
      return start;
    }

    /**
     * Values of a whole-grid array that each process holds a few of (its
     * window's), brought to process 0 only: each process sends the
     * whole-grid numbers @p index and the values @p values (plain data) of
     * its entries, and process 0 returns an array of @p n_global values in
     * which @p combine(result[index[k]], values[k]) has run for every entry
     * sent, in the order of the processes; the others return an empty
     * array. No process but 0 holds a whole-grid-sized array. MPI counts
     * are ints: all processes together may send at most 2^31 - 1 entries
     * (counted in entries, not bytes), which process 0 checks.
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
      AssertThrow(index.size() <= std::numeric_limits<int>::max(),
                  ExcMessage("gather_to_root: more than 2^31 - 1 entries on "
                             "one process."));
      const bool       root = Utilities::MPI::this_mpi_process(comm) == 0;
      const int        n    = index.size();
      std::vector<int> n_of(root ? Utilities::MPI::n_mpi_processes(comm) : 0);
      int ierr = MPI_Gather(&n, 1, MPI_INT, n_of.data(), 1, MPI_INT, 0, comm);
      AssertThrowMPI(ierr);
      // The offsets are ints too: their total is checked in 64 bits.
      const std::vector<int>    start = gather_displacements(n_of);
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
      // The values as one MPI type of sizeof(T) bytes, so that the counts
      // are entries, not bytes (which would pass 2^31 eight times sooner).
      MPI_Datatype entry;
      ierr = MPI_Type_contiguous(sizeof(T), MPI_BYTE, &entry);
      AssertThrowMPI(ierr);
      ierr = MPI_Type_commit(&entry);
      AssertThrowMPI(ierr);
      ierr = MPI_Gatherv(values.data(),
                         n,
                         entry,
                         all_values.data(),
                         n_of.data(),
                         start.data(),
                         entry,
                         0,
                         comm);
      AssertThrowMPI(ierr);
      ierr = MPI_Type_free(&entry);
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
