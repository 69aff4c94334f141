// Simulation/FLIP noise relaxation time (the FLIP-PIC blend of
// source/step/g2p.cc, beta = 1 - exp(-dt/tau) per step): the part of the
// points' velocity that the grid does not see decays over tau, whatever the
// time step, and resolved motion is left alone.
// A water block (no gravity, 4 points per cell) moves at 0.5 m/s in x, and
// every point carries a random velocity of up to 0.2 m/s on top. The
// sub-cell kinetic energy (points' minus grid's, monitors kinetic_energy
// and grid_kinetic_energy) is measured after 5 ms:
// - tau = 1 ms: it falls to 0.0054 of its start (asserted below 0.02; the
//   blend alone would give exp(-2 t/tau) = 4.5e-5 for noise the grid never
//   sees, but the pressure waves of the block keep feeding new noise);
// - tau = 0 (pure FLIP): it stays at 0.98 (asserted above 0.5);
// - the mean velocity is kept to 1e-12 (m/s) in both: the blend conserves
//   momentum (sum_p m_p v(x_p) is the grid momentum).

#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

#include <random>

using namespace fsgmpm;

namespace
{
  struct Result
  {
    double subcell_ratio, momentum_change;
  };

  Result
  run(const double tau)
  {
    auto         prm = test_tools::make_parameters(R"(
subsection Simulation
  set Gravity = 0, 0
  set End time = 0.005
  set FLIP noise relaxation time = )" + std::to_string(tau)
                                           + R"(
end
subsection Grid
  set Upper corner = 1, 1
  set Subdivisions = 20, 20
  set Boundary conditions = 0: free
end
subsection Bodies
  subsection Body 0
    set Box lower corner = 0.3, 0.3
    set Box upper corner = 0.7, 0.7
    set Material model = Newtonian fluid
    set Density = 1000
    set Free surface detection = false
    subsection Newtonian fluid
      set Bulk modulus = 1e6
      set Allow tension = true
    end
  end
end
subsection Output
  set Quiet = true
  set Directory = output_flip_noise_relaxation
end
)");
    Simulator<2> sim(*prm);
    auto        &particles = sim.get_particles();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    for (auto &v : particles.velocity)
      {
        v[0] = 0.5 + u(random);
        v[1] = u(random);
      }
    const auto mean_vx = [&] {
      double mass = 0, momentum = 0;
      for (unsigned int p = 0; p < particles.size(); ++p)
        {
          mass += particles.mass[p];
          momentum += particles.mass[p] * particles.velocity[p][0];
        }
      return momentum / mass;
    };
    const double vx0 = mean_vx();
    // The first step measures both energies of the perturbed state.
    sim.advance();
    const auto  &m0       = sim.get_monitors();
    const double subcell0 = m0.kinetic_energy - m0.grid_kinetic_energy;
    while (sim.advance())
      {}
    const auto &m = sim.get_monitors();
    return {(m.kinetic_energy - m.grid_kinetic_energy) / subcell0,
            mean_vx() - vx0};
  }
} // namespace

TEST(FlipNoiseRelaxation, SubcellNoiseDecaysOverTau)
{
  const Result blended = run(1e-3), flip = run(0);
  std::cout << "sub-cell kinetic energy after 5 ms: " << blended.subcell_ratio
            << " (tau = 1 ms), " << flip.subcell_ratio << " (FLIP)"
            << std::endl;
  EXPECT_LT(blended.subcell_ratio, 0.02);
  EXPECT_GT(flip.subcell_ratio, 0.5);
  EXPECT_LT(std::abs(blended.momentum_change), 1e-12);
  EXPECT_LT(std::abs(flip.momentum_change), 1e-12);
}
