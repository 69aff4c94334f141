#include <deal.II/base/exceptions.h>

#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/particles/particle_store.h>
#include <fsgmpm/run/dynamic_relaxation.h>

#include <algorithm>

namespace fsgmpm
{
  void
  DynamicRelaxation::Settings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Simulation");
    {
      prm.declare_entry("Termination",
                        "end_time",
                        Patterns::Selection("end_time|dr_converged|at_rest"),
                        "end_time: run to End time; dr_converged: stop "
                        "earlier when both Eq. (30) ratios stay below their "
                        "tolerances for the convergence window; at_rest: "
                        "stop when, after moving, the kinetic energy of the "
                        "grid motion (monitor grid_kinetic_energy) stays "
                        "below Rest tolerance times the initial potential "
                        "energy (above the mesh's lowest point) for "
                        "Damping/Convergence window steps.");
      prm.declare_entry("Rest tolerance",
                        "1e-6",
                        Patterns::Double(0),
                        "Termination = at_rest: grid kinetic energy / "
                        "initial potential energy below which the material "
                        "is at rest.");
    }
    prm.leave_subsection();
    prm.enter_subsection("Damping");
    {
      prm.declare_entry("Kinetic damping",
                        "false",
                        Patterns::Bool(),
                        "Zero all velocities at each peak of the kinetic "
                        "energy.");
      prm.declare_entry("Energy tolerance",
                        "0.05",
                        Patterns::Double(0),
                        "E_v of Eq. (30): kinetic energy / external work.");
      prm.declare_entry("Force tolerance",
                        "0.05",
                        Patterns::Double(0),
                        "E_f of Eq. (30): |F_ext - F_int| / |F_ext| over "
                        "the unconstrained nodal components.");
      prm.declare_entry("Convergence window",
                        "1000",
                        Patterns::Integer(1),
                        "Consecutive steps both Eq. (30) ratios must stay "
                        "below their tolerances.");
    }
    prm.leave_subsection();
  }



  void
  DynamicRelaxation::Settings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Simulation");
    stop_when_converged = (prm.get("Termination") == "dr_converged");
    stop_when_at_rest   = (prm.get("Termination") == "at_rest");
    rest_tolerance      = prm.get_double("Rest tolerance");
    load_time           = prm.get_double("Gravity ramp time");
    prm.leave_subsection();
    prm.enter_subsection("Damping");
    kinetic_damping    = prm.get_bool("Kinetic damping");
    energy_tolerance   = prm.get_double("Energy tolerance");
    force_tolerance    = prm.get_double("Force tolerance");
    convergence_window = prm.get_integer("Convergence window");
    prm.leave_subsection();
  }



  DynamicRelaxation::DynamicRelaxation(const Settings &settings)
    : settings(settings)
  {}



  void
  DynamicRelaxation::reset(const Monitors &monitors,
                           const double    initial_potential_energy)
  {
    previous_kinetic_energy        = monitors.kinetic_energy;
    this->initial_potential_energy = initial_potential_energy;
  }



  template <int dim>
  void
  DynamicRelaxation::apply_kinetic_damping(Monitors           &monitors,
                                           ParticleStore<dim> &particles,
                                           Membrane<dim>      *membrane)
  {
    if (settings.kinetic_damping
        && monitors.kinetic_energy < previous_kinetic_energy)
      {
        // A kinetic-energy peak has passed: remove all kinetic energy.
        monitors.dissipated_energy += monitors.kinetic_energy;
        for (auto &v : particles.velocity)
          v = Tensor<1, dim>();
        for (auto &C : particles.affine_velocity)
          C = Tensor<2, dim>();
        if (membrane)
          for (auto &v : membrane->velocity)
            v = Tensor<1, dim>();
        monitors.kinetic_energy = 0;
      }
    previous_kinetic_energy = monitors.kinetic_energy;
  }



  Termination
  DynamicRelaxation::update(const Monitors &monitors, const double time)
  {
    // Eq. (30); convergence is only meaningful once the full load is on.
    if (time >= settings.load_time
        && monitors.dr_energy_ratio <= settings.energy_tolerance
        && monitors.dr_force_ratio <= settings.force_tolerance)
      ++n_converged;
    else
      n_converged = 0;

    // At rest: after it has moved, the kinetic energy stays below the
    // tolerance for the window (a single step at a turning point of a
    // bounce is not rest).
    max_kinetic_energy
      = std::max(max_kinetic_energy, monitors.grid_kinetic_energy);
    const double rest_energy
      = settings.rest_tolerance * initial_potential_energy;
    n_rest = (max_kinetic_energy > rest_energy
              && monitors.grid_kinetic_energy < rest_energy)
               ? n_rest + 1
               : 0;
    if (settings.stop_when_at_rest && n_rest >= settings.convergence_window)
      return Termination::at_rest;
    if (settings.stop_when_converged
        && n_converged >= settings.convergence_window)
      return Termination::dr_converged;
    return Termination::running;
  }



  std::vector<double>
  DynamicRelaxation::energy_state() const
  {
    return {previous_kinetic_energy,
            initial_potential_energy,
            max_kinetic_energy};
  }



  std::vector<unsigned int>
  DynamicRelaxation::counter_state() const
  {
    return {n_rest, n_converged};
  }



  void
  DynamicRelaxation::set_state(const std::vector<double>       &energies,
                               const std::vector<unsigned int> &counters)
  {
    AssertThrow(energies.size() == 3 && counters.size() == 2,
                ExcMessage("The dynamic-relaxation state holds three "
                           "energies and two counters."));
    previous_kinetic_energy  = energies[0];
    initial_potential_energy = energies[1];
    max_kinetic_energy       = energies[2];
    n_rest                   = counters[0];
    n_converged              = counters[1];
  }

  template void
  DynamicRelaxation::apply_kinetic_damping(Monitors &,
                                           ParticleStore<2> &,
                                           Membrane<2> *);
  template void
  DynamicRelaxation::apply_kinetic_damping(Monitors &,
                                           ParticleStore<3> &,
                                           Membrane<3> *);
} // namespace fsgmpm
