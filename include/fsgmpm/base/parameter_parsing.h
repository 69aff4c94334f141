#ifndef fsgmpm_base_parameter_parsing_h
#define fsgmpm_base_parameter_parsing_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * Parsing helpers for parameter values that deal.II's patterns cannot
   * check, shared by the components that declare and parse their own
   * subsections (bodies, shapes, membrane, Parameters). Every error names
   * the full parameter path.
   */

  /// Read a list of dim doubles, throwing a message that names @p path.
  template <int dim>
  Tensor<1, dim>
  parse_vector(const std::string &text, const std::string &path);

  /// Read a closed 2D polygon 'x0, y0; x1, y1; ...' (at least three
  /// vertices), throwing a message that names @p path.
  std::vector<Point<2>>
  parse_polygon(const std::string &text, const std::string &path);

  /// A length that may be "auto": @p fallback for auto, else a finite
  /// number within +-1e9, throwing a message that names @p path.
  double
  parse_auto_or_double(const std::string &text,
                       const double       fallback,
                       const std::string &path);

  /// The dimension requested by Simulation/Dimension.
  unsigned int
  get_dimension(ParameterHandler &prm);
} // namespace fsgmpm

#endif
