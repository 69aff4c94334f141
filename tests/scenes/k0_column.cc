// A Mohr-Coulomb soil column (phi = 30 deg, c = 0, rho = 1500) initialised
// with the K0 = 0.5 geostatic stress under gravity on a fixed base with
// roller sides: over 1000 steps sigma_xx/sigma_yy (and sigma_zz/sigma_yy)
// stays at 0.5 within 2% (layer means, top and bottom cell rows excluded).

#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

#include <map>

using namespace fsgmpm;

TEST(K0Column, LateralStressRatioIsKept)
{
  const double H = 1.0, h = 0.05;
  auto         prm = test_tools::make_parameters(R"(
subsection Simulation
  set End time = 10
  set Maximum number of steps = 1000
end
subsection Grid
  set Upper corner = 0.2, 1.2
  set Subdivisions = 4, 24
  set Boundary conditions = 0: roller, 1: roller, 2: fixed
end
subsection Bodies
  subsection Body 0
    set Material model = Mohr-Coulomb
    set Density = 1500
    set Initial stress = geostatic
    set K0 = 0.5
    set Box lower corner = 0, 0
    set Box upper corner = 0.2, 1.0
    subsection Mohr-Coulomb
      set Young's modulus = 5e6
      set Poisson's ratio = 0.3
      set Friction angle = 30
      set Cohesion = 0
    end
  end
end
)");
  Simulator<2> sim(*prm);
  while (sim.advance())
    {}
  ASSERT_EQ(sim.get_termination(), "end_time") << sim.get_diagnosis();
  EXPECT_EQ(sim.get_step(), 1000u);
  const auto                                   &ps = sim.get_particles();
  std::map<unsigned int, std::array<double, 3>> layers;
  for (unsigned int p = 0; p < ps.size(); ++p)
    {
      const double y = ps.position[p][1];
      if (y < h || y > H - h)
        continue;
      auto &l = layers[static_cast<unsigned int>(y / h)];
      l[0] += ps.stress[p][0][0];
      l[1] += ps.stress[p][1][1];
      l[2] += ps.stress[p][2][2];
    }
  double worst = 0;
  for (const auto &[row, l] : layers)
    worst = std::max({worst,
                      std::abs(l[0] / l[1] / 0.5 - 1),
                      std::abs(l[2] / l[1] / 0.5 - 1)});
  std::cout << "[ measured ] K0 column: " << layers.size()
            << " layers, worst |ratio/0.5 - 1| = " << 100 * worst
            << " % after 1000 steps, kinetic energy "
            << sim.get_monitors().kinetic_energy << " J/m" << std::endl;
  EXPECT_LT(worst, 0.02);
}
