#ifndef fsgmpm_base_format_h
#define fsgmpm_base_format_h

#include <deal.II/base/point.h>

#include <sstream>
#include <string>

namespace fsgmpm
{
  /// A number for a message, in the shortest form with 6 significant digits
  /// (std::to_string prints 1e300 with 301 digits and 1e-301 as 0.000000).
  inline std::string
  format(const double x)
  {
    std::ostringstream s;
    s << x;
    return s.str();
  }

  /// A point for a message: its coordinates separated by spaces.
  template <int dim>
  std::string
  format(const dealii::Point<dim> &p)
  {
    std::ostringstream s;
    s << p;
    return s.str();
  }
} // namespace fsgmpm

#endif
