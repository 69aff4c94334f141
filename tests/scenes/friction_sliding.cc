// A block sliding on a Coulomb-friction floor under gravity decelerates at
// mu g (rigid-body reference). Initial velocity 1 m/s, mu = 0.3: the
// mean velocity falls linearly and the block stops at t = v0/(mu g).
// Asserts: the deceleration fitted over 0.05 s < t < 0.25 s is within 5%
// of mu g, and the block is at rest (|v| < 2% of v0) after the stop time.

#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

using namespace fsgmpm;

TEST(FrictionWall, SlidingBlockDeceleratesAtMuG)
{
  const double mu = 0.3, g = 9.81, v0 = 1.0;
  auto         prm = test_tools::make_parameters(R"(
subsection Simulation
  set End time = 0.45
end
subsection Grid
  set Upper corner = 1, 0.25
  set Subdivisions = 40, 10
  set Boundary conditions = 0: roller, 1: roller, 2: friction 0.3
end
subsection Bodies
  subsection Body 0
    set Box lower corner = 0.1, 0
    set Box upper corner = 0.4, 0.1
    set Initial velocity = 1, 0
    set Initial stress = geostatic
    set K0 = 0.428571428571
    subsection Linear elastic
      set Young's modulus = 1e7
    end
  end
end
)");
  Simulator<2> sim(*prm);
  const auto  &particles = sim.get_particles();
  // Least-squares slope of the mean x-velocity against time.
  double st = 0, sv = 0, stt = 0, stv = 0, n = 0, v_end = 0;
  while (sim.advance())
    {
      double m = 0, mv = 0;
      for (unsigned int p = 0; p < particles.size(); ++p)
        {
          m += particles.mass[p];
          mv += particles.mass[p] * particles.velocity[p][0];
        }
      const double t = sim.get_time(), v = mv / m;
      if (t > 0.05 && t < 0.25)
        {
          st += t;
          sv += v;
          stt += t * t;
          stv += t * v;
          n += 1;
        }
      v_end = v;
    }
  ASSERT_EQ(sim.get_termination(), fsgmpm::Termination::end_time)
    << sim.get_diagnosis();
  const double slope = (n * stv - st * sv) / (n * stt - st * st);
  std::cout << "[ measured ] deceleration " << -slope
            << " m/s^2 (mu g = " << mu * g << ", error "
            << 100 * (-slope / (mu * g) - 1)
            << " %), velocity at t = 0.45 s: " << v_end << " m/s" << std::endl;
  EXPECT_NEAR(-slope / (mu * g), 1.0, 0.05);
  EXPECT_LT(std::abs(v_end), 0.02 * v0);
}
