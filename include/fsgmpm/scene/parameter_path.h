#ifndef fsgmpm_scene_parameter_path_h
#define fsgmpm_scene_parameter_path_h

#include <deal.II/base/parameter_handler.h>

#include <boost/property_tree/ptree.hpp>

#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace fsgmpm
{
  /**
   * Set the parameter at @p path ("Section/Sub/Name", as fsgmpm --set
   * takes it) to @p value, leaving the handler at the subsection it was
   * in. Throws a message naming the path for an undeclared parameter or a
   * value its pattern refuses.
   */
  void
  set_parameter(dealii::ParameterHandler &prm,
                const std::string        &path,
                const std::string        &value);

  /**
   * The same for a number, written with 17 significant digits: converting
   * it with std::to_string would keep 6 decimals, so that 1e-7 became 0.
   */
  inline void
  set_parameter(dealii::ParameterHandler &prm,
                const std::string        &path,
                const double              value)
  {
    std::ostringstream text;
    text << std::setprecision(17) << value;
    set_parameter(prm, path, text.str());
  }

  /// Undo ParameterHandler's name mangling in its JSON output ("_20" for a
  /// space, "_27" for an apostrophe, ...).
  std::string
  demangle_parameter_name(const std::string &name);

  /// Every parameter of @p prm as a tree (ParameterHandler's JSON, in
  /// declaration order; names mangled, see demangle_parameter_name()).
  boost::property_tree::ptree
  parameter_tree(const dealii::ParameterHandler &prm);

  /**
   * Every parameter of @p prm with its current value, as ("Section/Sub/Name",
   * value) in declaration order (the paths --set takes).
   */
  std::vector<std::pair<std::string, std::string>>
  parameter_values(const dealii::ParameterHandler &prm);
} // namespace fsgmpm

#endif
