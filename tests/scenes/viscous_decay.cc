// The numerical viscosity of each velocity transfer, measured on a flow with
// an exact viscous decay: the Taylor-Green vortex in a box of slip walls.
// Water (rho = 1000, K = 2.5e6, mu = 1e-3 Pa s: nu = 1e-6 m^2/s, the floor;
// tension allowed so the vortex's low centre pressure exists), zero gravity,
// a 1 x 1 m box of roller walls, started with
//   u = U (sin kx cos ky, -cos kx sin ky),  k = pi / L,  U = 0.1 m/s.
// The mode is an exact solution of the Navier-Stokes equations (its
// advection is a pressure gradient), it has no normal velocity and no shear
// stress on the walls, and its kinetic energy decays as exp(-4 nu k^2 t).
// A shear layer between two strips needs periodic or open ends, which a
// box of walls does not have; the vortex fills the box and tests the
// transfer at one wavelength of two cells per metre, the scale of the flow
// around a body of that size. Mach 0.002: the acoustic energy the start
// without the vortex's pressure excites is Ma^2 of the kinetic energy, and
// the kinetic plus strain energy is what is read:
//   nu_eff = ln(E(0) / E(T)) / (4 k^2 T).
// The FLIP-PIC blend with relaxation time tau should read about h^2 /
// (6 tau) (one PIC round trip on linear elements keeps 1 - (kh)^2 / 6 of a
// mode, applied at the rate 1 / tau), wavenumber-free while kh is small.
// XPIC(m) (Hammerquist and Nairn 2017) as the blend's target keeps that
// mode to (1 - a)^m per relaxation instead of 1 - a.

#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <map>
#include <string>
#include <vector>

using namespace fsgmpm;

namespace
{
  constexpr double L = 1.0, U = 0.1, rho = 1000, nu_water = 1e-6;

  struct Decay
  {
    double       nu_eff  = 0; // m^2/s
    double       seconds = 0; // wall time
    unsigned int steps   = 0;
    unsigned int points  = 0;
    /// Kinetic plus strain energy at the start and the end, and the
    /// viscous work booked (monitors.csv's material_dissipation), J/m.
    double E0 = 0, E = 0, booked = 0;
  };

  // One run: @p h the cell size, @p transfer prm lines of subsection
  // Simulation, @p T the end time, @p viscosity the water's (Pa s).
  Decay
  run(const double       h,
      const std::string &transfer,
      const double       T,
      const std::string &viscosity = "1e-3")
  {
    const unsigned int n   = static_cast<unsigned int>(std::round(L / h));
    auto               prm = test_tools::make_parameters(
      "subsection Simulation\n"
                    "  set End time = "
      + std::to_string(T)
      + "\n"
                      "  set Gravity = 0, 0\n"
      + transfer
      + "end\n"
                      "subsection Grid\n"
                      "  set Upper corner = 1, 1\n"
                      "  set Subdivisions = "
      + std::to_string(n) + ", " + std::to_string(n)
      + "\n"
                      "  set Boundary conditions = 0: roller, 1: roller, 2: roller, "
                      "3: roller\n"
                      "end\n"
                      "subsection Bodies\n subsection Body 0\n"
                      "  set Box lower corner = 0, 0\n  set Box upper corner = 1, 1\n"
                      "  set Density = 1000\n"
                      "  set Particles per cell = 4\n"
                      "  set Material model = Newtonian fluid\n"
                      "  set Volumetric smoothing = NMD+ANP\n"
                      "  subsection Newtonian fluid\n"
                      "   set Bulk modulus = 2.5e6\n   set Viscosity = "
      + viscosity
      + "\n"
                      "   set Allow tension = true\n  end\n end\nend\n");
    Simulator<2> sim(*prm);
    auto        &particles = sim.get_particles();
    const double k         = M_PI / L;
    for (unsigned int p = 0; p < particles.size(); ++p)
      {
        const auto &x            = particles.position[p];
        particles.velocity[p][0] = U * std::sin(k * x[0]) * std::cos(k * x[1]);
        particles.velocity[p][1] = -U * std::cos(k * x[0]) * std::sin(k * x[1]);
      }
    sim.reinitialize_state();
    const double E0
      = sim.get_monitors().kinetic_energy + sim.get_monitors().strain_energy;
    const auto start = std::chrono::steady_clock::now();
    while (sim.advance())
      {}
    Decay d;
    d.seconds
      = std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    EXPECT_EQ(sim.get_termination(), fsgmpm::Termination::end_time)
      << sim.get_diagnosis();
    const double E
      = sim.get_monitors().kinetic_energy + sim.get_monitors().strain_energy;
    d.nu_eff = std::log(E0 / E) / (4 * k * k * sim.get_time());
    d.E0     = E0;
    d.E      = E;
    d.booked = sim.get_monitors().material_dissipation;
    d.steps  = sim.get_step();
    d.points = particles.size();
    return d;
  }

  struct Transfer
  {
    std::string name, prm;
  };

  const std::vector<Transfer> &
  transfers()
  {
    static const std::vector<Transfer> t
      = {{"FLIP", ""},
         {"FLIP, tau = 0.05 s", "  set FLIP noise relaxation time = 0.05\n"},
         {"FLIP, tau = 0.01 s", "  set FLIP noise relaxation time = 0.01\n"},
         {"XPIC(2), tau = 0.01 s",
          "  set FLIP noise relaxation time = 0.01\n  set XPIC order = 2\n"},
         {"XPIC(4), tau = 0.01 s",
          "  set FLIP noise relaxation time = 0.01\n  set XPIC order = 4\n"},
         {"XPIC(8), tau = 0.01 s",
          "  set FLIP noise relaxation time = 0.01\n  set XPIC order = 8\n"},
         {"APIC", "  set Velocity transfer = APIC\n"},
         {"APIC affine remap",
          "  set Velocity transfer = APIC affine remap\n"}};
    return t;
  }

  // The table row of one transfer at the cell sizes @p hs.
  std::vector<Decay>
  row(const Transfer &t, const std::vector<double> &hs, const double T)
  {
    std::vector<Decay> r;
    std::cout << "[ measured ] " << std::setw(20) << std::left << t.name;
    for (const double h : hs)
      {
        r.push_back(run(h, t.prm, T));
        std::cout << " | h = " << h << " m: nu_eff = " << std::setprecision(3)
                  << r.back().nu_eff << " m^2/s (" << r.back().nu_eff / nu_water
                  << " x water), " << r.back().steps << " steps, "
                  << r.back().seconds << " s";
      }
    std::cout << std::endl;
    return r;
  }
} // namespace

// Every transfer at 4 cm, FLIP, the shipped blend and XPIC(4) at 2 cm (about
// 40 s on 2 cores). The blend's numerical viscosity is h^2 / (6 tau) on top
// of FLIP's within 6 % (measured 0.1-3 %); the other rows within 10 % of the
// values measured when the test was written (the runs are deterministic:
// the same figures on 1 and 2 threads), far closer than the transfers are
// to each other.
TEST(ViscousDecay, NumericalViscosityOfEachTransfer)
{
  const double                 T = 0.5;
  std::map<std::string, Decay> at4, at2;
  for (const auto &t : transfers())
    at4[t.name] = row(t, {0.04}, T)[0];
  for (const auto &t : transfers())
    if (t.name == "FLIP" || t.name == "FLIP, tau = 0.01 s"
        || t.name == "XPIC(4), tau = 0.01 s")
      at2[t.name] = row(t, {0.02}, T)[0];
  const auto blend
    = [](const double h, const double tau) { return h * h / (6 * tau); };
  // FLIP: a few times water's viscosity (measured 26.9 x at 4 cm, 5.09 x at
  // 2 cm: falls with the mesh).
  EXPECT_NEAR(at4["FLIP"].nu_eff, 2.69e-5, 0.3e-5);
  EXPECT_NEAR(at2["FLIP"].nu_eff, 5.09e-6, 0.5e-6);
  for (const auto &[tau, name] : std::vector<std::pair<double, std::string>>{
         {0.05, "FLIP, tau = 0.05 s"}, {0.01, "FLIP, tau = 0.01 s"}})
    EXPECT_NEAR(at4[name].nu_eff / (blend(0.04, tau) + at4["FLIP"].nu_eff),
                1.,
                0.06)
      << name;
  EXPECT_NEAR(at2["FLIP, tau = 0.01 s"].nu_eff
                / (blend(0.02, 0.01) + at2["FLIP"].nu_eff),
              1.,
              0.06);
  // XPIC keeps the resolved mode: measured 1.85e-3 / 5.82e-4 at 4 cm (14 /
  // 46 times less than the blend with PIC), 7.84e-5 at 2 cm (85 times less:
  // 78 times water's).
  EXPECT_NEAR(at4["XPIC(2), tau = 0.01 s"].nu_eff, 1.85e-3, 0.19e-3);
  EXPECT_NEAR(at4["XPIC(4), tau = 0.01 s"].nu_eff, 5.82e-4, 0.58e-4);
  EXPECT_NEAR(at2["XPIC(4), tau = 0.01 s"].nu_eff, 7.84e-5, 0.78e-5);
  // APIC: its MUSL remap smooths like PIC each step (measured 7.2e-3);
  // with the affine remap 6.01e-4.
  EXPECT_NEAR(at4["APIC"].nu_eff, 7.2e-3, 0.72e-3);
  EXPECT_NEAR(at4["APIC affine remap"].nu_eff, 6.01e-4, 0.6e-4);
}

// The table of doc/accuracy_vs_cost.md: every transfer at 4, 2 and 1 cm
// (label validation, about 12 minutes on 2 cores).
// The viscous work is booked (material_dissipation): the vortex in a fluid
// of nu = 1e-3 m^2/s (mu = 1 Pa s), FLIP, 4 cm, 0.5 s. The exact decay
// removes E0 (1 - exp(-4 nu k^2 T)) = 1.95 % of the energy; the booked
// viscous work is 2 mu dev(d) : dev(d) V dt of the cells' rates. Measured:
// booked / exact 1.032 (the rates of the mapped nodal velocities hold
// some of FLIP's noise), booked / the energy lost 0.977 (FLIP's own
// numerical viscosity, 2.7e-5 m^2/s, and the acoustic start take the
// rest). Tolerances 0.06 and 0.05: an unbooked viscosity (0) or one booked
// twice fails.
TEST(ViscousDecay, ViscousWorkIsBooked)
{
  const double nu = 1e-3, T = 0.5, k = M_PI / L;
  const Decay  d     = run(0.04, "", T, "1");
  const double exact = d.E0 * (-std::expm1(-4 * nu * k * k * T));
  std::cout << "[ measured ] viscous work booked " << d.booked
            << " J/m, exact decay " << exact << " J/m (ratio "
            << d.booked / exact << "), energy lost " << d.E0 - d.E
            << " J/m (ratio " << d.booked / (d.E0 - d.E) << ")" << std::endl;
  EXPECT_NEAR(d.booked / exact, 1., 0.06);
  EXPECT_NEAR(d.booked / (d.E0 - d.E), 1., 0.05);
}

TEST(ViscousDecayValidation, TableAtFourTwoAndOneCentimetres)
{
  for (const auto &t : transfers())
    {
      const auto r = row(t, {0.04, 0.02, 0.01}, 0.5);
      for (const auto &d : r)
        EXPECT_GT(d.nu_eff, 0.5 * nu_water) << t.name;
    }
}
