#include <deal.II/base/exceptions.h>

#include <fsgmpm/run/stability_guard.h>

#include <algorithm>
#include <cmath>

namespace fsgmpm
{
  void
  StabilityGuard::Settings::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii;
    prm.enter_subsection("Stability");
    {
      prm.declare_entry("Kinetic energy growth factor",
                        "10",
                        Patterns::Double(1),
                        "Stop as unstable if the kinetic energy grows by "
                        "more than this factor over the growth window while "
                        "the external work does not account for it.");
      prm.declare_entry("Growth window",
                        "100",
                        Patterns::Integer(1),
                        "Steps over which the kinetic energy growth is "
                        "measured.");
      prm.declare_entry(
        "Energy creation tolerance",
        "0.05",
        Patterns::Double(0),
        "Stop as unstable if the kinetic plus strain energy exceeds the "
        "initial energy plus the external work minus the booked losses "
        "(damping, plastic and viscous work, the transfers', the outflow) by "
        "more than this fraction of the energy scale: the initial energy, "
        "the largest external work so far and the energy the scene holds "
        "(its points' potential energy above the mesh's lowest corner). "
        "Catches slow growth that the growth window does not; summary.json "
        "reports the run's largest reading "
        "(energy_created_largest_share). 0 switches it off.");
    }
    prm.leave_subsection();
  }



  void
  StabilityGuard::Settings::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Stability");
    growth_factor             = prm.get_double("Kinetic energy growth factor");
    growth_window             = prm.get_integer("Growth window");
    energy_creation_tolerance = prm.get_double("Energy creation tolerance");
    prm.leave_subsection();
  }



  StabilityGuard::StabilityGuard(const Settings &settings)
    : settings(settings)
  {}



  void
  StabilityGuard::reset(const Monitors &monitors, const double held)
  {
    held_energy = std::max(0., held);
    history.clear();
    history.push_back({{monitors.kinetic_energy + monitors.strain_energy,
                        monitors.external_work}});
    initial_energy         = monitors.kinetic_energy + monitors.strain_energy;
    external_work_scale    = std::abs(monitors.external_work);
    largest_created_energy = 0;
    largest_created_ratio  = 0;
  }



  std::string
  StabilityGuard::check(const Monitors &monitors,
                        const double    displacement_ratio)
  {
    if (!std::isfinite(displacement_ratio)
        || !std::isfinite(monitors.kinetic_energy)
        || !std::isfinite(monitors.strain_energy))
      return "a non-finite value appeared (velocity, stress or position)";
    if (displacement_ratio > 1.)
      return "a material point moved " + std::to_string(displacement_ratio)
             + " times its cell's smallest altitude in one step (it crossed "
               "more than one cell)";

    // Energy balance: kinetic + strain energy can only come from the
    // initial energy and the external work, less what damping removed
    // (plastic, viscous and transfer dissipation only lower the left side).
    // More means the step created energy.
    external_work_scale
      = std::max(external_work_scale, std::abs(monitors.external_work));
    const double stored    = monitors.kinetic_energy + monitors.strain_energy;
    const double created   = energy_created(monitors);
    const double scale     = energy_scale();
    largest_created_energy = std::max(largest_created_energy, created);
    if (scale > 0)
      largest_created_ratio = std::max(largest_created_ratio, created / scale);
    if (settings.energy_creation_tolerance > 0 && scale > 0
        && created > settings.energy_creation_tolerance * scale)
      return "the kinetic plus strain energy (" + std::to_string(stored)
             + " J) exceeds the initial energy plus the external work minus "
               "the booked losses by "
             + std::to_string(created) + " J, more than "
             + std::to_string(settings.energy_creation_tolerance)
             + " times the energy scale (" + std::to_string(scale)
             + " J: the energy put in and held): the step is creating "
               "energy (Stability/Energy creation tolerance = 0 disables "
               "this check)";

    history.push_back({{stored, monitors.external_work}});
    if (history.size() > settings.growth_window + 1)
      history.pop_front();
    if (history.size() == settings.growth_window + 1)
      {
        const auto  &old = history.front();
        const double available
          = old[0] + std::max(0., monitors.external_work - old[1]);
        if (monitors.kinetic_energy > settings.growth_factor * available
            && monitors.kinetic_energy > 1e-200)
          return "the kinetic energy grew to "
                 + std::to_string(monitors.kinetic_energy) + " J, more than "
                 + std::to_string(settings.growth_factor)
                 + " times the energy available "
                 + std::to_string(settings.growth_window)
                 + " steps earlier plus the external work since";
      }
    return "";
  }



  double
  StabilityGuard::energy_residual(const Monitors &monitors) const
  {
    return monitors.kinetic_energy + monitors.strain_energy
           - (initial_energy + monitors.external_work
              - monitors.dissipated_energy - monitors.material_dissipation
              - monitors.numerical_dissipation - monitors.outflow_energy);
  }



  double
  StabilityGuard::energy_created(const Monitors &monitors) const
  {
    // The residual with each booked loss counted only where it is a loss:
    // plastic work in the soil may not hide energy created by a transfer,
    // nor energy created in a material (a negative material_dissipation)
    // be hidden by the transfers' losses.
    return energy_residual(monitors)
           + std::max(0., -monitors.material_dissipation)
           + std::max(0., -monitors.numerical_dissipation)
           + std::max(0., -monitors.outflow_energy);
  }



  std::vector<double>
  StabilityGuard::state() const
  {
    std::vector<double> s = {initial_energy, external_work_scale, held_energy};
    for (const auto &h : history)
      s.insert(s.end(), h.begin(), h.end());
    return s;
  }



  void
  StabilityGuard::set_state(const std::vector<double> &s)
  {
    AssertThrow(s.size() >= 3 && s.size() % 2 == 1,
                dealii::ExcMessage("The checkpoint's stability-guard state "
                                   "is damaged."));
    initial_energy      = s[0];
    external_work_scale = s[1];
    held_energy         = s[2];
    history.clear();
    for (unsigned int k = 3; k < s.size(); k += 2)
      history.push_back({{s[k], s[k + 1]}});
  }



  void
  StabilityGuard::set_largest_state(const std::vector<double> &s)
  {
    AssertThrow(s.size() == 2,
                dealii::ExcMessage("The checkpoint's stability-guard state "
                                   "is damaged."));
    largest_created_energy = s[0];
    largest_created_ratio  = s[1];
  }
} // namespace fsgmpm
