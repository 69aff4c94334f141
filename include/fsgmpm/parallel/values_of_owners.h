#ifndef fsgmpm_parallel_values_of_owners_h
#define fsgmpm_parallel_values_of_owners_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <cstring>
#include <utility>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  namespace Parallel
  {
    /**
     * Replace every entry of @p values by the value of the one process for
     * which @p owned(i) holds, on every process of @p comm: a sum over the
     * processes in which the others give -0, the exact neutral element of
     * IEEE addition (x + -0 = x for every x, +0 included), so the result is
     * the owner's value bit for bit. Exactly one process must own each
     * entry. @p T is double or a Tensor of doubles.
     */
    template <typename T, typename Owned>
    void
    take_values_of_owners(std::vector<T> &values,
                          const Owned    &owned,
                          const MPI_Comm &comm)
    {
      static_assert(sizeof(T) % sizeof(double) == 0,
                    "take_values_of_owners() takes doubles or tensors of "
                    "doubles");
      constexpr unsigned int n = sizeof(T) / sizeof(double);
      std::vector<double> local(n * values.size(), -0.), global(local.size());
      for (unsigned int i = 0; i < values.size(); ++i)
        if (owned(i))
          std::memcpy(&local[n * i], &values[i], sizeof(T));
      Utilities::MPI::sum(make_array_view(std::as_const(local)),
                          comm,
                          make_array_view(global));
      for (unsigned int i = 0; i < values.size(); ++i)
        std::memcpy(&values[i], &global[n * i], sizeof(T));
    }
  } // namespace Parallel
} // namespace fsgmpm

#endif
