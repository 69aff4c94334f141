// Material points that leave the mesh are removed, counted in
// lost_particles and reported, never silently dropped. A stress-free block
// translating at constant velocity (no gravity) through a free boundary:
// exactly the points with x0 + v T > x_max must be lost. And when every
// point has left, the run ends with termination "error", not a crash.

#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

using namespace fsgmpm;

namespace
{
  std::string
  scene(const double end_time)
  {
    return R"(
subsection Simulation
  set Gravity = 0, 0
  set End time = )"
           + std::to_string(end_time) + R"(
end
subsection Grid
  set Upper corner = 1, 0.5
  set Subdivisions = 20, 10
  set Boundary conditions = 2: roller
end
subsection Bodies
  subsection Body 0
    set Box lower corner = 0.8, 0.1
    set Box upper corner = 0.95, 0.3
    set Initial velocity = 2, 0
  end
end
)";
  }
} // namespace

TEST(LostParticles, CountedExactly)
{
  const double T = 0.04, v = 2.0;
  auto         prm = test_tools::make_parameters(scene(T));
  Simulator<2> sim(*prm);
  unsigned int expected = 0;
  for (const auto &x : sim.get_particles().position)
    expected += (x[0] + v * T > 1.0 + 1e-12);
  const unsigned int n0 = sim.get_particles().size();
  while (sim.advance())
    {}
  EXPECT_EQ(sim.get_termination(), fsgmpm::Termination::end_time);
  std::cout << "[ measured ] lost " << sim.get_monitors().lost_particles
            << " of " << n0 << " points, expected " << expected << std::endl;
  EXPECT_GT(expected, 0u);
  EXPECT_EQ(sim.get_monitors().lost_particles, expected);
  EXPECT_EQ(sim.get_particles().size() + expected, n0);
}

TEST(LostParticles, AllLostEndsWithError)
{
  auto               prm = test_tools::make_parameters(scene(1.0));
  Simulator<2>       sim(*prm);
  const unsigned int n0 = sim.get_particles().size();
  while (sim.advance())
    {}
  EXPECT_EQ(sim.get_termination(), fsgmpm::Termination::error);
  EXPECT_EQ(sim.get_monitors().lost_particles, n0);
  EXPECT_NE(sim.get_diagnosis().find("no material point"), std::string::npos);
}
