// Coarse geotube: prm/geotube_A5.56.prm at 16 cm cells with the
// quasi-static weakly compressible fluid (K_f = 2.7e7 Pa: p_max/K_f = 1e-3),
// 16 points per cell, relaxed for 8 s of simulated time (dynamic relaxation
// with directional mass scaling, the slip-consistent loop stiffness, and
// local damping 0.7), then the monitors are averaged over 8-12 s: the
// relaxation does not converge by Eq. (30) at 1e-3 (the force ratio levels
// off at about 0.05: cell-crossing noise), and the residual sloshing moves
// single samples by a few per cent while the shape stays put
// (doc/membrane_validation.md). Reference: the independent analytic
// solution (include/fsgmpm/reference/geotube_reference.h: inextensible
// weightless membrane, hydrostatic fill, frictionless base) for the run's
// own measured enclosed area and membrane length (the solver's error); the
// error against the nominal 5.56 m^2 and 9.2 m (the user's error) is
// printed.
// Asserts (tolerances a few times the measured errors, not the validation
// criteria of doc/membrane_validation.md, so that a change of a few per
// cent shows):
// 2D: H/W within 0.004 of the analytic value for the measured area and
// length (measured -0.0013 with the damped time-step bound, -0.0002
// before) and within 0.008 of the nominal 5.56 m^2, 9.2 m one (measured
// -0.0030); mean tension within 2% of the analytic value for the measured
// area and length (measured -0.2%) and within 4% of the nominal one
// (measured -1.0%); top and bottom pressure of the line fit within 3% of
// the analytic bottom pressure (measured -0.4% and +1.1% of it). The max/mean
// tension check (1%) only guards the slip projection, which makes the tension
// uniform by construction. No point lost and at most 0.5% of the points outside
// the membrane. The same for the 3D variant (prm/geotube_A5.56_3d.prm,
// averaged over 4-6 s: it relaxes in about 3 s), measured H/W -0.0039 (own)
// and -0.0055 (nominal), tension +1.8% and +1.0%, p_top -0.3% and p_bottom
// -2.5% of p_bottom (over 8-10 s: -0.0050, -0.0067, +0.8%, 0.0%, -1.3%,
// -1.6%): H/W within 0.012 and 0.015, tension within 3% and 3%, pressures
// within 4%.
// Measured values: see the [ measured ] lines and doc/membrane_validation.md.
// Label validation (geotube_coarse_eq30), not yet met: convergence by
// Eq. (30) at 1e-3 within 30 s of relaxation.

#include <fsgmpm/io/membrane_output.h>
#include <fsgmpm/reference/geotube_reference.h>
#include <fsgmpm/scene/parameter_path.h>
#include <fsgmpm/simulator.h>
#include <gtest/gtest.h>

#include "test_utilities.h"

#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

using namespace fsgmpm;

namespace
{
  std::unique_ptr<ParameterHandler>
  coarse_parameters(const double       end_time,
                    const std::string &scene = "geotube_A5.56.prm")
  {
    auto prm = test_tools::make_parameters_from_scene(scene);
    prm->enter_subsection("Simulation");
    prm->set("End time", end_time);
    prm->leave_subsection();
    prm->enter_subsection("Grid");
    prm->set("Cell size", 0.16);
    prm->leave_subsection();
    prm->enter_subsection("Bodies");
    prm->enter_subsection("Body 0");
    prm->enter_subsection("Newtonian fluid");
    prm->set("Bulk modulus", 2.7e7);
    prm->leave_subsection();
    prm->leave_subsection();
    prm->leave_subsection();
    prm->enter_subsection("Output");
    // One directory per scene, so that ctest -j runs the 2D and 3D entries
    // side by side.
    prm->set("Directory",
             "output_geotube_coarse_" + scene.substr(0, scene.rfind('.')));
    prm->set("Quiet", true);
    prm->leave_subsection();
    return prm;
  }

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

  // Top and bottom pressure of the line fit against the analytic ones,
  // within @p tolerance times the analytic bottom pressure.
  template <typename Reference>
  void
  expect_pressures(const std::map<std::string, double> &m,
                   const Reference                     &ref,
                   const double                         tolerance)
  {
    EXPECT_NEAR(m.at("top_pressure"),
                ref.top_pressure,
                tolerance * ref.bottom_pressure);
    EXPECT_NEAR(m.at("bottom_pressure"),
                ref.bottom_pressure,
                tolerance * ref.bottom_pressure);
  }
} // namespace

namespace
{
  // Runs the scene to @p end_time, averages the monitors from @p from on,
  // and checks them against the analytic solution for the measured
  // enclosed area and membrane length (tolerances in the file header).
  // Tolerances (see the file header).
  struct Tolerances
  {
    double hw, hw_nominal, tension, tension_nominal, pressure;
    /// Bound on max/mean tension - 1: 1e-2 guards the slip projection
    /// (uniform by construction); no-slip leaves a spread.
    double tension_spread = 1e-2;
  };

  template <int dim>
  void
  check_coarse_geotube(ParameterHandler  &prm,
                       const double       from,
                       const std::string &label,
                       const Tolerances  &tol)
  {
    Simulator<dim>                sim(prm);
    std::map<std::string, double> m;
    unsigned int                  samples = 0;
    while (sim.advance())
      if (sim.get_time() >= from && sim.get_step() % 100 == 0)
        {
          for (const auto &[name, value] : monitors(sim))
            m[name] += value;
          ++samples;
        }
    ASSERT_TRUE(sim.get_termination() == fsgmpm::Termination::end_time
                || sim.get_termination() == fsgmpm::Termination::dr_converged)
      << sim.get_diagnosis();
    ASSERT_GT(samples, 10u);
    for (auto &[name, value] : m)
      value /= samples;
    const auto   ref     = geotube_reference::solve(m.at("membrane_length"),
                                              m.at("enclosed_area"),
                                              12000.);
    const auto   nominal = geotube_reference::solve(9.2, 5.56, 12000.);
    const double hw      = m.at("height") / m.at("width");
    std::printf("measured %s, mean from %.0f s (%u steps): H = %.4f m, W = "
                "%.4f m, H/W = "
                "%.4f; analytic for the measured A = %.4f m^2, L = %.4f m: "
                "H/W = %.4f (error %+.4f); nominal H/W = %.4f (error %+.4f)\n",
                label.c_str(),
                from,
                sim.get_step(),
                m.at("height"),
                m.at("width"),
                hw,
                m.at("enclosed_area"),
                m.at("membrane_length"),
                ref.height / ref.width,
                hw - ref.height / ref.width,
                nominal.height / nominal.width,
                hw - nominal.height / nominal.width);
    std::printf("measured tension %.0f N/m (analytic %.0f, %+.1f%%; nominal "
                "%.0f, %+.1f%%), max/mean - 1 = %.2e; p_top %.0f Pa (analytic "
                "%.0f), p_bottom %.0f Pa (analytic %.0f); contact width %.3f m "
                "(analytic %.3f); fluid volume %.4f m^2; outside %g; Eq. (30) "
                "ratios %.2e / %.2e\n",
                m.at("mean_tension"),
                ref.tension,
                100 * (m.at("mean_tension") / ref.tension - 1),
                nominal.tension,
                100 * (m.at("mean_tension") / nominal.tension - 1),
                m.at("max_tension") / m.at("mean_tension") - 1,
                m.at("top_pressure"),
                ref.top_pressure,
                m.at("bottom_pressure"),
                ref.bottom_pressure,
                m.at("contact_width"),
                ref.contact_width,
                m.at("fluid_volume"),
                m.at("particles_outside"),
                sim.get_monitors().dr_energy_ratio,
                sim.get_monitors().dr_force_ratio);

    // Against the analytic solution for the run's own area and length (the
    // solver's error) and for the nominal ones (the user's error).
    EXPECT_NEAR(hw, ref.height / ref.width, tol.hw);
    EXPECT_NEAR(hw, nominal.height / nominal.width, tol.hw_nominal);
    EXPECT_NEAR(m.at("mean_tension") / ref.tension, 1., tol.tension);
    EXPECT_NEAR(m.at("mean_tension") / nominal.tension,
                1.,
                tol.tension_nominal);
    EXPECT_LT(m.at("max_tension") / m.at("mean_tension") - 1,
              tol.tension_spread);
    EXPECT_EQ(sim.get_monitors().lost_particles, 0u);
    EXPECT_LE(m.at("particles_outside"), 0.005 * sim.get_particles().size());
    // The linear fit of the pressure (16 points per cell; with 4 the bottom
    // pressure came out 11% high).
    expect_pressures(m, ref, tol.pressure);
  }
} // namespace

TEST(GeotubeCoarse, ShapeAndTensionMatchAnalytic)
{
  auto prm = coarse_parameters(12.0);
  check_coarse_geotube<2>(*prm, 8.0, "16 cm", {0.004, 0.008, 0.02, 0.04, 0.03});
}

// The 3D variant (prm/geotube_A5.56_3d.prm): tetrahedra one cell thick with
// roller faces, the membrane an extruded elliptic cylinder of triangles
// (stacked nodes share x-y: plane strain), 8 points per tetrahedron; the
// monitors are per ring and per unit thickness. Tolerances in the file header.
TEST(GeotubeCoarse, Slab3DMatchesAnalytic)
{
  auto prm = coarse_parameters(6.0, "geotube_A5.56_3d.prm");
  check_coarse_geotube<3>(*prm,
                          4.0,
                          "3D slab 16 cm",
                          {0.012, 0.015, 0.03, 0.03, 0.04});
}

// The paper's coupling, no-slip (the membrane nodes move with the grid
// velocity only), with the setting measured to work for it
// (doc/accuracy_vs_cost.md section 1): membrane elements of 0.9 cells (with
// 0.4 cells the cables inside one cell form a zigzag of taut and slack
// cables that the grid cannot see) and the nodal stress projection (without
// it the P1 fill locks volumetrically and holds the initial ellipse; NMD
// unlocks it but drains the area). The relaxation takes about 25 s (3 s with
// slip); averaged over 40-50 s. Measured: H/W +0.0009 (own area and length)
// and -0.0016 (nominal), T +0.7% and -0.6%, max/mean tension - 1 = 1.14 (a
// local zigzag at one edge of the ground contact; elsewhere uniform to
// 1 kN/m), p_top +0.8% and p_bottom +0.0% of p_bottom. Asserted: H/W within
// 0.003 and 0.005, T within 2% and 2%, pressures within 3%, max/mean - 1
// below 1.6.
TEST(GeotubeCoarseValidation, NoSlipMatchesAnalytic)
{
  auto prm = coarse_parameters(50.0);
  set_parameter(*prm, "Membrane/Tangential coupling", "no-slip");
  set_parameter(*prm, "Membrane/Element size", "0.144");
  set_parameter(*prm, "Membrane/Split length", "1");
  set_parameter(*prm, "Output/Directory", "output_geotube_no_slip");
  set_parameter(*prm, "Simulation/Stress integration", "nodal projection");
  check_coarse_geotube<2>(*prm,
                          40.0,
                          "no-slip 16 cm",
                          {0.003, 0.005, 0.02, 0.02, 0.03, 1.6});
}

// Quadratic membrane elements with the slip (MembraneSlip::
// relax_tangential_forces), validation entries: the 2D geotube
// (degree 2, 12.8 cm cells, so the same node spacing as degree 1; 12 s,
// averaged from 8 s; 60 s wall) and the 3D slab (6 s, from 4 s; 170 s).
// Measured (doc/membrane_validation.md, "Quadratic membrane elements"):
// 2D H/W -0.0020 (own) and -0.0030 (nominal), T -0.8% and -1.3%, p_top
// -1.1% and p_bottom +1.4% of p_bottom, max/mean T - 1 = 4.9e-3; 3D
// -0.0046, -0.0054, +1.9%, +1.4%, +0.3%, +0.2%, 3.1e-2 (the quadratic
// triangles' stress varies within the cells; the sub-elements' tension is
// monitored).
TEST(GeotubeCoarseValidation, DegreeTwoSlipMatchesAnalytic)
{
  auto prm = coarse_parameters(12.0);
  set_parameter(*prm, "Membrane/Element degree", "2");
  set_parameter(*prm, "Membrane/Element size", "0.128");
  set_parameter(*prm, "Output/Directory", "output_geotube_degree_2");
  check_coarse_geotube<2>(*prm,
                          8.0,
                          "degree 2 with slip 16 cm",
                          {0.004, 0.008, 0.02, 0.04, 0.03, 0.015});
}

TEST(GeotubeCoarseValidation, Slab3DDegreeTwoSlipMatchesAnalytic)
{
  auto prm = coarse_parameters(6.0, "geotube_A5.56_3d.prm");
  set_parameter(*prm, "Membrane/Element degree", "2");
  set_parameter(*prm, "Membrane/Element size", "0.128");
  set_parameter(*prm, "Output/Directory", "output_geotube_3d_degree_2");
  check_coarse_geotube<3>(*prm,
                          4.0,
                          "3D slab degree 2 with slip 16 cm",
                          {0.012, 0.015, 0.03, 0.03, 0.01, 0.06});
}

TEST(GeotubeCoarseValidation, ConvergesByEq30)
{
  auto         prm = coarse_parameters(30.0);
  Simulator<2> sim(*prm);
  while (sim.advance())
    ;
  std::printf("measured termination %s after %.2f s, Eq. (30) ratios %.2e / "
              "%.2e\n",
              fsgmpm::to_string(sim.get_termination()).c_str(),
              sim.get_time(),
              sim.get_monitors().dr_energy_ratio,
              sim.get_monitors().dr_force_ratio);
  EXPECT_EQ(sim.get_termination(), fsgmpm::Termination::dr_converged);
  const auto m   = monitors(sim);
  const auto ref = geotube_reference::solve(m.at("membrane_length"),
                                            m.at("enclosed_area"),
                                            12000.);
  std::printf("measured p_top %.0f Pa (analytic %.0f), p_bottom %.0f Pa "
              "(analytic %.0f)\n",
              m.at("top_pressure"),
              ref.top_pressure,
              m.at("bottom_pressure"),
              ref.bottom_pressure);
  expect_pressures(m, ref, 0.1);
}

// --- The 3D slab's membrane read from Gmsh --------------------------------
namespace
{
  // The 3D slab, no-slip (the paper's coupling; slip is chord-based, degree
  // 1 only), with the membrane read from tests/meshes/@p mesh (written by
  // tests/meshes/make_elliptic_cylinder.py).
  std::unique_ptr<ParameterHandler>
  slab_parameters(const double       end_time,
                  const std::string &mesh,
                  const unsigned int degree)
  {
    auto prm = coarse_parameters(end_time, "geotube_A5.56_3d.prm");
    set_parameter(*prm, "Membrane/Shape", "gmsh");
    set_parameter(*prm,
                  "Membrane/Mesh file",
                  std::string(FSGMPM_TEST_SOURCE_DIR) + "/meshes/" + mesh);
    set_parameter(*prm, "Membrane/Element degree", degree);
    set_parameter(*prm, "Membrane/Tangential coupling", "no-slip");
    set_parameter(*prm, "Membrane/Split length", 1.);
    set_parameter(*prm, "Simulation/Stress integration", "nodal projection");
    set_parameter(*prm, "Simulation/Termination", "end_time");
    return prm;
  }

  std::vector<unsigned char>
  decode_base64(const std::string &text)
  {
    static const std::string alphabet
      = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<unsigned char> out;
    unsigned int               buffer = 0, bits = 0;
    for (const char c : text)
      {
        const auto k = alphabet.find(c);
        if (k == std::string::npos)
          continue; // '=' padding, white space
        buffer = (buffer << 6) | k;
        bits += 6;
        if (bits >= 8)
          {
            bits -= 8;
            out.push_back((buffer >> bits) & 0xff);
          }
      }
    return out;
  }

  // The bytes of DataArray @p name of a VTU that deal.II's DataOut wrote:
  // base64 of a header of four uint32 (one block, its size twice, the
  // compressed size), then base64 of the zlib-compressed block.
  std::vector<unsigned char>
  vtu_array(const std::string &vtu, const std::string &name)
  {
    const auto start = vtu.find("Name=\"" + name + "\"");
    if (start == std::string::npos)
      return {};
    const auto        open  = vtu.find('>', start) + 1;
    std::string       data  = vtu.substr(open, vtu.find('<', open) - open);
    const std::size_t first = data.find_first_not_of(" \n");
    data                    = data.substr(first);
    const auto header       = decode_base64(data.substr(0, 24));
    uint32_t   h[4];
    std::memcpy(h, header.data(), sizeof(h));
    EXPECT_EQ(h[0], 1u);
    const auto                 compressed = decode_base64(data.substr(24));
    std::vector<unsigned char> bytes(h[1]);
    uLongf                     size = h[1];
    EXPECT_EQ(uncompress(bytes.data(), &size, compressed.data(), h[3]), Z_OK);
    return bytes;
  }
} // namespace

// Second-order Gmsh triangles at degree 2 run and are written by deal.II's
// DataOut (Output/Membrane output = finite elements): 80 quadratic
// triangles (VTK Lagrange triangles, 6 points each) with tension,
// minor_tension, tension_tensor, stretch, velocity and displacement; the
// largest tension in the file is the membrane's (single precision), and the
// tension tensor's trace is tension + minor_tension (both are averages of
// the same quadrature points, and the trace is linear).
TEST(GeotubeCoarse, GmshSecondOrderWrittenByDataOut)
{
  auto prm = slab_parameters(0.2, "geotube_A5.56_p2.msh", 2);
  set_parameter(*prm, "Output/Directory", "output_gmsh_p2");
  set_parameter(*prm, "Output/Output interval", 0.1);
  set_parameter(*prm, "Output/Membrane output", "finite elements");
  Simulator<3> sim(*prm);
  ASSERT_EQ(sim.run(), fsgmpm::Termination::end_time) << sim.get_diagnosis();
  const auto &membrane = *sim.get_membrane();
  // 40 x 2 corners and the middle nodes of 40 x 4 edges.
  EXPECT_EQ(membrane.n_nodes(), 240u);

  std::ifstream     in("output_gmsh_p2/membrane_00002.vtu");
  std::stringstream text;
  text << in.rdbuf();
  const std::string vtu = text.str();
  EXPECT_NE(vtu.find("NumberOfPoints=\"480\" NumberOfCells=\"80\""),
            std::string::npos);
  const auto types = vtu_array(vtu, "types");
  ASSERT_EQ(types.size(), 80u);
  for (const unsigned char t : types)
    EXPECT_EQ(t, 69); // VTK_LAGRANGE_TRIANGLE
  for (const std::string name :
       {"velocity", "displacement", "minor_tension", "stretch"})
    EXPECT_NE(vtu.find("Name=\"" + name + "\""), std::string::npos) << name;
  const auto bytes = vtu_array(vtu, "tension");
  ASSERT_EQ(bytes.size(), 480 * sizeof(float));
  std::vector<float> tension(480);
  std::memcpy(tension.data(), bytes.data(), bytes.size());
  const double written = *std::max_element(tension.begin(), tension.end());
  const double largest
    = *std::max_element(membrane.tension.begin(), membrane.tension.end());
  std::printf("measured largest tension at 0.2 s: %.1f N/m (file %.1f)\n",
              largest,
              written);
  EXPECT_GT(largest, 1000.);
  EXPECT_NEAR(written, largest, 1e-6 * largest);

  const auto minor_bytes  = vtu_array(vtu, "minor_tension");
  const auto tensor_bytes = vtu_array(vtu, "tension_tensor");
  ASSERT_EQ(minor_bytes.size(), 480 * sizeof(float));
  ASSERT_EQ(tensor_bytes.size(), 480 * 9 * sizeof(float));
  std::vector<float> minor(480), tensor(480 * 9);
  std::memcpy(minor.data(), minor_bytes.data(), minor_bytes.size());
  std::memcpy(tensor.data(), tensor_bytes.data(), tensor_bytes.size());
  double worst_trace = 0;
  for (unsigned int p = 0; p < 480; ++p)
    worst_trace
      = std::max(worst_trace,
                 std::abs(double(tensor[9 * p]) + tensor[9 * p + 4]
                          + tensor[9 * p + 8] - tension[p] - minor[p]));
  std::printf("measured |trace(tension_tensor) - tension - minor_tension| "
              "<= %.2e N/m\n",
              worst_trace);
  EXPECT_LT(worst_trace, 1e-6 * largest);
}
