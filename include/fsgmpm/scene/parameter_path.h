#ifndef fsgmpm_scene_parameter_path_h
#define fsgmpm_scene_parameter_path_h

#include <deal.II/base/parameter_handler.h>

#include <string>

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
} // namespace fsgmpm

#endif
