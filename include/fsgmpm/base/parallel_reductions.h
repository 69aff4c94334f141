#ifndef fsgmpm_base_parallel_reductions_h
#define fsgmpm_base_parallel_reductions_h

#include <deal.II/base/parallel.h>

#include <fsgmpm/base/compensated_sum.h>

#include <algorithm>
#include <array>
#include <vector>

namespace fsgmpm
{
  /**
   * Parallel loops and reductions over [0, n) whose results do not depend
   * on the number of threads: the items are taken in fixed chunks, in
   * order, and the chunks merged in order.
   */
  namespace Reductions
  {
    /// Run f(begin, end) over [0, n) in parallel chunks (TBB through deal.II).
    template <typename Function>
    void
    parallel_range(const unsigned int n,
                   const Function    &f,
                   const unsigned int grain = 256)
    {
      dealii::parallel::apply_to_subranges(0u, n, f, grain);
    }

    /**
     * A reduction over the items [0, n) in fixed chunks of @p chunk, in
     * parallel: each chunk starts from @p initial, f(a, value) takes item a
     * in, in order, and merge(total, chunk_value) combines the chunks' values
     * in chunk order, starting from @p initial. The chunks do not depend on
     * the number of threads, so neither does the result.
     */
    template <typename Value, typename Function, typename Merge>
    Value
    chunked_reduction(const unsigned int n,
                      const unsigned int chunk,
                      const Value       &initial,
                      const Function    &f,
                      const Merge       &merge)
    {
      const unsigned int n_chunks = (n + chunk - 1) / chunk;
      std::vector<Value> partial(n_chunks, initial);
      parallel_range(
        n_chunks,
        [&](const unsigned int b, const unsigned int e) {
          for (unsigned int k = b; k < e; ++k)
            {
              // In a local, which the compiler can keep in registers.
              Value value = initial;
              for (unsigned int a = k * chunk; a < std::min(n, (k + 1) * chunk);
                   ++a)
                f(a, value);
              partial[k] = value;
            }
        },
        1);
      Value total = initial;
      for (const Value &p : partial)
        merge(total, p);
      return total;
    }

    /**
     * N compensated sums over the items [0, n), in parallel: f(a, sums)
     * adds item a's terms to sums[0..N-1]. The items are summed in fixed
     * chunks of 512 (small enough to share among threads), in order, and the
     * chunks' sums merged in order (CompensatedSum::add(const CompensatedSum
     * &)), so the result does not depend on the number of threads.
     */
    template <unsigned int N, typename Function>
    std::array<CompensatedSum, N>
    compensated_sums(const unsigned int n, const Function &f)
    {
      using Sums = std::array<CompensatedSum, N>;
      return chunked_reduction(
        n, 512, Sums(), f, [](Sums &total, const Sums &chunk_sums) {
          for (unsigned int q = 0; q < N; ++q)
            total[q].add(chunk_sums[q]);
        });
    }

    /**
     * N maxima over the items [0, n), in parallel: f(a, maxima) raises
     * maxima[0..N-1] by item a's values (std::max). Each chunk of 4096 items
     * starts from @p initial and the chunks' maxima are merged with
     * std::max: a maximum is exact, so the result does not depend on the
     * number of threads.
     */
    template <unsigned int N, typename Function>
    std::array<double, N>
    parallel_maxima(const unsigned int           n,
                    const std::array<double, N> &initial,
                    const Function              &f)
    {
      using Maxima = std::array<double, N>;
      return chunked_reduction(
        n, 4096, initial, f, [](Maxima &total, const Maxima &chunk_maxima) {
          for (unsigned int q = 0; q < N; ++q)
            total[q] = std::max(total[q], chunk_maxima[q]);
        });
    }

  } // namespace Reductions
} // namespace fsgmpm

#endif
