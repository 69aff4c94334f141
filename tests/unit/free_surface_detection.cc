// Free-surface detection in the volume-fraction form (paper
// Eqs. 31-33, f_c = 0.6), checked on the initial state of fluid bodies:
// (a) a column whose surface lies on a grid line has no flagged point;
// (b) with the surface at half a cell, flags appear only in the top cell
//     row (and there are some);
// (c) an isolated cluster smaller than one cell is flagged entirely;
// and a body with detection switched off has no flag.

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
