/* ---------------------------------------------------------------------
 * fsgmpm tutorial step-2: a material of your own, a Bingham mud
 * ---------------------------------------------------------------------
 *
 * <h1>Introduction</h1>
 *
 * fsgmpm's material models are plug-ins: a model is a class with a
 * parameter subsection of its own, registered by name, and a body of a
 * scene selects it with `Material model = <name>`, exactly as it selects
 * the built-in models. This tutorial writes one in its own file, without
 * touching the library: a Bingham mud, a fluid that does not flow below a
 * yield stress tau_y and flows with the plastic viscosity mu_p above it,
 *
 *   tau = tau_y + mu_p gamma_dot       where it flows (|tau| > tau_y),
 *   gamma_dot = 0                      elsewhere.
 *
 * The textbook way to compute this is a regularised viscosity,
 * eta = min(eta_max, mu_p + tau_y/gamma_dot). In an explicit code that is
 * expensive: the time step falls as 1/eta_max (the viscous limit), and a
 * small eta_max lets the "rigid" mud creep. We write it instead as an
 * elasto-viscoplastic fluid (in the spirit of Saramito, 2007): the
 * deviatoric stress s is elastic with a shear modulus G below the yield
 * stress, and above it relaxes towards the yield surface over the time
 * t_r = mu_p / G (a Duvaut-Lions overstress),
 *
 *   s_trial = R s R^T + 2 G dt dev(d),
 *   s = s_trial                                  if tau(s_trial) <= tau_y,
 *   s = (s_trial + (dt/t_r) s_y) / (1 + dt/t_r)  otherwise,
 *
 * with tau(s) = sqrt(s:s/2), s_y = tau_y s_trial / tau(s_trial) the
 * trial stress scaled back to the yield surface, and R the step's rotation
 * (the Hill rate of the library's solids). In steady shear at the rate
 * gamma_dot this gives tau = tau_y + mu_p gamma_dot exactly, and at rest
 * the mud is an elastic solid: it stops. The pressure is the one of the
 * library's weakly compressible Newtonian fluid, p = -K (J - 1) >= 0, so
 * the mud is a Newtonian fluid whose deviatoric stress law we replace: we
 * derive from fsgmpm::NewtonianFluid.
 *
 * The program
 * - checks the model on a single point in steady simple shear against
 *   tau_y + mu_p gamma_dot (the test every new material needs before it
 *   goes into a scene);
 * - runs the water column of step-1 once with water and once with mud,
 *   and prints the two fronts;
 * - compares the mud's deposit with what plasticity allows. Mud sticks to
 *   the floor (we give it a no-slip floor; the water keeps step-1's
 *   frictionless one), so a layer of depth h(x) at rest carries its
 *   surface slope on the floor's shear stress, rho g h |dh/dx| <= tau_y
 *   (the shallow-layer limit of Liu and Mei, 1989). The steepest deposit a
 *   front at x_f admits is h_s(x) = sqrt(2 tau_y (x_f - x)/(rho g)); a
 *   deposit at rest must lie below it, and the smallest run-out the
 *   column's area A = 2a^2 can have is the one that fills it,
 *   L_s = (3 A / (2 sqrt(2 tau_y/(rho g))))^(2/3) = 0.391 m. Inertia
 *   carries a collapsing column further than that; how much further is
 *   the dynamics, which the program measures.
 */

// @sect3{Include files}
//
// Besides the Simulator and the parameters of step-1, the material
// interface (the kinematics a material receives), the Newtonian fluid we
// derive from, the registration macro, and the Hill rotation.
#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/materials/hill_rotation.h>
#include <fsgmpm/materials/material_factory.h>
#include <fsgmpm/materials/newtonian_fluid.h>
#include <fsgmpm/scene/parameters.h>
#include <fsgmpm/simulator.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

namespace Step2
{
  using namespace dealii;
  using namespace fsgmpm;

  // @sect3{The Bingham mud}
  //
  // A material declares its parameters in a subsection of the body (by
  // convention named like the model) and creates itself from them; @p path
  // ("Bodies/Body 0") names the body in error messages, so that a user
  // reads which entry to fix.
  class BinghamMud : public NewtonianFluid
  {
  public:
    BinghamMud(const double bulk_modulus,
               const double plastic_viscosity,
               const double yield_stress,
               const double shear_modulus,
               const double density)
      : NewtonianFluid(bulk_modulus,
                       plastic_viscosity,
                       density,
                       PressureLaw::linear,
                       7,
                       0.)
      , tau_y(yield_stress)
      , G(shear_modulus)
    {}

    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Bingham mud");
      prm.declare_entry("Bulk modulus",
                        "2.5e6",
                        Patterns::Double(1, 1e13),
                        "K in Pa: p = -K (J - 1), cut off at zero.");
      prm.declare_entry("Plastic viscosity",
                        "1",
                        Patterns::Double(0),
                        "mu_p in Pa s: tau = tau_y + mu_p gamma_dot.");
      prm.declare_entry("Yield stress",
                        "200",
                        Patterns::Double(0),
                        "tau_y in Pa (the von Mises shear stress).");
      prm.declare_entry("Shear modulus",
                        "1e5",
                        Patterns::Double(0),
                        "G in Pa: the elastic shear stiffness below the "
                        "yield stress (large against tau_y).");
      prm.leave_subsection();
    }

    static std::unique_ptr<BinghamMud>
    create(ParameterHandler &prm, const double density, const std::string &path)
    {
      prm.enter_subsection("Bingham mud");
      const double K    = prm.get_double("Bulk modulus");
      const double mu_p = prm.get_double("Plastic viscosity");
      const double tau  = prm.get_double("Yield stress");
      const double G    = prm.get_double("Shear modulus");
      prm.leave_subsection();
      // The relaxation needs G > 0 and mu_p > 0; a shear modulus that is
      // not large against the yield stress would make the "rigid" mud
      // visibly elastic.
      AssertThrow(mu_p > 0 && G > 0,
                  ExcMessage(path
                             + "/Bingham mud/Plastic viscosity and Shear "
                               "modulus must be positive."));
      AssertThrow(G >= 100 * tau,
                  ExcMessage(path
                             + "/Bingham mud/Shear modulus must be at least "
                               "100 times the Yield stress (the elastic "
                               "strain at yield, tau_y/G, must be small)."));
      auto mud  = std::make_unique<BinghamMud>(K, mu_p, tau, G, density);
      mud->path = path;
      return mud;
    }

    std::string
    name() const override
    {
      return "Bingham mud";
    }

    // The stress update of the introduction, one call for a run of points
    // of this material. kinematics[i] holds the point's strain rate, its
    // rotation over the step and its volume ratio J after the step. (The
    // base class's viscous stress needs no rotation and says so with
    // rotates_stress(); a derived class gets the rotation unless it
    // overrides that too.)
    void
    update_stresses(const PointKinematics *kinematics,
                    SymmetricTensor<2, 3> *stress,
                    const unsigned int     n,
                    const double           dt) const override
    {
      const double relaxation = dt * G / mu; // dt / t_r
      for (unsigned int i = 0; i < n; ++i)
        {
          const SymmetricTensor<2, 3> s_trial
            = deviator(rotate_stress(stress[i], kinematics[i].rotation))
              + 2 * G * dt * deviator(kinematics[i].strain_rate);
          const double tau_trial  = std::sqrt(0.5 * (s_trial * s_trial));
          SymmetricTensor<2, 3> s = s_trial;
          if (tau_trial > tau_y)
            s = (s_trial + relaxation * (tau_y / tau_trial) * s_trial)
                / (1 + relaxation);
          const double p = std::max(pressure(kinematics[i].volume_ratio), 0.);
          stress[i]      = s - p * unit_symmetric_tensor<3>();
        }
    }

    // The time step: the elastic shear wave adds to the pressure wave
    // (P-wave modulus K + 4G/3), and the viscous limit of the base class
    // uses mu_p through viscosity().
    double
    wave_speed(const double density) const override
    {
      return std::sqrt((K + 4. * G / 3.) / density);
    }

    // The stored energy: the compression of the base class plus the
    // elastic shear energy s:s/(4G).
    double
    strain_energy_density(const SymmetricTensor<2, 3> &sigma) const override
    {
      const SymmetricTensor<2, 3> s = deviator(sigma);
      return NewtonianFluid::strain_energy_density(sigma) + s * s / (4 * G);
    }

    const double tau_y, G;
  };

  // The registration, at namespace scope: from now on a body may say
  // `Material model = Bingham mud`. It runs before main(), so the body's
  // parameter `Material model` lists the new name, and a misspelt one is
  // refused with the list of names.
  FSGMPM_REGISTER_MATERIAL(BinghamMud,
                           "Bingham mud",
                           "elasto-viscoplastic Bingham mud of tutorial "
                           "step-2 (subsection Bingham mud)")


  // @sect3{A single point in simple shear}
  //
  // Before a model goes into a scene, one point: we shear it at the
  // constant rate gamma_dot (d_xy = gamma_dot/2) with J = 1, for long
  // enough (100 relaxation times after yield) to reach the steady state,
  // and compare the shear stress with tau_y + mu_p gamma_dot. Returns the
  // largest relative difference.
  double
  single_point_test(const BinghamMud &mud)
  {
    std::cout << "Single point in simple shear (tau_y = " << mud.tau_y
              << " Pa, mu_p = " << mud.mu << " Pa s, G = " << mud.G << " Pa):\n"
              << "  gamma_dot [1/s]   tau [Pa]   tau_y + mu_p gamma_dot\n";
    double worst = 0;
    for (const double rate : {0.1, 1., 10., 100., 1000.})
      {
        PointKinematics kin;
        kin.strain_rate[0][1] = 0.5 * rate;
        kin.rotation          = Tensor<2, 3>(unit_symmetric_tensor<3>());
        kin.volume_ratio      = 1;
        SymmetricTensor<2, 3> stress;
        // Time to yield (tau_y / (G gamma_dot)) plus 100 relaxation times,
        // in steps of a tenth of the relaxation time.
        const double t_r   = mud.mu / mud.G;
        const double dt    = 0.1 * t_r;
        const double t_end = mud.tau_y / (mud.G * rate) + 100 * t_r;
        for (double t = 0; t < t_end; t += dt)
          mud.update_stresses(&kin, &stress, 1, dt);
        const double expected = mud.tau_y + mud.mu * rate;
        worst = std::max(worst, std::abs(stress[0][1] / expected - 1));
        std::cout << std::setw(17) << rate << std::setw(11)
                  << std::setprecision(6) << stress[0][1] << std::setw(25)
                  << expected << '\n';
      }
    return worst;
  }



  // @sect3{The scene}
  //
  // Step-1's water column, with the material chosen by name: @p model is
  // "Newtonian fluid" (water) or "Bingham mud", each with its own
  // subsection. The mud is heavier (1600 kg/m^3), sticks to the floor
  // (`fixed`), and uses APIC transfers: like the sand of
  // prm/granular_column_collapse.prm, a material that must come to rest
  // cannot keep FLIP's sub-cell velocity noise (with FLIP the mud's run
  // went unstable at 0.85 s). The water keeps step-1's settings.
  void
  describe_scene(ParameterHandler  &prm,
                 const std::string &model,
                 const unsigned int cells_across,
                 const double       end_time)
  {
    Parameters<2>::declare_parameters(prm);
    const bool mud = (model == "Bingham mud");
    prm.parse_input_from_string(R"(
subsection Simulation
  set Dimension = 2
  set Gravity   = 0, -9.81
  set Velocity transfer = FLIP
end
subsection Grid
  set Upper corner        = 0.684, 0.285
  set Boundary conditions = 0: roller, 1: roller, 2: roller, 3: free
end
subsection Bodies
  subsection Body 0
    set Box lower corner = 0, 0
    set Box upper corner = 0.114, 0.228
    set Initial stress   = hydrostatic
    subsection Newtonian fluid
      set Bulk modulus = 2.5e6
      set Viscosity    = 8.9e-4
    end
    subsection Bingham mud
      set Bulk modulus      = 2.5e6
      set Plastic viscosity = 1
      set Yield stress      = 200
      set Shear modulus     = 1e5
    end
  end
end
subsection Output
  set Quiet = true
end
)");
    prm.enter_subsection("Simulation");
    prm.set("End time", end_time);
    prm.set("Velocity transfer", mud ? "APIC" : "FLIP");
    prm.leave_subsection();
    prm.enter_subsection("Grid");
    prm.set("Boundary conditions",
            std::string("0: roller, 1: roller, 2: ")
              + (mud ? "fixed" : "roller") + ", 3: free");
    prm.leave_subsection();
    prm.enter_subsection("Grid");
    prm.set("Subdivisions",
            std::to_string(6 * cells_across) + ", "
              + std::to_string(5 * cells_across / 2));
    prm.leave_subsection();
    prm.enter_subsection("Bodies");
    prm.enter_subsection("Body 0");
    prm.set("Material model", model);
    prm.set("Density", mud ? 1600. : 1000.);
    prm.leave_subsection();
    prm.leave_subsection();
    prm.enter_subsection("Output");
    prm.set("Directory", mud ? "output_step-2_mud" : "output_step-2_water");
    prm.leave_subsection();
  }



  // @sect3{Measurements}
  //
  // The front as in step-1 (the largest x in the bottom cell row, plus half
  // a point spacing), and the depth at the back wall: the highest point in
  // the first cell column, plus half a point spacing.
  double
  front_position(const ParticleStore<2> &particles, const double row_height)
  {
    double front = 0;
    for (unsigned int p = 0; p < particles.size(); ++p)
      if (particles.position[p][1] < row_height)
        front = std::max(front,
                         particles.position[p][0]
                           + 0.5 * std::sqrt(particles.volume[p]));
    return front;
  }

  double
  depth_between(const ParticleStore<2> &particles,
                const double            x0,
                const double            x1)
  {
    double depth = 0;
    for (unsigned int p = 0; p < particles.size(); ++p)
      if (particles.position[p][0] >= x0 && particles.position[p][0] < x1)
        depth = std::max(depth,
                         particles.position[p][1]
                           + 0.5 * std::sqrt(particles.volume[p]));
    return depth;
  }

  double
  depth_at_wall(const ParticleStore<2> &particles, const double column_width)
  {
    return depth_between(particles, 0, column_width);
  }



  // @sect3{The run}
  //
  // Water and mud advance side by side, one step of each per loop, and
  // every 0.1 s we print both fronts; the mud's depth at the wall follows.
  // At the end, the mud's deposit against the steepest admissible profile
  // h_s^2 = k (x_f - x), k = 2 tau_y/(rho g). Returns the mud's final front
  // and depth at the wall.
  std::pair<double, double>
  run(const unsigned int cells_across, const double end_time, const double k)
  {
    ParameterHandler water_prm, mud_prm;
    // The water reaches the far wall at about 0.3 s; we stop it at 0.4 s
    // (run on, its splash back from the wall at 20 cells trips the
    // energy-creation guard at 0.82 s).
    describe_scene(water_prm,
                   "Newtonian fluid",
                   cells_across,
                   std::min(end_time, 0.4));
    describe_scene(mud_prm, "Bingham mud", cells_across, end_time);
    Simulator<2> water(water_prm), mud(mud_prm);

    const double a = 0.114, h = a / cells_across;
    std::cout << "\nWater column and mud column, " << cells_across
              << " cells across, " << mud.get_particles().size()
              << " points each.\n"
              << "  t [s]   water front [m]   mud front [m]   mud depth at "
                 "the wall [m]\n";
    double next_report = 0;
    bool   water_runs = true, mud_runs = true;
    while (water_runs || mud_runs || next_report <= end_time + 1e-9)
      {
        // Print when both have passed the report time.
        if ((!water_runs || water.get_time() >= next_report - 1e-12)
            && (!mud_runs || mud.get_time() >= next_report - 1e-12))
          {
            std::cout << std::fixed << std::setprecision(3) << std::setw(7)
                      << next_report << std::setw(18)
                      << front_position(water.get_particles(), h)
                      << std::setw(16) << front_position(mud.get_particles(), h)
                      << std::setw(22) << depth_at_wall(mud.get_particles(), h)
                      << '\n';
            next_report += 0.1;
          }
        // Advance whichever is behind.
        if (water_runs && (water.get_time() <= mud.get_time() || !mud_runs))
          water_runs = water.advance();
        else if (mud_runs)
          mud_runs = mud.advance();
        else
          break;
      }
    AssertThrow(water.get_termination() == fsgmpm::Termination::end_time,
                ExcMessage("The water run stopped early: "
                           + water.get_diagnosis()));
    AssertThrow(mud.get_termination() == fsgmpm::Termination::end_time,
                ExcMessage("The mud run stopped early: "
                           + mud.get_diagnosis()));
    std::cout << "Steps: water " << water.get_step() << ", mud "
              << mud.get_step() << "\n";

    // The deposit's depth in bins of 0.05 m against the steepest profile
    // its front admits, h_s = sqrt(k (x_f - x)), at the bin's centre.
    const double front = front_position(mud.get_particles(), h);
    std::cout << "Mud deposit:   x [m]   depth [m]   steepest admissible [m]\n";
    for (double x = 0; x < front; x += 0.05)
      std::cout << std::setw(18) << x + 0.025 << std::setw(12)
                << depth_between(mud.get_particles(), x, x + 0.05)
                << std::setw(26)
                << std::sqrt(k * std::max(front - x - 0.025, 0.)) << '\n';
    return {front_position(mud.get_particles(), h),
            depth_at_wall(mud.get_particles(), h)};
  }
} // namespace Step2



// @sect3{The main function}
//
// The single-point test first (it must hold to round-off), then the two
// runs, and the deposit against the bounds of the introduction.
int
main(int argc, char **argv)
{
  using namespace Step2;
  try
    {
      const unsigned int cells_across = (argc > 1) ? std::stoi(argv[1]) : 20;
      const double       end_time     = (argc > 2) ? std::stod(argv[2]) : 1.0;

      const BinghamMud mud(2.5e6, 1, 200, 1e5, 1600);
      const double     worst = single_point_test(mud);
      std::cout << "Largest relative difference from tau_y + mu_p gamma_dot: "
                << std::scientific << std::setprecision(2) << worst << "\n";
      AssertThrow(worst < 1e-9, ExcMessage("The single-point test failed."));

      const double rho = 1600, g = 9.81, A = 2 * 0.114 * 0.114;
      const double k = 2 * mud.tau_y / (rho * g); // h_s^2 = k (x_f - x)
      const auto [front, depth] = run(cells_across, end_time, k);
      const double L_s          = std::pow(1.5 * A / std::sqrt(k), 2. / 3.);
      std::cout << std::fixed << std::setprecision(4) << "Mud deposit: run-out "
                << front << " m (smallest admissible " << L_s
                << " m); depth at the wall " << depth
                << " m (steepest admissible " << std::sqrt(k * front)
                << " m)\n";
    }
  catch (std::exception &exc)
    {
      std::cerr << "step-2: error: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}

/* <h1>Results</h1>
 *
 * The output of this program and what it shows are in README.md beside
 * this file.
 */
