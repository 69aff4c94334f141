// Termination = at_rest, the column shape and the runout / final_height
// monitors on a case with a known answer: an elastic column (Shape =
// column, width 0.4 m, aspect ratio 0.5, base at x = 0.3) standing
// stress-free on a fixed floor, loaded by gravity and locally damped, comes
// to rest as a block of the same size, so runout (from the wall x = 0) = 0.7 m
// and final_height = 0.2 m up to the elastic settlement (rho g H / M < 2e-3 of
// H) and half a point spacing (< 0.005 m); the run ends "at_rest" with a
// kinetic energy below 1e-6 of the initial potential energy for the convergence
// window (not at a single turning point of the bounce), measured on the grid
// motion (grid_kinetic_energy); the points' kinetic energy, which also holds
// the FLIP fluctuations that move nothing, is printed.

#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

using namespace fsgmpm;

namespace
{
  // An elastic column 0.4 m wide and 0.2 m high standing stress-free on a
  // fixed floor.
  const std::string column_on_a_floor = R"(
subsection Grid
  set Upper corner = 1, 0.4
  set Subdivisions = 40, 16
  set Boundary conditions = 0: roller, 1: roller, 2: fixed
end
subsection Bodies
  subsection Body 0
    set Shape = column
    set Column base corner = 0.3, 0
    set Column width = 0.4
    set Column aspect ratio = 0.5
    subsection Linear elastic
      set Young's modulus = 1e7
    end
  end
end
)";
} // namespace

TEST(AtRest, SettledColumnAndDepositMonitors)
{
  auto         prm = test_tools::make_parameters(R"(
subsection Simulation
  set End time = 5
  set Termination = at_rest
  set Rest tolerance = 1e-6
end
subsection Damping
  set Local damping coefficient = 0.5
end
subsection Monitors
  set Scene monitors = runout, final_height
end
)" + column_on_a_floor);
  Simulator<2> sim(*prm);
  double       x_min = 1, x_max = 0, y_min = 1, y_max = 0;
  for (const auto &x : sim.get_particles().position)
    {
      x_min = std::min(x_min, x[0]);
      x_max = std::max(x_max, x[0]);
      y_min = std::min(y_min, x[1]);
      y_max = std::max(y_max, x[1]);
    }
  // The column shape fills [0.3, 0.7] x [0, 0.2].
  EXPECT_GT(x_min, 0.3);
  EXPECT_LT(x_max, 0.7);
  EXPECT_GT(y_min, 0.);
  EXPECT_LT(y_max, 0.2);

  const double pe0 = sim.get_monitors().potential_energy;
  while (sim.advance())
    {}
  ASSERT_EQ(sim.get_termination(), fsgmpm::Termination::at_rest)
    << sim.get_diagnosis();
  const auto m = sim.get_scene_monitors();
  std::cout << "[ measured ] at rest after " << sim.get_time() << " s ("
            << sim.get_step() << " steps): runout " << m[0]
            << " m, final height " << m[1] << " m, kinetic energy "
            << sim.get_monitors().grid_kinetic_energy << " J/m (grid), "
            << sim.get_monitors().kinetic_energy << " J/m (points)"
            << std::endl;
  EXPECT_LT(sim.get_monitors().grid_kinetic_energy, 1e-6 * pe0);
  EXPECT_NEAR(m[0], 0.7, 0.005);
  EXPECT_NEAR(m[1], 0.2, 0.005);
}



// The potential energy during a gravity ramp is that of the gravity acting
// at the time (-sum m g(t).x, g(t) = g t / T), the field whose work the
// external work books; after the ramp that of the full gravity.
TEST(AtRest, PotentialEnergyFollowsTheGravityRamp)
{
  auto         prm = test_tools::make_parameters(R"(
subsection Simulation
  set End time = 0.3
  set Gravity ramp time = 0.2
end
)" + column_on_a_floor);
  Simulator<2> sim(*prm);
  const auto   potential = [&](const double g) {
    double e = 0;
    for (unsigned int p = 0; p < sim.get_particles().size(); ++p)
      e += sim.get_particles().mass[p] * g * sim.get_particles().position[p][1];
    return e;
  };
  EXPECT_EQ(sim.get_monitors().potential_energy, 0.);
  bool checked_ramp = false;
  while (sim.advance())
    if (!checked_ramp && sim.get_time() >= 0.1)
      {
        const double expected = potential(9.81 * sim.get_time() / 0.2);
        std::cout << "[ measured ] potential energy at " << sim.get_time()
                  << " s of a 0.2 s ramp: "
                  << sim.get_monitors().potential_energy << " J/m, -m g(t) y "
                  << expected << " J/m" << std::endl;
        EXPECT_NEAR(sim.get_monitors().potential_energy,
                    expected,
                    1e-12 * expected);
        checked_ramp = true;
      }
  EXPECT_TRUE(checked_ramp);
  EXPECT_NEAR(sim.get_monitors().potential_energy,
              potential(9.81),
              1e-12 * potential(9.81));
}
