// The energy-creation guard (Stability/Energy creation tolerance): a slow
// instability that the kinetic-energy growth window (10x in 100 steps)
// cannot see must still stop the run as unstable. An elastic block sliding
// without gravity on a roller floor gets its point velocities scaled by
// 1.01 after every step (an artificial energy pump: kinetic energy 7.2x
// per 100 steps).
// Asserts: with the default tolerance 0.5 the run stops as "unstable" with
// the energy-creation diagnosis once the created energy exceeds half the
// energy put in (after about 20 steps: 1.01^(2n) > 1.5); with the guard
// switched off (0) the same run reaches its end time, i.e. the growth
// window alone misses it; and without the pump, the guard stays silent.

#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

using namespace fsgmpm;

namespace
{
  std::string
  scene(const double tolerance)
  {
    return R"(
subsection Simulation
  set Gravity = 0, 0
  set Maximum number of steps = 300
  set End time = 10
end
subsection Stability
  set Energy creation tolerance = )"
           + std::to_string(tolerance) + R"(
end
subsection Grid
  set Upper corner = 2, 0.5
  set Subdivisions = 40, 10
  set Boundary conditions = 2: roller
end
subsection Bodies
  subsection Body 0
    set Box lower corner = 0.2, 0
    set Box upper corner = 0.6, 0.2
    set Initial velocity = 1, 0
  end
end
)";
  }

  // Run the scene, scaling the point velocities by @p pump after each step.
  std::unique_ptr<Simulator<2>>
  run(const double tolerance, const double pump)
  {
    auto prm = test_tools::make_parameters(scene(tolerance));
    auto sim = std::make_unique<Simulator<2>>(*prm);
    while (sim->advance())
      for (auto &v : sim->get_particles().velocity)
        v *= pump;
    return sim;
  }
} // namespace

TEST(EnergyGuard, StopsASlowInstability)
{
  const auto sim = run(0.5, 1.01);
  std::cout << "[ measured ] stopped at step " << sim->get_step() << ": "
            << sim->get_diagnosis() << std::endl;
  EXPECT_EQ(sim->get_termination(), fsgmpm::Termination::unstable);
  EXPECT_NE(sim->get_diagnosis().find("creating energy"), std::string::npos);
  EXPECT_LT(sim->get_step(), 100u);
}

TEST(EnergyGuard, GrowthWindowAloneMissesIt)
{
  const auto sim = run(0, 1.01);
  EXPECT_EQ(sim->get_step(), 300u) << sim->get_diagnosis();
  EXPECT_NE(sim->get_termination(), fsgmpm::Termination::unstable);
}

TEST(EnergyGuard, SilentWithoutThePump)
{
  const auto sim = run(0.5, 1.0);
  EXPECT_EQ(sim->get_step(), 300u) << sim->get_diagnosis();
  EXPECT_NE(sim->get_termination(), fsgmpm::Termination::unstable);
}
