// Collapse of a water column, n^2 = 2, at ctest size (20 cells across
// w0 = 0.114 m, prm/water_column_collapse_n2.prm) with a weakly compressible
// K_f = 2.5 MPa (sound speed 50 m/s, more than 10x the flow speed), against
// Martin & Moyce (1952) in their normalisation: front Z = z/a against
// T = t sqrt(2g/a) over the tabulated T <= 3.3, residual height
// H = eta/(2a) against tau = t sqrt(g/a) over tau <= 3.
//
// Default suite (label scene): without time shift, height RMS <= 0.06; the
// front RMS <= 0.1 after the best constant delay of the simulation, which
// must be at most 30 ms (the experiment's gate, not modelled, delays its
// start); the delay and the unshifted RMS are reported.
// Validation (label validation): the criterion without shift, front
// RMS <= 0.3. Measured 0.306-0.321 over mesh, particles per cell, Courant
// number and f_c (doc/water_validation.md): the model without a gate leads
// the experiment; this test documents that and fails until it is resolved.
//
// ThroughTheFarWallImpact (default suite): the coarse column (10 cells
// across w0) run on to 1 s, past the far-wall impact, the run-up and the
// collapse of the air cavity that the falling water closes at about 0.8 s:
// it must complete with the energy guard off and create no energy
// (kinetic + strain - initial - work + damping at most 1e-4 J/m; measured
// 2.1e-5, the first steps' acoustic transient), with the open top as
// shipped (the run-up leaves through it as lost points, which take their
// energy with them) and in a tank closed by a slip lid (nothing leaves).
// With the points at the free surface in NMD's averages (ANP leaves them
// out) the cavity's collapse created 19 J/m (open top) and 46 J/m (lid).

#include <fsgmpm/scene/parameter_path.h>
#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

#include <fstream>
#include <sstream>

using namespace fsgmpm;

namespace
{
  // Piecewise-linear interpolation of (t, v) samples at time x.
  double
  interpolate(const std::vector<std::pair<double, double>> &s, const double x)
  {
    if (x <= s.front().first)
      return s.front().second;
    for (unsigned int i = 1; i < s.size(); ++i)
      if (x <= s[i].first)
        return s[i - 1].second
               + (s[i].second - s[i - 1].second) * (x - s[i - 1].first)
                   / (s[i].first - s[i - 1].first);
    return s.back().second;
  }
} // namespace

namespace
{
  struct Errors
  {
    double       z_rms, h_rms, z_rms_shifted, shift;
    unsigned int lost;
  };

  // The n^2 = 2 scene at K_f = 2.5 MPa; @p gate_history, if not empty,
  // enables the moving wall on the column's right face with that velocity
  // history.
  Errors
  run_n2(const std::string &gate_history = "")
  {
    const double a = 0.114, g = 9.81;
    auto         prm = test_tools::make_parameters("");
    prm->parse_input(std::string(FSGMPM_TEST_SOURCE_DIR)
                     + "/../prm/water_column_collapse_n2.prm");
    prm->enter_subsection("Bodies");
    prm->enter_subsection("Body 0");
    prm->enter_subsection("Newtonian fluid");
    prm->set("Bulk modulus", "2.5e6");
    prm->leave_subsection();
    prm->leave_subsection();
    prm->leave_subsection();
    if (!gate_history.empty())
      {
        set_parameter(*prm, "Moving wall/Enabled", "true");
        set_parameter(*prm, "Moving wall/Lower corner", "0.114, 0");
        set_parameter(*prm, "Moving wall/Upper corner", "0.114, 0.3");
        set_parameter(*prm, "Moving wall/Velocity history", gate_history);
      }
    Simulator<2> sim(*prm);
    EXPECT_EQ(sim.get_scene_monitor_names(),
              (std::vector<std::string>{"front_position", "column_height"}));

    std::vector<std::pair<double, double>> front, height;
    auto                                   record = [&] {
      const auto v = sim.get_scene_monitors();
      front.emplace_back(sim.get_time() * std::sqrt(2 * g / a), v[0] / a);
      height.emplace_back(sim.get_time() * std::sqrt(g / a), v[1] / (2 * a));
    };
    record();
    while (sim.advance())
      if (sim.get_step() % 20 == 0)
        record();
    record();
    EXPECT_EQ(sim.get_termination(), fsgmpm::Termination::end_time)
      << sim.get_diagnosis();

    std::ifstream in(std::string(FSGMPM_TEST_SOURCE_DIR)
                     + "/reference/martin_moyce_1952_n2.csv");
    EXPECT_TRUE(in.good());
    std::string                            line;
    double                                 z_sum = 0, h_sum = 0;
    unsigned                               z_n = 0, h_n = 0;
    std::vector<std::pair<double, double>> front_reference;
    while (std::getline(in, line))
      {
        if (line.empty() || line[0] == '#' || line.rfind("series", 0) == 0)
          continue;
        std::istringstream s(line);
        std::string        series, t, v;
        std::getline(s, series, ',');
        std::getline(s, t, ',');
        std::getline(s, v, ',');
        const double time = std::stod(t), value = std::stod(v);
        if (series == "front" && time <= 3.3 + 1e-9)
          {
            z_sum += std::pow(interpolate(front, time) - value, 2);
            ++z_n;
            front_reference.emplace_back(time, value);
          }
        if (series == "height" && time <= 3.0 + 1e-9)
          {
            h_sum += std::pow(interpolate(height, time) - value, 2);
            ++h_n;
          }
      }
    Errors e;
    e.z_rms = std::sqrt(z_sum / z_n);
    e.h_rms = std::sqrt(h_sum / h_n);
    e.lost  = sim.get_monitors().lost_particles;
    // Best constant delay s >= 0 of the simulation: Z_sim(T - s) vs Z_exp(T).
    e.z_rms_shifted = e.z_rms;
    e.shift         = 0;
    for (double shift = 0; shift <= 1.0; shift += 0.005)
      {
        double sum = 0;
        for (const auto &[T, Z] : front_reference)
          sum += std::pow(interpolate(front, std::max(0., T - shift)) - Z, 2);
        const double rms = std::sqrt(sum / front_reference.size());
        if (rms < e.z_rms_shifted)
          {
            e.z_rms_shifted = rms;
            e.shift         = shift;
          }
      }
    std::cout << "[ measured ] n^2 = 2, 20 cells across w0, K_f = 2.5 MPa"
              << (gate_history.empty() ? "" : ", gate " + gate_history) << ": "
              << sim.get_particles().size() << " points, " << sim.get_step()
              << " steps; front RMS error in Z = " << e.z_rms << " (" << z_n
              << " points; " << e.z_rms_shifted
              << " with the simulation delayed by T = " << e.shift << ", i.e. "
              << 1e3 * e.shift / std::sqrt(2 * g / a)
              << " ms), height RMS error in H = " << e.h_rms << " (" << h_n
              << " points), lost " << e.lost << std::endl;
    return e;
  }
} // namespace

TEST(WaterColumnCollapse, MartinMoyceN2)
{
  const Errors e = run_n2();
  EXPECT_LE(e.h_rms, 0.06);
  // The front's shape: within 0.1 after a gate-sized delay (at most 30 ms,
  // T = 0.39).
  EXPECT_LE(e.z_rms_shifted, 0.1);
  EXPECT_LE(e.shift, 0.39);
  EXPECT_EQ(e.lost, 0u);
}

TEST(WaterColumnCollapseValidation, MartinMoyceN2WithoutShift)
{
  const Errors e = run_n2();
  EXPECT_LE(e.z_rms, 0.3);
  EXPECT_LE(e.h_rms, 0.06);
}

// The gate (Moving wall) of doc/accuracy_vs_cost.md section 2: at rest it
// holds the column in hydrostatic equilibrium (the front moves less than
// 1e-3 mm in 0.1 s; measured 1.2e-4 mm); lifted at the Froude-scaled speed of
// Lobovsky et al. (2014), V = 1.95 sqrt(g H) = 2.92 m/s, it delays the front:
// unshifted RMS 0.271 measured (0.306 without gate), the best delay 17.5 ms
// (20.2).
TEST(WaterColumnCollapse, Gate)
{
  {
    auto prm = test_tools::make_parameters("");
    prm->parse_input(std::string(FSGMPM_TEST_SOURCE_DIR)
                     + "/../prm/water_column_collapse_n2.prm");
    set_parameter(*prm, "Simulation/End time", "0.1");
    set_parameter(*prm, "Bodies/Body 0/Newtonian fluid/Bulk modulus", "2.5e6");
    set_parameter(*prm, "Moving wall/Enabled", "true");
    set_parameter(*prm, "Moving wall/Lower corner", "0.114, 0");
    set_parameter(*prm, "Moving wall/Upper corner", "0.114, 0.3");
    set_parameter(*prm, "Moving wall/Velocity history", "0: 0 0");
    Simulator<2> sim(*prm);
    const double front0 = sim.get_scene_monitors()[0];
    while (sim.advance())
      if (sim.get_scene_monitors()[0] - front0 > 1e-6)
        {
          ADD_FAILURE() << "the front left the gate by "
                        << sim.get_scene_monitors()[0] - front0
                        << " m at t = " << sim.get_time();
          break;
        }
    EXPECT_EQ(sim.get_termination(), fsgmpm::Termination::end_time)
      << sim.get_diagnosis();
    std::cout << "[ measured ] gate at rest: front moved "
              << 1e3 * (sim.get_scene_monitors()[0] - front0) << " mm in 0.1 s"
              << std::endl;
  }
  const Errors e = run_n2("0: 0 2.92");
  EXPECT_NEAR(e.z_rms, 0.271, 0.015);
  EXPECT_NEAR(e.shift, 0.229, 0.03); // 17.5 ms
  EXPECT_LE(e.h_rms, 0.06);
  EXPECT_EQ(e.lost, 0u);
}

namespace
{
  struct LongRun
  {
    double       largest_creation, final_balance, work;
    unsigned int lost;
  };

  LongRun
  run_coarse_to_one_second(const std::string &boundary_conditions)
  {
    auto prm = test_tools::make_parameters("");
    prm->parse_input(std::string(FSGMPM_TEST_SOURCE_DIR)
                     + "/../prm/water_column_collapse_n2.prm");
    set_parameter(*prm, "Simulation/End time", "1");
    set_parameter(*prm, "Grid/Subdivisions", "60, 25");
    set_parameter(*prm, "Grid/Boundary conditions", boundary_conditions);
    set_parameter(*prm, "Bodies/Body 0/Newtonian fluid/Bulk modulus", "2.5e6");
    // Watch the balance ourselves, every step.
    set_parameter(*prm, "Stability/Energy creation tolerance", "0");
    Simulator<2> sim(*prm);
    const auto   held = [&] {
      const Monitors &m = sim.get_monitors();
      return m.kinetic_energy + m.strain_energy;
    };
    const double initial = held();
    const auto   balance = [&] {
      const Monitors &m = sim.get_monitors();
      return held() - initial - m.external_work + m.dissipated_energy;
    };
    LongRun r{0, 0, 0, 0};
    while (sim.advance())
      r.largest_creation = std::max(r.largest_creation, balance());
    EXPECT_EQ(sim.get_termination(), fsgmpm::Termination::end_time)
      << sim.get_diagnosis();
    EXPECT_NEAR(sim.get_time(), 1., 1e-9);
    r.final_balance = balance();
    r.work          = sim.get_monitors().external_work;
    r.lost          = sim.get_monitors().lost_particles;
    std::cout << "[ measured ] n^2 = 2, 10 cells across w0, K_f = 2.5 MPa, to "
              << sim.get_time() << " s, walls " << boundary_conditions
              << ": largest energy created " << r.largest_creation
              << " J/m, balance at the end " << r.final_balance
              << " J/m (the work done " << r.work << " J/m), " << r.lost
              << " points left the tank" << std::endl;
    return r;
  }
} // namespace

TEST(WaterColumnCollapse, ThroughTheFarWallImpact)
{
  // As shipped: the top is open.
  const LongRun open
    = run_coarse_to_one_second("0: roller, 1: roller, 2: roller, 3: free");
  EXPECT_LE(open.largest_creation, 1e-4);
  EXPECT_GT(open.lost, 0u);
  // Energy only leaves (the lost points', the transfer's losses).
  EXPECT_LT(open.final_balance, 0.);
  // Closed by a slip lid: nothing leaves, nothing is created.
  const LongRun closed
    = run_coarse_to_one_second("0: roller, 1: roller, 2: roller, 3: slip");
  EXPECT_LE(closed.largest_creation, 1e-4);
  EXPECT_EQ(closed.lost, 0u);
  EXPECT_LT(closed.final_balance, 0.);
}
