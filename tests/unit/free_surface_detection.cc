// Free-surface detection in the volume-fraction form (paper
// Eqs. 31-33, f_c = 0.6), checked on the initial state of fluid bodies:
// (a) a column whose surface lies on a grid line has no flagged point;
// (b) with the surface at half a cell, flags appear only in the top cell
//     row (and there are some);
// (c) an isolated cluster smaller than one cell is flagged entirely;
// and a body with detection switched off has no flag; and the reset of
// flagged points books only energy a force stored in them.

#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

using namespace fsgmpm;

namespace
{
  std::unique_ptr<Simulator<2>>
  make(const std::string &lower,
       const std::string &upper,
       const unsigned int ppc,
       const std::string &extra = "")
  {
    static std::unique_ptr<ParameterHandler> prm;
    prm = test_tools::make_parameters(
      "subsection Grid\n  set Upper corner = 0.2, 0.6\n"
      "  set Subdivisions = 10, 30\nend\n"
      "subsection Bodies\n subsection Body 0\n"
      "  set Material model = Newtonian fluid\n"
      "  set Initial stress = hydrostatic\n"
      "  set Particles per cell = "
      + std::to_string(ppc) + "\n  set Box lower corner = " + lower
      + "\n  set Box upper corner = " + upper + "\n" + extra + " end\nend\n");
    return std::make_unique<Simulator<2>>(*prm);
  }
} // namespace

TEST(FreeSurfaceDetection, SurfaceOnGridLine)
{
  const auto   sim = make("0, 0", "0.2, 0.5", 4); // h = 0.02, 25 rows
  const auto  &ps  = sim->get_particles();
  unsigned int n   = 0;
  for (unsigned int p = 0; p < ps.size(); ++p)
    n += ps.free_surface[p];
  EXPECT_EQ(n, 0u);
  EXPECT_EQ(sim->get_monitors().free_surface_fraction, 0.);
}

TEST(FreeSurfaceDetection, SurfaceAtHalfCell)
{
  const auto   sim = make("0, 0", "0.2, 0.49", 16); // top row half full
  const auto  &ps  = sim->get_particles();
  unsigned int top = 0, below = 0;
  for (unsigned int p = 0; p < ps.size(); ++p)
    if (ps.free_surface[p])
      (ps.position[p][1] >= 0.48 ? top : below) += 1;
  std::cout << "[ measured ] surface at half a cell: " << top
            << " flagged in the top row, " << below << " below" << std::endl;
  EXPECT_GT(top, 0u);
  EXPECT_EQ(below, 0u);
}

TEST(FreeSurfaceDetection, IsolatedClusterSmallerThanACell)
{
  // A 0.012 x 0.012 cluster (cells are 0.02) in the middle of the tank.
  const auto  sim = make("0.104, 0.304", "0.116, 0.316", 64);
  const auto &ps  = sim->get_particles();
  ASSERT_GT(ps.size(), 3u);
  for (unsigned int p = 0; p < ps.size(); ++p)
    EXPECT_EQ(ps.free_surface[p], 1) << "point at " << ps.position[p];
  EXPECT_EQ(sim->get_monitors().free_surface_fraction, 1.);
  // Flagged points carry zero pressure.
  for (unsigned int p = 0; p < ps.size(); ++p)
    EXPECT_NEAR(trace(ps.stress[p]), 0., 1e-12);
}

TEST(FreeSurfaceDetection, SwitchedOff)
{
  const auto  sim = make("0.104, 0.304",
                        "0.116, 0.316",
                        64,
                        "  set Free surface detection = false\n");
  const auto &ps  = sim->get_particles();
  for (unsigned int p = 0; p < ps.size(); ++p)
    EXPECT_EQ(ps.free_surface[p], 0);
}

// The reset of a flagged point (zero pressure, volume back to the
// reference) books as lost only the energy a nodal force stored in the
// point. A cluster smaller than a cell is flagged at every step, so it is
// a pressureless dust: no force ever acts on its volume, and the energy its
// volume ratio holds after a step's update (the explicit update's lag,
// about K (tr d dt)^2 V / 2 per point) is created and removed within the
// step. The cluster falls onto the roller floor at 1 m/s in zero gravity
// and is slowed by it (until 0.019 s, when it has packed enough that
// points are no longer flagged): kinetic energy is lost, nothing is stored,
// and the reset books nothing. With each stress integration: NMD's
// averages leave flagged points out, so a cluster of them keeps its
// volumes; with the nodal projection they follow the projected rate and
// hold the lag until the reset.
TEST(FreeSurfaceDetection, ResetOfAPointFlaggedThroughoutBooksNothing)
{
  for (const std::string integration : {"points", "nodal projection"})
    {
      const auto   prm = test_tools::make_parameters(R"(
subsection Simulation
  set End time = 0.019
  set Gravity  = 0, 0
  set Stress integration = )" + integration + R"(
end
subsection Grid
  set Upper corner = 0.2, 0.6
  set Subdivisions = 10, 30
end
subsection Bodies
  subsection Body 0
    set Material model    = Newtonian fluid
    set Particles per cell = 64
    set Box lower corner  = 0.104, 0.024
    set Box upper corner  = 0.116, 0.036
    set Initial velocity  = 0, -1
    subsection Newtonian fluid
      set Bulk modulus = 2.5e6
    end
  end
end
subsection Output
  set Directory       = output_free_surface_reset
  set Output interval = 0
  set Quiet           = true
end
)");
      Simulator<2> sim(*prm);
      const double kinetic_0 = sim.get_monitors().kinetic_energy;
      unsigned int steps     = 0;
      while (sim.advance())
        {
          ++steps;
          ASSERT_EQ(sim.get_monitors().free_surface_fraction, 1.)
            << integration << ", at step " << steps;
        }
      const auto &m = sim.get_monitors();
      std::cout << "[ measured ] pressureless cluster on the floor, "
                << integration << ", after " << steps
                << " steps: kinetic energy " << m.kinetic_energy << " of "
                << kinetic_0 << " J/m, strain energy " << m.strain_energy
                << ", booked reset " << m.numerical_dissipation << std::endl;
      // The guard saw no energy created (it stopped the nodal projection's
      // run at step 72 when the reset booked the lag), the floor slowed the
      // cluster, and it holds no stored energy.
      EXPECT_EQ(sim.get_termination(), Termination::end_time) << integration;
      EXPECT_LT(m.kinetic_energy, 0.8 * kinetic_0);
      EXPECT_EQ(m.strain_energy, 0.);
      // The reset booked nothing: no force stored energy in a flagged point.
      EXPECT_EQ(m.numerical_dissipation, 0.);
    }
}
