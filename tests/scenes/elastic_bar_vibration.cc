// Axial vibration of a fixed-free elastic bar (nu = 0, 20 cells along the
// length, strain amplitude 1e-4), 2D triangles and 3D tetrahedra.
// Reference: first mode of the 1D wave equation, period T = 4 L / sqrt(E/rho),
// velocity field v(x, t) = v0 sin(pi x / 2L) cos(2 pi t / T).
// Asserts: first period within 2% of T; total energy (kinetic + strain)
// drift below 2% over five periods.

#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

using namespace fsgmpm;

namespace
{
  constexpr double L = 1.0, E = 1e6, rho = 1000.;

  template <int dim>
  void
  run_bar(const std::string &scheme, const std::string &integration = "points")
  {
    const double c   = std::sqrt(E / rho);
    const double T   = 4 * L / c;
    const double v0  = 1e-4 * c; // strain amplitude v0/c = 1e-4
    std::string  prm = "subsection Simulation\n"
                       "  set Dimension = "
                      + std::to_string(dim)
                      + "\n"
                        "  set End time = "
                      + std::to_string(5.2 * T)
                      + "\n"
                        "  set Gravity = 0, 0\n"
                        "  set Courant number = 0.5\n"
                        "  set Update scheme = "
                      + scheme
                      + "\n"
                        "  set Stress integration = "
                      + integration
                      + "\n"
                        "end\n"
                        "subsection Grid\n";
    if (dim == 2)
      prm += "  set Lower corner = 0, 0\n  set Upper corner = 1.2, 0.1\n"
             "  set Subdivisions = 24, 2\n"
             "  set Boundary conditions = 0: roller, 2: roller, 3: roller\n";
    else
      prm
        += "  set Lower corner = 0, 0, 0\n  set Upper corner = 1.2, 0.1, 0.1\n"
           "  set Subdivisions = 24, 2, 2\n"
           "  set Boundary conditions = 0: roller, 2: roller, 3: roller, "
           "4: roller, 5: roller\n";
    prm += "end\n"
           "subsection Bodies\n subsection Body 0\n"
           "  set Box lower corner = 0, 0"
           + std::string(dim == 3 ? ", 0" : "")
           + "\n  set Box upper corner = 1, 0.1"
           + std::string(dim == 3 ? ", 0.1" : "")
           + "\n  set Particles per cell = " + (dim == 2 ? "4" : "8")
           + "\n  set Density = 1000\n"
             "  subsection Linear elastic\n   set Young's modulus = 1e6\n"
             "   set Poisson's ratio = 0\n  end\n end\nend\n";
    auto           parameters = test_tools::make_parameters(prm);
    Simulator<dim> sim(*parameters);
    auto          &particles = sim.get_particles();
    for (unsigned int p = 0; p < particles.size(); ++p)
      {
        particles.velocity[p] = Tensor<1, dim>();
        particles.velocity[p][0]
          = v0 * std::sin(M_PI * particles.position[p][0] / (2 * L));
      }
    sim.reinitialize_state();
    const double E0 = sim.get_monitors().kinetic_energy;

    // Zero crossings of the total x-momentum (proportional to cos(wt)).
    std::vector<double> crossings;
    double              previous_momentum = 0, previous_time = 0;
    double              max_drift = 0;
    for (unsigned int p = 0; p < particles.size(); ++p)
      previous_momentum += particles.mass[p] * particles.velocity[p][0];
    while (sim.advance())
      {
        double momentum = 0;
        for (unsigned int p = 0; p < particles.size(); ++p)
          momentum += particles.mass[p] * particles.velocity[p][0];
        if ((momentum > 0) != (previous_momentum > 0))
          crossings.push_back(previous_time
                              + (sim.get_time() - previous_time)
                                  * previous_momentum
                                  / (previous_momentum - momentum));
        previous_momentum = momentum;
        previous_time     = sim.get_time();
        const auto &m     = sim.get_monitors();
        max_drift
          = std::max(max_drift,
                     std::abs(m.kinetic_energy + m.strain_energy - E0) / E0);
      }
    ASSERT_EQ(sim.get_termination(), fsgmpm::Termination::end_time)
      << sim.get_diagnosis();
    ASSERT_GE(crossings.size(), 9u);
    const double period = crossings[2] - crossings[0];
    std::cout << "[ measured ] " << dim << "D " << scheme << ", " << integration
              << ": particles = " << particles.size()
              << ", steps = " << sim.get_step() << ", first period = " << period
              << " s (analytic " << T << " s, error " << 100 * (period / T - 1)
              << " %), energy drift over 5 periods = " << 100 * max_drift
              << " %" << std::endl;
    EXPECT_NEAR(period / T, 1.0, 0.02);
    EXPECT_LT(max_drift, 0.02);
  }
} // namespace

TEST(ElasticBarVibration, TrianglesMUSL)
{
  run_bar<2>("MUSL");
}

TEST(ElasticBarVibration, TetrahedraMUSL)
{
  run_bar<3>("MUSL");
}

// The internal force from the nodal stress projection.
TEST(ElasticBarVibration, TrianglesMUSLNodalProjection)
{
  run_bar<2>("MUSL", "nodal projection");
}

TEST(ElasticBarVibration, TetrahedraMUSLNodalProjection)
{
  run_bar<3>("MUSL", "nodal projection");
}
