#ifndef fsgmpm_base_compensated_sum_h
#define fsgmpm_base_compensated_sum_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <cmath>
#include <utility>
#include <vector>

namespace fsgmpm
{
  /**
   * Neumaier's compensated summation: the rounding error of every addition
   * is kept in a second sum, so a sum of n terms is accurate to about one
   * rounding whatever their order (a plain sum: up to n roundings, 5e-12
   * relative for the 3D geocontainer's water mass). Monitors that add up
   * over points use it, so that their values do not change in the last
   * digits when the points are sorted differently or split over processes.
   * Over processes: sum_over_processes().
   */
  class CompensatedSum
  {
  public:
    CompensatedSum() = default;

    /// A sum that starts at @p value (e.g. one already summed over the
    /// processes).
    explicit CompensatedSum(const double value)
      : s(value)
    {}

    void
    add(const double x)
    {
      const double t = s + x;
      c += (std::abs(s) >= std::abs(x)) ? (s - t) + x : (x - t) + s;
      s = t;
    }

    /// Add another compensated sum (its sum, then its correction): the
    /// merge of sums over consecutive ranges of terms.
    void
    add(const CompensatedSum &other)
    {
      add(other.s);
      c += other.c;
    }

    double
    sum() const
    {
      return s;
    }

    double
    correction() const
    {
      return c;
    }

    double
    value() const
    {
      return s + c;
    }

  private:
    double s = 0, c = 0;
  };



  /**
   * The value of each of @p sums (one per process) summed over the
   * processes of @p comm: the sums and the corrections are added over the
   * processes separately and then together, so the result is still
   * accurate to a rounding or two and does not depend on how the terms
   * were split.
   */
  inline std::vector<double>
  sum_over_processes(const std::vector<CompensatedSum> &sums,
                     const MPI_Comm                    &comm)
  {
    const unsigned int  n = sums.size();
    std::vector<double> local(2 * n), global(2 * n), values(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        local[k]     = sums[k].sum();
        local[n + k] = sums[k].correction();
      }
    dealii::Utilities::MPI::sum(dealii::make_array_view(std::as_const(local)),
                                comm,
                                dealii::make_array_view(global));
    for (unsigned int k = 0; k < n; ++k)
      values[k] = global[k] + global[n + k];
    return values;
  }



  /// As above, for one sum.
  inline double
  sum_over_processes(const CompensatedSum &sum, const MPI_Comm &comm)
  {
    const double local[2] = {sum.sum(), sum.correction()};
    double       global[2];
    dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(local, 2),
                                comm,
                                dealii::ArrayView<double>(global, 2));
    return global[0] + global[1];
  }
} // namespace fsgmpm

#endif
