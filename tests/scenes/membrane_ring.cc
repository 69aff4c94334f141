// Pressurised membrane ring (Laplace law; membrane note T2): a closed 2D
// membrane of radius 0.5 m, pre-strained by 1%, squeezes the fluid disc it
// encloses (no gravity) until the fluid pressure p balances the tension T.
// Reference: T = p R for a circle of radius R (R from the enclosed area),
// independent of the grid, the fluid model and the smoothing.
// Asserts, for Volumetric smoothing = none and NMD+ANP after 1 s:
//   (1) mean tension within 3% of p R (p: mean point pressure);
//   (2) the ring stays circular: |height/width - 1| < 1e-3;
//   (3) no fluid point outside the membrane, none lost, energy finite;
//   (4) without smoothing, the kinetic energy has decayed below 1e-3 of the
//       initial membrane strain energy. With NMD+ANP it is printed, not
//       asserted: a residual stirring of the enclosed fluid (KE/W0 = 1.4e-3
//       at 1 s) is a known open defect of NMD next to the membrane (it also
//       keeps the geotube from converging; doc/membrane_validation.md).

#include <fsgmpm/monitors/geotube_monitor.h>
#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

#include <cmath>
#include <cstdio>
#include <sstream>

using namespace fsgmpm;

namespace
{
  constexpr double R0 = 0.5, EA = 1e5, eps0 = 0.01;

  std::string
  ring_prm(const std::string &smoothing)
  {
    std::ostringstream polygon;
    polygon.precision(12);
    for (unsigned int k = 0; k < 48; ++k)
      polygon << (k ? "; " : "") << 1 + R0 * std::cos(2 * M_PI * k / 48) << ", "
              << 1 + R0 * std::sin(2 * M_PI * k / 48);
    return "subsection Simulation\n  set End time = 1.0\n"
           "  set Gravity = 0, 0\nend\n"
           "subsection Damping\n  set Local damping coefficient = 0.3\nend\n"
           "subsection Grid\n  set Lower corner = 0, 0\n"
           "  set Upper corner = 2, 2\n  set Cell size = 0.05\n"
           "  set Boundary conditions = 0: roller\nend\n"
           "subsection Membrane\n  set Enabled = true\n"
           "  set Shape = polygon\n  set Polygon vertices = "
           + polygon.str() + "\n  set Axial stiffness = " + std::to_string(EA)
           + "\n  set Initial strain = " + std::to_string(eps0)
           + "\nend\n"
             "subsection Bodies\n subsection Body 0\n"
             "  set Shape = membrane\n  set Density = 1000\n"
             "  set Material model = Newtonian fluid\n"
             "  set Free surface detection = false\n"
             "  set Volumetric smoothing = "
           + smoothing
           + "\n  subsection Newtonian fluid\n    set Bulk modulus = 2e6\n"
             "    set Viscosity = 1\n  end\n end\nend\n"
             "subsection Output\n  set Directory = output_membrane_ring\n"
             "  set Quiet = true\nend\n";
  }

  void
  check(const std::string &smoothing)
  {
    auto         prm = test_tools::make_parameters(ring_prm(smoothing));
    Simulator<2> sim(*prm);
    const double initial_strain_energy = sim.get_monitors().strain_energy;
    while (sim.advance())
      ;
    ASSERT_EQ(sim.get_termination(), fsgmpm::Termination::end_time)
      << sim.get_diagnosis();
    const auto &membrane  = *sim.get_membrane();
    const auto &particles = sim.get_particles();
    const auto  m         = membrane_monitors(membrane, particles, 0.005, 0.1);

    double p = 0;
    for (unsigned int q = 0; q < particles.size(); ++q)
      p -= trace(particles.stress[q]) / 3. / particles.size();
    const double R = std::sqrt(m.at("enclosed_area") / M_PI);
    const double T = m.at("mean_tension");
    std::printf("measured %s: mean tension %.2f N/m, p R = %.2f N/m "
                "(error %.3f%%), height/width - 1 = %.2e, KE/W0 = %.2e, "
                "outside %g\n",
                smoothing.c_str(),
                T,
                p * R,
                100 * (T / (p * R) - 1),
                m.at("height") / m.at("width") - 1,
                sim.get_monitors().kinetic_energy / initial_strain_energy,
                m.at("particles_outside"));
    EXPECT_NEAR(T / (p * R), 1., 0.03);
    EXPECT_LT(std::abs(m.at("height") / m.at("width") - 1), 1e-3);
    EXPECT_EQ(m.at("particles_outside"), 0.);
    EXPECT_EQ(sim.get_monitors().lost_particles, 0u);
    if (smoothing == "none")
      {
        EXPECT_LT(sim.get_monitors().kinetic_energy,
                  1e-3 * initial_strain_energy);
      }
  }
} // namespace

TEST(MembraneRing, LaplaceLawWithoutSmoothing)
{
  check("none");
}

TEST(MembraneRing, LaplaceLawWithNmdAnp)
{
  check("NMD+ANP");
}
