#ifndef fsgmpm_tests_test_utilities_h
#define fsgmpm_tests_test_utilities_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/mesh_generation.h>
#include <fsgmpm/scene/parameters.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fsgmpm
{
  namespace test_tools
  {
    /// The unit square or cube split into n^dim boxes of simplices.
    template <int dim>
    void
    make_unit_box(const unsigned int n, dealii::Triangulation<dim> &tria)
    {
      dealii::Point<dim> upper;
      for (unsigned int d = 0; d < dim; ++d)
        upper[d] = 1;
      MeshGeneration::make_box<dim>(dealii::Point<dim>(),
                                    upper,
                                    std::vector<unsigned int>(dim, n),
                                    tria);
    }

    /// A BackgroundGrid on make_unit_box().
    template <int dim>
    std::unique_ptr<BackgroundGrid<dim>>
    make_unit_box_grid(const unsigned int n)
    {
      dealii::Triangulation<dim> tria;
      make_unit_box(n, tria);
      return std::make_unique<BackgroundGrid<dim>>(std::move(tria));
    }

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

#ifdef FSGMPM_TEST_SOURCE_DIR
    /// make_parameters() of a scene file shipped in prm/ (path relative to
    /// the repository's prm directory), for tests that run a shipped scene.
    inline std::unique_ptr<dealii::ParameterHandler>
    make_parameters_from_scene(const std::string &prm_file)
    {
      std::ifstream in(std::string(FSGMPM_TEST_SOURCE_DIR) + "/../prm/"
                       + prm_file);
      if (!in)
        throw std::runtime_error("cannot read prm/" + prm_file);
      std::ostringstream text;
      text << in.rdbuf();
      return make_parameters(text.str());
    }
#endif
  } // namespace test_tools
} // namespace fsgmpm

#endif
