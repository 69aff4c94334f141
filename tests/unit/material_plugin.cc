// Material models are plug-ins: a program registers its own
// model in its own source file with FSGMPM_REGISTER_MATERIAL, and a body
// selects it by name. This file registers "test elastic", a linear elastic
// material that counts its stress updates and reads its constants from its
// own subsection. A block dropped with it must move exactly as with the
// built-in "linear elastic" of the same constants (same arithmetic, so the
// positions and stresses agree to the last bit), the plug-in must have been
// called, and bad registrations must be refused with a clear error.

#include <gtest/gtest.h>

#include <fsgmpm/materials/linear_elastic.h>
#include <fsgmpm/materials/material_factory.h>
#include <fsgmpm/simulator.h>

#include <atomic>

#include "test_utilities.h"

namespace fsgmpm
{
  namespace
  {
    std::atomic<unsigned long> test_elastic_updates{0};

    class TestElastic : public LinearElastic
    {
    public:
      using LinearElastic::LinearElastic;

      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Test elastic");
        prm.declare_entry("Young's modulus", "1e6", Patterns::Double(0));
        prm.declare_entry("Poisson's ratio", "0.3", Patterns::Double(-1, 0.5));
        prm.leave_subsection();
      }

      static std::unique_ptr<TestElastic>
      create(ParameterHandler &prm, const double density, const std::string &)
      {
        prm.enter_subsection("Test elastic");
        auto material
          = std::make_unique<TestElastic>(prm.get_double("Young's modulus"),
                                          prm.get_double("Poisson's ratio"),
                                          density);
        prm.leave_subsection();
        return material;
      }

      std::string
      name() const override
      {
        return "test elastic";
      }

      void
      update_stresses(const PointKinematics *kinematics,
                      SymmetricTensor<2, 3> *stress,
                      const unsigned int     n,
                      const double           dt) const override
      {
        test_elastic_updates += n;
        LinearElastic::update_stresses(kinematics, stress, n, dt);
      }
    };
  } // namespace

  FSGMPM_REGISTER_MATERIAL(TestElastic,
                           "test elastic",
                           "linear elastic, counting its updates (test)")

  namespace
  {
    std::string
    block_drop(const std::string &model, const std::string &subsection)
    {
      return R"(
subsection Simulation
  set Dimension = 2
  set End time  = 0.05
  set Gravity   = 0, -9.81
end
subsection Grid
  set Type                = box
  set Lower corner        = 0, 0
  set Upper corner        = 1, 0.6
  set Subdivisions        = 20, 12
  set Boundary conditions = 0: roller, 1: roller, 2: roller, 3: free
end
subsection Bodies
  set Number of bodies = 1
  subsection Body 0
    set Shape            = box
    set Box lower corner = 0.3, 0.05
    set Box upper corner = 0.7, 0.25
    set Density          = 1000
    set Material model   = )"
             + model + R"(
    subsection )"
             + subsection + R"(
      set Young's modulus = 2e5
      set Poisson's ratio = 0.25
    end
  end
end
subsection Output
  set Directory       = output_material_plugin
  set Output interval = 1
  set Quiet           = true
end
)";
    }
  } // namespace

  TEST(MaterialPlugin, RegisteredModelIsSelectableAndUsed)
  {
    const auto names = MaterialFactory::names();
    EXPECT_NE(std::find(names.begin(), names.end(), "test elastic"),
              names.end());
    for (const std::string builtin :
         {"linear elastic", "Mohr-Coulomb", "Newtonian fluid"})
      EXPECT_NE(std::find(names.begin(), names.end(), builtin), names.end())
        << builtin;

    auto plugin_prm
      = test_tools::make_parameters(block_drop("test elastic", "Test elastic"));
    auto builtin_prm = test_tools::make_parameters(
      block_drop("linear elastic", "Linear elastic"));
    Simulator<2> plugin(*plugin_prm), builtin(*builtin_prm);
    EXPECT_EQ(test_elastic_updates, 0u);
    while (plugin.advance())
      ;
    while (builtin.advance())
      ;
    EXPECT_EQ(plugin.get_termination(), fsgmpm::Termination::end_time);
    EXPECT_GT(test_elastic_updates, 0u);

    const auto &a = plugin.get_particles();
    const auto &b = builtin.get_particles();
    ASSERT_EQ(a.size(), b.size());
    double max_position = 0, max_stress = 0, max_sag = 0;
    for (unsigned int p = 0; p < a.size(); ++p)
      {
        max_position
          = std::max(max_position, (a.position[p] - b.position[p]).norm());
        max_stress = std::max(max_stress, (a.stress[p] - b.stress[p]).norm());
        max_sag    = std::max(max_sag, std::abs(a.stress[p][1][1]));
      }
    std::cout << "plug-in against built-in: max position difference "
              << max_position << " m, max stress difference " << max_stress
              << " Pa (largest |sigma_yy| " << max_sag << " Pa), "
              << test_elastic_updates << " point updates by the plug-in"
              << std::endl;
    EXPECT_EQ(max_position, 0.);
    EXPECT_EQ(max_stress, 0.);
    // The block is loaded: the comparison is not between two empty states.
    EXPECT_GT(max_sag, 100.);
  }

  TEST(MaterialPlugin, BadRegistrationsAreRefused)
  {
    const auto declare = [](ParameterHandler &) {};
    const auto create  = [](ParameterHandler &, double, const std::string &)
      -> std::unique_ptr<Material> { return nullptr; };
    EXPECT_THROW(MaterialFactory::register_material(
                   "test elastic", "a second one", declare, create),
                 ExceptionBase);
    EXPECT_THROW(
      MaterialFactory::register_material("a|b", "bad name", declare, create),
      ExceptionBase);
    EXPECT_THROW(
      MaterialFactory::register_material("", "no name", declare, create),
      ExceptionBase);
    ParameterHandler prm;
    EXPECT_THROW(MaterialFactory::create("no such model", prm, 1000., "Body 0"),
                 ExceptionBase);
  }
} // namespace fsgmpm
