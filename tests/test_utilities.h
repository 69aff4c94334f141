#ifndef fsgmpm_tests_test_utilities_h
#define fsgmpm_tests_test_utilities_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/scene/parameters.h>

#include <memory>
#include <string>

namespace fsgmpm
{
  namespace test_tools
  {
    /// A ParameterHandler with every fsgmpm parameter declared and the
    /// given prm text parsed (unknown entries throw, as for users).
    inline std::unique_ptr<dealii::ParameterHandler>
    make_parameters(const std::string &prm_text)
    {
      auto prm = std::make_unique<dealii::ParameterHandler>();
      Parameters<2>::declare_parameters(*prm);
      prm->parse_input_from_string(prm_text);
      return prm;
    }
  } // namespace test_tools
} // namespace fsgmpm

#endif
