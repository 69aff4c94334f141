/* ---------------------------------------------------------------------
 * fsgmpm tutorial step-3: a geotube
 * ---------------------------------------------------------------------
 *
 * <h1>Introduction</h1>
 *
 * A geotube is a long geotextile tube filled with a slurry; lying on the
 * ground it flattens until the tension of the textile and the pressure of
 * the fill balance. Its cross-section is the paper's first test (Hamad et
 * al. 2017, Section 3.3; `prm/geotube_A5.56.prm`): a textile of
 * circumference L = 9.2 m holds A = 5.56 m^2 of a fluid of unit weight
 * gamma = 12 kN/m^3 on smooth rigid ground. This program lets it settle,
 * measures the shape, the tension and the pressures, and compares them with
 * the analytic solution, on three meshes.
 *
 * <h3>The membrane</h3>
 *
 * The textile is a finite-element membrane inside the MPM frame: in 2D a
 * closed chain of 2-node cables whose nodes exchange mass, momentum and
 * force with the background grid like material points (the FEM-MPM
 * coupling of the paper's Section 2.1.2). A textile carries no compression;
 * the paper cuts it off in the principal stresses of the membrane, Eq. (9),
 * sigma_I,II = (sigma_11 + sigma_22)/2 -+ sigma_m with the Mohr radius
 * sigma_m = sqrt(((sigma_11 - sigma_22)/2)^2 + sigma_12^2), and when the
 * elastic predictor gives sigma_II < 0 it shrinks the Mohr circle by a
 * homothety until sigma_II = 0, Eq. (10) (fsgmpm's 3D membrane triangles
 * do exactly this). A cable has a single principal stress, the axial one,
 * so the cut-off becomes T = EA max(0, l/l_0 - 1): a shortened cable goes
 * slack. Here EA = 50 MN/m, practically inextensible. The contact between
 * textile and fill is frictionless (`Tangential coupling = slip`): the
 * nodes slide along the membrane so that the tension is uniform, as a
 * fluid at rest, which carries no shear, requires.
 *
 * <h3>Dynamic relaxation and Eq. (30)</h3>
 *
 * The tube starts as the ellipse of the same circumference and area, with
 * a hydrostatic fill, and falls into its shape. We want the state at rest,
 * not the motion, so the paper lets a viscous fill (mu = 1 Pa s) damp the
 * sloshing, and judges the result by two ratios on the grid nodes,
 *
 *   E_kin / W_ext <= E_v   and   |F_ext - F_int| / |F_ext| <= E_f,  (30)
 *
 * with E_kin = 1/2 sum_i m_i v_i.v_i and W_ext the work of the external
 * forces so far, the forces over the unconstrained nodal components (no
 * support reactions); the paper uses E_v = E_f = 0.05. fsgmpm adds local
 * damping (a force -alpha |F_unbalanced| sign(v) on every node, alpha =
 * 0.7), which does not change the state at rest, and a mass scaling that
 * lifts the time step of the stiff membrane to the fluid's. The fill is
 * weakly compressible, K = 2.7e7 Pa instead of the paper's 2.13e9: the
 * largest pressure is then 1e-3 of K, H/W and T move by less than 1%, and
 * the run takes 15 times fewer steps (doc/membrane_validation.md).
 *
 * <h3>The analytic solution</h3>
 *
 * Leshchinsky et al. (1996): an inextensible weightless membrane holding a
 * hydrostatic fluid on a frictionless base has a constant tension T and
 * the curvature p(y)/T with p(y) = p_top + gamma (H - y); the bottom is a
 * flat strip of width b. Two equilibria check it: p_bottom b = gamma A
 * (vertical) and 2T = p_top H + gamma H^2/2 (a half section, horizontal).
 * For L = 9.2 m and A = 5.56 m^2 it gives H/W = 0.495 (the paper: 0.50) and
 * pressures 4.71 to 26.45 kPa (the paper's MPM: 4.4 to 26.7 kPa).
 * geotube_reference::solve() (include/fsgmpm/reference/, header only)
 * computes it by shooting. We compare with it twice: for the run's own
 * enclosed area and membrane length (the solver's error) and for the
 * nominal 5.56 m^2 and 9.2 m (the error a user sees, including that of
 * filling the ellipse with points).
 */

// @sect3{Include files}
//
// The Simulator and its parameters as in step-1 (set_parameter() sets one
// by its path), the geotube monitors of the membrane, and the analytic
// solution, a header-only part of the library.
#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/monitors/geotube_monitor.h>
#include <fsgmpm/reference/geotube_reference.h>
#include <fsgmpm/scene/parameter_path.h>
#include <fsgmpm/scene/parameters.h>
#include <fsgmpm/simulator.h>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace Step3
{
  using namespace dealii;
  using namespace fsgmpm;

  // @sect3{The scene}
  //
  // prm/geotube_A5.56.prm with the weakly compressible fill, as text. The
  // body `Shape = membrane` fills the inside of the membrane with 16 points
  // per cell; the ground acts on the membrane nodes (`Ground level`), and
  // the grid reaches below it. The paper smooths the fill with NMD and ANP
  // (its Eqs. 22-29); next to a membrane they drain it here, so the fill
  // is unsmoothed (doc/membrane_validation.md). Damping/Energy and Force
  // tolerance are Eq. (30)'s E_v and E_f, here the paper's 0.05; the
  // Simulator counts the consecutive steps for which both hold
  // (get_converged_steps()), and with `Simulation/Termination =
  // dr_converged` it would stop once they span the `Convergence window`
  // (1000 steps). We run to the End time instead and watch.
  void
  describe_scene(ParameterHandler &prm,
                 const double      cell_size,
                 const double      end_time)
  {
    Parameters<2>::declare_parameters(prm);
    prm.parse_input_from_string(R"(
subsection Simulation
  set Dimension = 2
  set Gravity   = 0, -9.81
end
subsection Damping
  set Local damping coefficient = 0.7
  set Mass scaling              = true
  set Energy tolerance          = 0.05
  set Force tolerance           = 0.05
end
subsection Grid
  set Lower corner        = 0, -0.32
  set Upper corner        = 6, 3.2
  set Boundary conditions = 2: roller
end
subsection Membrane
  set Enabled             = true
  set Shape               = ellipse
  set Circumference       = 9.2
  set Enclosed area       = 5.56
  set Lowest point        = 3, 0
  set Axial stiffness     = 5e7
  set Areal mass          = 0.5
  set Tangential coupling = slip
  set Ground level        = 0
  set Ground stiffness    = 1e7
end
subsection Bodies
  subsection Body 0
    set Shape                  = membrane
    set Particles per cell     = 16
    # 12 kN/m^3 / 9.81 m/s^2
    set Density                = 1223.24159021407
    set Material model         = Newtonian fluid
    set Initial stress         = hydrostatic
    set Volumetric smoothing   = none
    set Free surface detection = false
    subsection Newtonian fluid
      set Bulk modulus  = 2.7e7
      set Viscosity     = 1.0
      set Allow tension = true
    end
  end
end
subsection Output
  set Quiet = true
end
)");
    set_parameter(prm, "Simulation/End time", std::to_string(end_time));
    set_parameter(prm, "Grid/Cell size", std::to_string(cell_size));
  }



  // @sect3{The run}
  //
  // One mesh: relax to @p end_time, print Eq. (30) once a second, and
  // average the geotube monitors over the last quarter of the run (every
  // 100th step: they test every point against the membrane polygon). A
  // single step's force ratio jumps whenever a point crosses a cell edge
  // (its V_p p grad N changes at once), so we print the median and the
  // smallest value of each second. fsgmpm::membrane_monitors() measures H
  // and W as max - min of the membrane nodes, the contact width from the
  // nodes within a tenth of a cell of the lowest one, the length-weighted
  // mean tension, and p_top and p_bottom from a least-squares line of the
  // point pressures against y over a central strip two cells wide.
  struct Result
  {
    std::map<std::string, double> m; // the monitors' averages
    double       force_ratio = 0, converged_at = -1, wall_seconds = 0;
    unsigned int steps = 0;
  };

  double
  median(std::vector<double> v)
  {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  }

  Result
  relax(const double cell_size, const double end_time)
  {
    const auto       start = std::chrono::steady_clock::now();
    ParameterHandler prm;
    describe_scene(prm, cell_size, end_time);
    Simulator<2> simulator(prm);
    std::cout
      << std::defaultfloat << "\nCell size " << cell_size
      << " m: " << simulator.get_particles().size() << " points, "
      << simulator.get_membrane()->n_nodes() << " membrane nodes.\n"
      << "  t [s]  E_kin/W_ext   force ratio: median      min     H/W\n";

    Result              r;
    std::vector<double> ratios, late_ratios;
    double              next_report = 1;
    unsigned int        samples     = 0;
    for (bool running = true; running;)
      {
        running              = simulator.advance();
        const double    t    = simulator.get_time();
        const Monitors &eq30 = simulator.get_monitors();
        ratios.push_back(eq30.dr_force_ratio);
        if (t >= 0.75 * end_time)
          late_ratios.push_back(eq30.dr_force_ratio);
        if (r.converged_at < 0
            && simulator.get_converged_steps()
                 >= simulator.get_parameters().relaxation.convergence_window)
          r.converged_at = t;

        const bool report = (t >= next_report - 1e-9) || !running;
        const bool sample
          = t >= 0.75 * end_time && simulator.get_step() % 100 == 0;
        if (!report && !sample)
          continue;
        const auto m = membrane_monitors(*simulator.get_membrane(),
                                         simulator.get_particles(),
                                         0.1 * cell_size,
                                         2 * cell_size);
        if (sample)
          {
            for (const auto &[name, value] : m)
              r.m[name] += value;
            ++samples;
          }
        if (report)
          {
            std::cout << std::fixed << std::setprecision(1) << std::setw(7) << t
                      << std::scientific << std::setw(13)
                      << eq30.dr_energy_ratio << std::setw(23) << median(ratios)
                      << std::setw(9)
                      << *std::min_element(ratios.begin(), ratios.end())
                      << std::fixed << std::setprecision(4) << std::setw(8)
                      << m.at("height") / m.at("width") << '\n';
            ratios.clear();
            next_report += 1;
          }
      }
    AssertThrow(simulator.get_termination() == Termination::end_time,
                ExcMessage("The run stopped early: "
                           + simulator.get_diagnosis()));
    for (auto &[name, value] : r.m)
      value /= samples;
    r.force_ratio = median(late_ratios);
    r.steps       = simulator.get_step();
    r.wall_seconds
      = std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    return r;
  }



  // @sect3{The comparison}
  //
  // The averaged monitors against the analytic solution for the run's own
  // area and length, and against the nominal one. The analytic contact
  // width is measured as the monitor measures it, from the points of the
  // analytic shape within a tenth of a cell of the ground (the membrane
  // leaves the ground tangentially, so this is wider than the strip b).
  // One line of errors goes to @p table.
  void
  compare(const Result &r, const double cell_size, std::ostream &table)
  {
    const auto &m       = r.m;
    const auto  own     = geotube_reference::solve(m.at("membrane_length"),
                                              m.at("enclosed_area"),
                                              12000.);
    const auto  nom     = geotube_reference::solve(9.2, 5.56, 12000.);
    const auto  contact = [&](const geotube_reference::Solution &s) {
      double x0 = s.width, x1 = -s.width;
      for (const auto &p : s.shape)
        if (p[1] <= 0.1 * cell_size)
          x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
      return x1 - x0;
    };
    const double hw = m.at("height") / m.at("width");
    std::cout << std::defaultfloat << std::showpoint << std::setprecision(4)
              << "Eq. (30) at 0.05 over 1000 steps: ";
    if (r.converged_at < 0)
      std::cout << "not met";
    else
      std::cout << "met at t = " << r.converged_at << " s";
    std::cout << ". Averages over the last quarter:\n"
              << std::setprecision(5) << "enclosed area "
              << m.at("enclosed_area") << " m^2 (fluid volume "
              << m.at("fluid_volume") << "), membrane length "
              << m.at("membrane_length") << " m\n"
              << std::setprecision(4)
              << "                      fsgmpm  analytic: own A, L   nominal\n";
    for (const auto &[name, value, a, b] :
         std::vector<std::tuple<std::string, double, double, double>>{
           {"H [m]", m.at("height"), own.height, nom.height},
           {"W [m]", m.at("width"), own.width, nom.width},
           {"H/W", hw, own.height / own.width, nom.height / nom.width},
           {"contact width [m]",
            m.at("contact_width"),
            contact(own),
            contact(nom)},
           {"T [kN/m]", m.at("mean_tension"), own.tension, nom.tension},
           {"p_top [kPa]",
            m.at("top_pressure"),
            own.top_pressure,
            nom.top_pressure},
           {"p_bottom [kPa]",
            m.at("bottom_pressure"),
            own.bottom_pressure,
            nom.bottom_pressure}})
      {
        const double unit = (name[0] == 'T' || name[0] == 'p') ? 1e-3 : 1.;
        std::cout << std::setw(20) << name << std::setw(10) << value * unit
                  << std::setw(19) << a * unit << std::setw(10) << b * unit
                  << '\n';
      }
    const double e_hw = hw - own.height / own.width;
    const double e_t  = 100 * (m.at("mean_tension") / own.tension - 1);
    const double e_p
      = 100 * (m.at("bottom_pressure") / own.bottom_pressure - 1);
    std::cout << std::noshowpoint << std::fixed << std::setprecision(2)
              << "Result at " << cell_size << " m: H/W " << std::setprecision(4)
              << hw << " (error " << std::showpos << e_hw << std::noshowpos
              << "), T " << std::setprecision(2) << m.at("mean_tension") / 1e3
              << " kN/m (error " << std::showpos << e_t << "%)\n"
              << std::noshowpos;
    table << std::fixed << std::setprecision(2) << std::setw(7) << cell_size
          << std::showpos << std::setprecision(4) << std::setw(11) << e_hw
          << std::setprecision(2) << std::setw(11) << e_t << std::setw(15)
          << e_p << std::noshowpos << std::setprecision(3) << std::setw(13)
          << r.force_ratio << std::setw(8) << r.steps << std::setprecision(0)
          << std::setw(10) << r.wall_seconds << '\n';
  }
} // namespace Step3



// @sect3{The main function}
//
// `./step-3 [end time] [cell sizes...]`: by default 20 s of relaxation on
// 32, 16 and 8 cm cells. A table of the errors against the analytic solution
// for the run's own area and length, with the median force ratio over the
// averaging window and the cost, closes the run.
int
main(int argc, char **argv)
{
  using namespace Step3;
  try
    {
      const double        end_time = (argc > 1) ? std::stod(argv[1]) : 20.;
      std::vector<double> cells;
      for (int i = 2; i < argc; ++i)
        cells.push_back(std::stod(argv[i]));
      if (cells.empty())
        cells = {0.32, 0.16, 0.08};
      std::ostringstream table;
      for (const double h : cells)
        compare(relax(h, end_time), h, table);
      std::cout << "\nErrors against the analytic solution for the run's own "
                   "area and length:\n"
                << "  h [m]  H/W error  T error %  p_bot error %  "
                   "force ratio   steps  wall [s]\n"
                << table.str();
    }
  catch (std::exception &exc)
    {
      std::cerr << "step-3: error: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}

/* <h1>Results</h1>
 *
 * The output of this program and what it shows are in README.md beside
 * this file.
 */
