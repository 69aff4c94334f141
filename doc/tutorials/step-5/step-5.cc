/* ---------------------------------------------------------------------
 * fsgmpm tutorial step-5: a geocontainer drops through water
 * ---------------------------------------------------------------------
 *
 * <h1>Introduction</h1>
 *
 * The paper's application (Hamad et al. 2017, Section 5; Bezuijen et al.'s
 * tests at Deltares): a geotextile container holding 25 kg of sand is
 * released on the surface of a 0.8 m deep water tank. It was measured to
 * sink at 0.8 m/s at 0.8 s (the paper's Fig. 15); the paper's own
 * simulation reaches the floor at 1.1 s (its Fig. 11). The three
 * materials of steps 1-3 meet: sand (Mohr-Coulomb, Eqs. 5-8, Hill rate
 * Eq. 6, K0 initial stress), a geotextile (step-3's tension-only cables,
 * Eqs. 9-10 in one dimension, EA = 50 kN/m) and water (Eqs. 11-16, free
 * surface Eqs. 31-33). The scene is `prm/geocontainer_polygon.prm`; the
 * assumptions the paper leaves open (a pentagonal section of 0.0202 m^2
 * and perimeter 0.62 m, the tank, the textile's areal mass) are in
 * doc/geocontainer_validation.md.
 *
 * <h3>Sand and membrane: shared grid nodes</h3>
 *
 * The membrane is a finite-element chain inside the MPM grid (Section
 * 2.1.2): its nodes add their mass and momentum to the grid nodes of their
 * cells, as material points do in Eq. (17); their tensions join the
 * internal force, Eq. (3); after the grid update (Eqs. 18-20) they move
 * with the grid velocity at their positions, Eq. (21). Sand and membrane
 * share grid nodes and move together: the paper's no-slip coupling.
 *
 * <h3>Water: a second velocity field, frictionless contact</h3>
 *
 * The paper puts the water on the same nodes (its "non-slip contact
 * approach"). Then water within a cell of the bag moves with it, its
 * contact line cannot pass over the bag's top corner, and the bag floats
 * in a depression of the surface (doc page, section 4). So the water gets
 * a velocity field of its own (`Velocity field = 1`): each grid node
 * carries a mass, momentum and velocity per field, Eqs. (17)-(20) are
 * solved per field, and where the points of both fields fill half a node's
 * volume (`Contact volume fraction`) a frictionless contact (Bardenhagen,
 * Brackbill and Sulsky 2000) gives both the normal velocity of their
 * common centre of mass while they approach; they slide and separate
 * freely. Two more choices, both measured on the doc page: the water is
 * weakly compressible (K_f = 2.13e7 Pa, sound speed 146 m/s; the real
 * 2.13e9 moves the velocity history to 0.8 s by 0.005 m/s RMS at 4 cm),
 * and the stress is integrated from a linear nodal field (`Stress
 * integration = nodal projection`) instead of the paper's NMD and ANP
 * (Eqs. 22-29), under which the water's point cloud compacted and its
 * falling points fed the sinking.
 *
 * <h3>What the program measures</h3>
 *
 * The sinking velocity and the height over the floor against time, against
 * the experiment; and the energy balance: the work of gravity on sand and
 * water, the kinetic energy, and the rest, dissipated (plastic work,
 * viscosity, and the numerical dissipation of the grid transfers). Water
 * that keeps its volume rises where the bag displaces it: the sinking is
 * paid for by the sand alone.
 */

// @sect3{Include files}
//
// As in steps 1-4, plus the container monitors of the library (points
// that crossed the membrane).
#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/monitors/container_monitor.h>
#include <fsgmpm/scene/parameter_path.h>
#include <fsgmpm/scene/parameters.h>
#include <fsgmpm/simulator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace Step5
{
  using namespace dealii;
  using namespace fsgmpm;

  // @sect3{The scene}
  //
  // prm/geocontainer_polygon.prm without its monitors and output, as text. The
  // sand (body 0, `Shape = membrane`) fills the inside of the membrane with 16
  // points per triangle; the water (body 1) fills the tank with 4, leaving
  // out the regions of the bodies before it, here the bag. The tank's
  // sides are one-sided frictionless walls (`slip`: water may leave them),
  // its floor a `roller`; the membrane nodes also feel the floor themselves
  // (`Ground level`). FLIP's sub-cell noise is relaxed over 10 ms toward
  // XPIC(4)'s velocity, which drops the noise but keeps the resolved flow
  // (a blend toward PIC's would add a viscosity h^2 / (6 tau), 6 650 times
  // water's at 2 cm). The tank reaches 1.2 m above the water, for the jet
  // that rises where the water closes over the bag. Gravity, the Courant
  // number 0.5 and the grid's lower corner (0, 0) are defaults.
  void
  describe_scene(ParameterHandler  &prm,
                 const double       cell_size,
                 const double       end_time,
                 const unsigned int threads)
  {
    Parameters<2>::declare_parameters(prm);
    prm.parse_input_from_string(R"(
subsection Simulation
  set FLIP noise relaxation time = 0.01
  set XPIC order                 = 4
  set Contact volume fraction    = 0.5
  set Stress integration         = nodal projection
end
subsection Grid
  set Upper corner        = 2, 2
  set Boundary conditions = 0: slip, 1: slip, 2: roller
end
subsection Membrane
  set Enabled             = true
  set Shape               = polygon
  set Polygon vertices    = 1.0, 0.8; 1.13564, 0.88007; 1.09495, 0.92076; 0.90505, 0.92076; 0.86436, 0.88007
  set Circumference       = 0.62
  set Enclosed area       = 0.0202429
  set Lowest point        = 1.0, 0.8
  set Axial stiffness     = 5e4
  set Poisson ratio       = 0
  set Areal mass          = 0.3
  set Tangential coupling = no-slip
  set Ground level        = 0
end
subsection Bodies
  set Number of bodies = 2
  subsection Body 0
    set Shape              = membrane
    set Particles per cell = 16
    set Density            = 1900
    set Material model     = Mohr-Coulomb
    set Initial stress     = geostatic
    set K0                 = 0.5
    subsection Mohr-Coulomb
      set Young's modulus = 3e5
      set Poisson's ratio = 0.333
      set Friction angle  = 30
      set Dilatancy angle = 0
      set Cohesion        = 1000
    end
  end
  subsection Body 1
    set Shape              = box
    set Box lower corner   = 0, 0
    set Box upper corner   = 2, 0.8
    set Particles per cell = 4
    set Density            = 1000
    set Material model     = Newtonian fluid
    set Initial stress     = hydrostatic
    set Velocity field     = 1
    subsection Newtonian fluid
      set Bulk modulus = 2.13e7
      set Viscosity    = 8.9e-4
    end
  end
end
subsection Output
  set Directory = output_step-5
  set Quiet     = true
end
)");
    set_parameter(prm, "Grid/Cell size", cell_size);
    set_parameter(prm, "Simulation/End time", end_time);
    set_parameter(prm, "Simulation/Number of threads", double(threads));
  }



  // @sect3{Our measurements}
  //
  // From the points, per body: mass, centre of mass, vertical momentum,
  // kinetic energy. The container's velocity is the sand's mass-weighted
  // one (the textile carries 0.5% of the mass and is left out), its height
  // over the floor that of the lowest membrane node.
  struct Body
  {
    double mass = 0, y = 0, v = 0, kinetic_energy = 0;
  };

  std::array<Body, 2>
  measure_bodies(const ParticleStore<2> &particles)
  {
    std::array<Body, 2> b;
    for (unsigned int p = 0; p < particles.size(); ++p)
      {
        Body        &body = b[particles.body_id[p]];
        const double m    = particles.mass[p];
        body.mass += m;
        body.y += m * particles.position[p][1];
        body.v += m * particles.velocity[p][1];
        body.kinetic_energy += 0.5 * m * particles.velocity[p].norm_square();
      }
    for (Body &body : b)
      body.y /= body.mass, body.v /= body.mass;
    return b;
  }

  std::pair<double, double>
  membrane_heights(const Membrane<2> &membrane)
  {
    std::pair<double, double> y(membrane.position[0][1],
                                membrane.position[0][1]);
    for (const Point<2> &x : membrane.position)
      y = {std::min(y.first, x[1]), std::max(y.second, x[1])};
    return y;
  }



  // @sect3{The run}
  //
  // We drive the Simulator step by step as in step-1. Every 10 ms a line
  // goes to step-5.csv, every 0.1 s to the screen. The energy balance
  // between the start and now: W_g is the work of gravity, g sum m_b (y_b(0)
  // - y_b) over the bodies; what is neither kinetic nor stored (elastic
  // energy, the `strain_energy` monitor) has been dissipated. We stop when
  // the container has landed: its lowest node within a cell of the floor
  // and the sand no longer moving down.
  void
  run(const double cell_size, const double end_time, const unsigned int threads)
  {
    ParameterHandler prm;
    describe_scene(prm, cell_size, end_time, threads);
    Simulator<2>       simulator(prm);
    const Membrane<2> &membrane = *simulator.get_membrane();
    const double       g = 9.81, water_level = 0.8, tank_width = 2;

    const std::array<Body, 2> start = measure_bodies(simulator.get_particles());
    const double              sand_area
      = container_monitors(simulator.get_particles(), &membrane, 0)
          .at("soil_area");
    const double strain_energy_0 = simulator.get_monitors().strain_energy;
    std::cout << "Cell size " << cell_size
              << " m: " << simulator.get_particles().size() << " points, "
              << membrane.n_nodes() << " membrane nodes, sand " << start[0].mass
              << " kg/m, water " << start[1].mass << " kg/m.\n"
              << "  t [s]  v [m/s]  y_c [m]  bottom [m]  E_kin [J]  W_g [J]"
                 "  dissipated [J]\n";

    std::ofstream csv("step-5.csv");
    csv << "t,v_down,y_sand,bottom,W_sand,W_water,E_kin_sand,E_kin_water,"
           "dissipated\n";
    const std::vector<double> check_times = {0.2, 0.4, 0.6, 0.8};
    std::vector<double>       velocities;
    double       next_csv = 0, next_report = 0, landed_at = -1, depth_in = 0;
    double       t_old = 0, v_old = 0;
    unsigned int most_inside = 0;
    for (bool running = true; running;)
      {
        running             = simulator.advance();
        const double t      = simulator.get_time();
        const auto   b      = measure_bodies(simulator.get_particles());
        const double bottom = membrane_heights(membrane).first;
        // The velocity at a check time, interpolated in the step that
        // crosses it (so that a run ending there gives the same figure).
        if (velocities.size() < check_times.size()
            && t >= check_times[velocities.size()] - 1e-12)
          velocities.push_back(v_old
                               + (-b[0].v - v_old)
                                   * (check_times[velocities.size()] - t_old)
                                   / (t - t_old));
        t_old = t, v_old = -b[0].v;
        if (landed_at < 0 && bottom < cell_size && b[0].v >= 0)
          landed_at = t, running = false;
        if (t < next_csv - 1e-12 && running)
          continue;
        next_csv += 0.01;
        const auto c
          = container_monitors(simulator.get_particles(), &membrane, 0);
        most_inside
          = std::max<unsigned int>(most_inside, c.at("water_points_inside"));
        depth_in             = std::max(depth_in, c.at("water_inside_depth"));
        const double w_sand  = start[0].mass * g * (start[0].y - b[0].y);
        const double w_water = start[1].mass * g * (start[1].y - b[1].y);
        const double e_kin   = b[0].kinetic_energy + b[1].kinetic_energy;
        const double dissipated
          = w_sand + w_water - e_kin
            - (simulator.get_monitors().strain_energy - strain_energy_0);
        csv << t << ',' << -b[0].v << ',' << b[0].y << ',' << bottom << ','
            << w_sand << ',' << w_water << ',' << b[0].kinetic_energy << ','
            << b[1].kinetic_energy << ',' << dissipated << '\n';
        if (t >= next_report - 1e-9 || !running)
          {
            std::cout << std::fixed << std::setprecision(2) << std::setw(7) << t
                      << std::setprecision(3) << std::setw(9) << -b[0].v
                      << std::setw(9) << b[0].y << std::setw(12) << bottom
                      << std::setprecision(1) << std::setw(11) << e_kin
                      << std::setw(9) << w_sand + w_water << std::setw(16)
                      << dissipated << '\n';
            next_report += 0.1;
          }
      }
    AssertThrow(
      landed_at > 0 || simulator.get_termination() == Termination::end_time,
      ExcMessage("The run stopped early: " + simulator.get_diagnosis()));

    // @sect3{Against the experiment}
    //
    // The velocities at the check times, the landing, and the audit of the
    // water: keeping its volume around a submerged bag of area A at height
    // y_c, its centre of mass rises by rho_w A (h_0 + A/(2 L) - y_c)/M_w
    // (h_0 the water level, L the tank's width: the water of the bag's new
    // place spreads over the tank).
    for (unsigned int i = 0; i < velocities.size(); ++i)
      std::cout << "Sinking velocity at " << std::setprecision(1)
                << check_times[i] << " s: " << std::setprecision(5)
                << velocities[i] << " m/s"
                << (i == 3 ? " (experiment 0.8 m/s)\n" : "\n");
    const auto [bottom, top] = membrane_heights(membrane);
    std::cout
      << std::setprecision(3)
      << (landed_at > 0 ? "Landed at " : "Not landed by ")
      << simulator.get_time() << " s, the lowest node " << bottom
      << " m above the floor (the paper's simulation: landed at 1.1 s).\n";
    const auto b = measure_bodies(simulator.get_particles());
    if (top < water_level)
      std::cout << "The water's centre of mass rose "
                << 1e3 * (b[1].y - start[1].y) << " mm; keeping its volume: "
                << 1e3 * 1000 * sand_area
                     * (water_level + sand_area / (2 * tank_width) - b[0].y)
                     / start[1].mass
                << " mm.\n";
    std::cout << "Water points inside the membrane: at most " << most_inside
              << " (" << std::setprecision(1) << 1e3 * depth_in
              << " mm deep at most). Steps: " << simulator.get_step() << ".\n";
  }
} // namespace Step5



// @sect3{The main function}
//
// `./step-5 [cell size] [end time] [threads]`: 4 cm cells and 3 s by
// default (the run stops when the container lands), all cores.
int
main(int argc, char **argv)
{
  try
    {
      const double       cell_size = (argc > 1) ? std::stod(argv[1]) : 0.04;
      const double       end_time  = (argc > 2) ? std::stod(argv[2]) : 3.0;
      const unsigned int threads   = (argc > 3) ? std::stoi(argv[3]) : 0;
      Step5::run(cell_size, end_time, threads);
    }
  catch (std::exception &exc)
    {
      std::cerr << "step-5: error: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}

/* <h1>Results</h1>
 *
 * The output of this program and what it shows are in README.md beside
 * this file.
 */
