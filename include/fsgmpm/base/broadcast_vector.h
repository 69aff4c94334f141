#ifndef fsgmpm_base_broadcast_vector_h
#define fsgmpm_base_broadcast_vector_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace fsgmpm
{
  namespace Parallel
  {
    /// Call f(offset, count) for the pieces of at most 1 GiB of @p size
    /// bytes (an MPI count is an int).
    template <typename Function>
    void
    for_each_piece(const std::uint64_t size, const Function &f)
    {
      const std::uint64_t piece = std::uint64_t(1) << 30;
      for (std::uint64_t offset = 0; offset < size; offset += piece)
        f(offset, static_cast<int>(std::min(piece, size - offset)));
    }

    /// The bytes of a vector of plain values from process @p root to all
    /// of @p communicator, in pieces of at most 1 GiB.
    template <typename T>
    void
    broadcast_vector(std::vector<T>    &values,
                     const MPI_Comm    &communicator,
                     const unsigned int root)
    {
      std::uint64_t n    = values.size();
      int           ierr = MPI_Bcast(&n, 1, MPI_UINT64_T, root, communicator);
      AssertThrowMPI(ierr);
      values.resize(n);
      char *bytes = reinterpret_cast<char *>(values.data());
      for_each_piece(
        n * sizeof(T), [&](const std::uint64_t offset, const int count) {
          ierr = MPI_Bcast(bytes + offset, count, MPI_BYTE, root, communicator);
          AssertThrowMPI(ierr);
        });
    }
  } // namespace Parallel
} // namespace fsgmpm

#endif
