// Geocontainer drop, coarse: prm/geocontainer_polygon.prm and
// prm/geocontainer_ellipse.prm at 4 cm cells as shipped (weakly
// compressible water K = 2.13e7 Pa, FLIP noise relaxation 0.01 s toward
// XPIC(4), the
// water in its own velocity field with frictionless contact on the bag,
// the nodal stress projection), the first 0.2 s: sand in its membrane,
// falling into the water. Asserted over every step:
// - each body's mass is the same as at the start to 1e-12 (relative);
// - no water point inside the membrane and no sand point outside it, at
//   any step (the membrane is impermeable to the points, MembraneCrossing;
//   with Membrane/Impermeable to points = false, contact on the grid nodes
//   alone, 2 and 3 water points crossed by up to 7.3 mm, and 2 and 1 sand
//   points by up to 1.38 mm);
// - the sand's area within 3% of its start (measured within 0.22%);
// - the run is stable and loses no point;
// and that the container accelerates downward: its mass-weighted vertical
// velocity at 0.05, 0.1 and 0.2 s is negative and growing in magnitude
// (measured -0.38, -0.61, -0.79 m/s for the polygon, -0.29, -0.45, -0.68
// for the ellipse: the polygon's pointed bottom enters faster, as in the
// paper's Fig. 15), at 0.2 s within 0.02 m/s of that measurement. About
// 65 s on 2 cores (the scene monitors are evaluated at every step here).

#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

#include <algorithm>
#include <cmath>
#include <map>

using namespace fsgmpm;

namespace
{
  template <int dim>
  std::map<std::string, double>
  monitors(const Simulator<dim> &sim)
  {
    std::map<std::string, double> m;
    const auto                    names  = sim.get_scene_monitor_names();
    const auto                    values = sim.get_scene_monitors();
    for (unsigned int i = 0; i < names.size(); ++i)
      m[names[i]] = values[i];
    return m;
  }
} // namespace

TEST(GeocontainerDrop, CoarseDropKeepsMaterialsApartAndAccelerates)
{
  for (const std::string scene :
       {"geocontainer_polygon.prm", "geocontainer_ellipse.prm"})
    {
      auto prm = test_tools::make_parameters_from_scene(scene);
      prm->enter_subsection("Simulation");
      prm->set("End time", 0.2);
      prm->leave_subsection();
      prm->enter_subsection("Grid");
      prm->set("Cell size", 0.04);
      prm->leave_subsection();
      prm->enter_subsection("Bodies");
      prm->enter_subsection("Body 1");
      prm->enter_subsection("Newtonian fluid");
      prm->set("Bulk modulus", 2.13e7);
      prm->leave_subsection();
      prm->leave_subsection();
      prm->leave_subsection();
      prm->enter_subsection("Output");
      prm->set("Directory", "output_geocontainer_drop");
      prm->set("Quiet", true);
      prm->leave_subsection();

      Simulator<2> sim(*prm);
      const auto   start = monitors(sim);
      ASSERT_GT(start.at("soil_area"), 0.);
      EXPECT_EQ(start.at("water_points_inside"), 0.) << scene;
      EXPECT_EQ(start.at("soil_points_outside"), 0.) << scene;
      unsigned int                           max_outside = 0, max_inside = 0;
      double                                 max_depth  = 0;
      double                                 max_out    = 0;
      double                                 worst_area = 0;
      std::vector<std::pair<double, double>> velocity; // at 0.05, 0.1, 0.2
      const std::vector<double>              times = {0.05, 0.1, 0.2};
      for (bool running = true; running;)
        {
          running      = sim.advance();
          const auto m = monitors(sim);
          for (const std::string body : {"body_mass_0", "body_mass_1"})
            ASSERT_NEAR(m.at(body) / start.at(body), 1., 1e-12)
              << scene << " " << body << " at t = " << sim.get_time();
          max_inside
            = std::max<unsigned int>(max_inside, m.at("water_points_inside"));
          max_depth = std::max(max_depth, m.at("water_inside_depth"));
          max_outside
            = std::max<unsigned int>(max_outside, m.at("soil_points_outside"));
          max_out = std::max(max_out, m.at("soil_outside_distance"));
          worst_area
            = std::max(worst_area,
                       std::abs(m.at("soil_area") / start.at("soil_area") - 1));
          if (velocity.size() < times.size()
              && sim.get_time() >= times[velocity.size()] * (1 - 1e-12))
            velocity.emplace_back(sim.get_time(), m.at("container_velocity_y"));
        }
      EXPECT_EQ(sim.get_termination(), fsgmpm::Termination::end_time)
        << scene << ": " << sim.get_diagnosis();
      EXPECT_EQ(sim.get_monitors().lost_particles, 0u) << scene;
      EXPECT_EQ(max_outside, 0u) << scene;
      EXPECT_EQ(max_inside, 0u) << scene;
      EXPECT_EQ(max_depth, 0.) << scene;
      EXPECT_EQ(max_out, 0.) << scene;
      EXPECT_LT(worst_area, 0.03) << scene;
      ASSERT_EQ(velocity.size(), 3u) << scene;
      EXPECT_LT(velocity[0].second, 0.) << scene;
      for (unsigned int i = 1; i < velocity.size(); ++i)
        EXPECT_LT(velocity[i].second, velocity[i - 1].second)
          << scene << " at t = " << velocity[i].first;
      // The velocity at 0.2 s against our measurement (-0.789 and -0.677
      // m/s), so that a change of the result shows.
      EXPECT_NEAR(velocity[2].second,
                  scene == "geocontainer_polygon.prm" ? -0.789 : -0.677,
                  0.02)
        << scene;
      std::cout << scene << ": v_y = " << velocity[0].second << ", "
                << velocity[1].second << ", " << velocity[2].second
                << " m/s at 0.05, 0.1, 0.2 s; sand points outside <= "
                << max_outside << " (at most " << max_out
                << " m out), water points inside <= " << max_inside
                << " (at most " << max_depth << " m deep), sand area within "
                << worst_area << std::endl;
    }
}



// Validation (label validation, not in the default run): both shipped
// scenes as shipped (2 cm, 16 and 4 points per cell, nodal stress
// projection, FLIP's noise relaxed toward XPIC(4), polygon to 1.7 s,
// ellipse to 2.1 s), from the water surface to the tank floor. The
// experiment (paper Section 5.2): 0.8 m/s at 0.8 s (its landing time is
// not given; the paper's simulation lands at 1.1 s).
// Our scenes sink at 0.598 and 0.600 m/s at 0.8 s (25.2 and 25.0% below),
// for the reasons measured in doc/geocontainer_validation.md, section 5.
// Asserted against our measurement, so that a change of the result shows:
// the velocity at 0.8 s within 0.05 m/s, the landing time within 0.05 s,
// the membrane's lowest node at 1.6 s within 1 cm (measured 1.304 and
// 1.419 s, 2.20 and 3.32 cm), masses to 1e-12, no water point inside the
// membrane and no sand point outside it at any step (the membrane is
// impermeable to the points; with contact on the grid nodes alone 25 and 25
// points crossed, up to 13.3 and 16.0 mm deep), no point lost (the tank has a
// lid), a stable run; and that the water keeps its volume: by the work gravity
// has done, the water's centre of mass has risen at 0.8 s by the volume the bag
// displaces plus the share of the surface's waves and of the jet where the
// water closes over the bag (measured 0.42 and 0.54 mm above 6.07 and 5.62 mm;
// with the paper's NMD+ANP it fell, doc section 5). About 16 min for both on
// 2 threads.
TEST(GeocontainerDropValidation, ShippedScenesTowardsTheFloor)
{
  struct Expected
  {
    std::string scene;
    double      v_08, landing, lowest_16, rise_above_displaced;
  };
  for (const Expected &e :
       {Expected{"geocontainer_polygon.prm", -0.598, 1.304, 0.0220, 0.00042},
        Expected{"geocontainer_ellipse.prm", -0.600, 1.419, 0.0332, 0.00054}})
    {
      auto prm = test_tools::make_parameters_from_scene(e.scene);
      prm->enter_subsection("Output");
      prm->set("Directory", "output_geocontainer_validation");
      prm->set("Quiet", true);
      prm->leave_subsection();
      Simulator<2> sim(*prm);
      const auto   start = monitors(sim);
      double       v_08 = 0, landing = -1, lowest_16 = -1, max_depth = 0;
      double       water_rise = 0, displaced_rise = 0;
      unsigned int max_inside = 0, max_outside = 0;
      for (bool running = true; running;)
        {
          running      = sim.advance();
          const auto m = monitors(sim);
          for (const std::string body : {"body_mass_0", "body_mass_1"})
            ASSERT_NEAR(m.at(body) / start.at(body), 1., 1e-12)
              << e.scene << " " << body << " at t = " << sim.get_time();
          max_inside
            = std::max<unsigned int>(max_inside, m.at("water_points_inside"));
          max_depth = std::max(max_depth, m.at("water_inside_depth"));
          max_outside
            = std::max<unsigned int>(max_outside, m.at("soil_points_outside"));
          if (v_08 == 0 && sim.get_time() >= 0.8 * (1 - 1e-12))
            {
              v_08 = m.at("container_velocity_y");
              // The energy audit (doc/scripts/geocontainer_audit.py): the
              // work of gravity less the sand's share is the water's fall.
              const double g = 9.81;
              const double fall
                = start.at("container_centre_y") - m.at("container_centre_y");
              water_rise = -(sim.get_monitors().external_work
                             - start.at("body_mass_0") * g * fall)
                           / (start.at("body_mass_1") * g);
              displaced_rise = 1000. * start.at("soil_area") * fall
                               / start.at("body_mass_1");
            }
          if (landing < 0 && sim.get_time() > 1.
              && m.at("container_velocity_y") >= 0)
            landing = sim.get_time();
          if (lowest_16 < 0 && sim.get_time() >= 1.6 * (1 - 1e-12))
            {
              lowest_16 = 1e300;
              for (const auto &x : sim.get_membrane()->position)
                lowest_16 = std::min(lowest_16, x[1]);
            }
        }
      std::cout << e.scene << ": v_y(0.8 s) = " << v_08 << " m/s, landing at "
                << landing << " s (-1: none), lowest membrane node at 1.6 s "
                << lowest_16 << " m; water points inside <= " << max_inside
                << " (at most " << max_depth << " m deep); the water's "
                << "centre of mass rose " << water_rise << " m at 0.8 s "
                << "(displaced volume: " << displaced_rise << " m)"
                << std::endl;
      EXPECT_EQ(sim.get_termination(), fsgmpm::Termination::end_time)
        << e.scene << ": " << sim.get_diagnosis();
      // Above the displaced volume by the waves' and the jet's share.
      EXPECT_NEAR(water_rise - displaced_rise, e.rise_above_displaced, 0.0003)
        << e.scene;
      EXPECT_EQ(sim.get_monitors().lost_particles, 0u) << e.scene;
      EXPECT_NEAR(v_08, e.v_08, 0.05) << e.scene;
      EXPECT_NEAR(landing, e.landing, 0.05) << e.scene;
      EXPECT_NEAR(lowest_16, e.lowest_16, 0.01) << e.scene;
      EXPECT_EQ(max_inside, 0u) << e.scene;
      EXPECT_EQ(max_depth, 0.) << e.scene;
      EXPECT_EQ(max_outside, 0u) << e.scene;
    }
}



// Validation (label validation): the 3D slab (prm/geocontainer_polygon_3d.prm,
// the polygon extruded one layer (2 cm) thick between roller faces) at 4 cm
// to 0.8 s beside the 2D polygon at 4 cm. Between roller faces the slab is
// plane strain, so its sinking velocity must follow the 2D one; the 3D membrane
// (triangles, its section tested at each point's own z) must keep every
// point on its side. Measured at 0.2 / 0.4 / 0.6 / 0.8 s: 3D 0.761 / 0.538 /
// 0.444 / 0.500 m/s, 2D 0.789 / 0.571 / 0.499 / 0.528 (RMS relative
// difference 7.0 %). Asserted: the RMS relative difference below 10 %, the
// 3D velocity at 0.4 and 0.8 s within 0.03 m/s of the measurement (so that
// a change of the result shows), masses to 1e-12, no point across the
// membrane at any step (measured none), none lost, a normal end. About
// 13 min on one core (the 3D slab 12).
TEST(GeocontainerDropValidation, Slab3dFollowsPlaneStrainAt4cm)
{
  const std::vector<double> times = {0.2, 0.4, 0.6, 0.8};
  const auto                run   = [&](auto &sim, const std::string &label) {
    const auto          start = monitors(sim);
    std::vector<double> v;
    unsigned int        max_inside = 0, max_outside = 0;
    for (bool running = true; running;)
      {
        running      = sim.advance();
        const auto m = monitors(sim);
        for (const std::string body : {"body_mass_0", "body_mass_1"})
          EXPECT_NEAR(m.at(body) / start.at(body), 1., 1e-12)
            << label << " " << body << " at t = " << sim.get_time();
        max_inside
          = std::max<unsigned int>(max_inside, m.at("water_points_inside"));
        max_outside
          = std::max<unsigned int>(max_outside, m.at("soil_points_outside"));
        if (v.size() < times.size()
            && sim.get_time() >= times[v.size()] * (1 - 1e-12))
          v.push_back(-m.at("container_velocity_y"));
      }
    EXPECT_EQ(sim.get_termination(), fsgmpm::Termination::end_time)
      << label << ": " << sim.get_diagnosis();
    EXPECT_EQ(sim.get_monitors().lost_particles, 0u) << label;
    EXPECT_EQ(max_inside, 0u) << label;
    EXPECT_EQ(max_outside, 0u) << label;
    std::cout << label << ": sinking at";
    for (unsigned int i = 0; i < v.size(); ++i)
      std::cout << " " << v[i] << " (" << times[i] << " s)";
    std::cout << " m/s; water points inside <= " << max_inside
              << ", sand points outside <= " << max_outside << std::endl;
    return v;
  };
  const auto parameters = [](const std::string &scene) {
    auto prm = test_tools::make_parameters_from_scene(scene);
    prm->enter_subsection("Simulation");
    prm->set("End time", 0.8);
    prm->leave_subsection();
    prm->enter_subsection("Grid");
    prm->set("Cell size", 0.04);
    prm->leave_subsection();
    prm->enter_subsection("Output");
    prm->set("Directory", "output_geocontainer_3d_validation");
    prm->set("Quiet", true);
    prm->set("Write particles", false);
    prm->leave_subsection();
    return prm;
  };

  auto         prm_2d = parameters("geocontainer_polygon.prm");
  Simulator<2> sim_2d(*prm_2d);
  const auto   v_2d   = run(sim_2d, "2D at 4 cm");
  auto         prm_3d = parameters("geocontainer_polygon_3d.prm");
  Simulator<3> sim_3d(*prm_3d);
  const auto   v_3d = run(sim_3d, "3D slab at 4 cm");
  ASSERT_EQ(v_2d.size(), times.size());
  ASSERT_EQ(v_3d.size(), times.size());
  double rms = 0;
  for (unsigned int i = 0; i < times.size(); ++i)
    rms += std::pow((v_3d[i] - v_2d[i]) / v_2d[i], 2) / times.size();
  rms = std::sqrt(rms);
  std::cout << "[ measured ] 3D slab against 2D at 4 cm: RMS relative "
            << "difference " << rms << std::endl;
  EXPECT_LT(rms, 0.10);
  EXPECT_NEAR(v_3d[1], 0.537, 0.03);
  EXPECT_NEAR(v_3d[3], 0.500, 0.03);
}
