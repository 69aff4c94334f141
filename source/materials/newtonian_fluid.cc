#include <deal.II/base/exceptions.h>

#include <fsgmpm/materials/material_factory.h>
#include <fsgmpm/materials/newtonian_fluid.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace fsgmpm
{
  NewtonianFluid::NewtonianFluid(const double      bulk_modulus,
                                 const double      viscosity,
                                 const double      density,
                                 const PressureLaw law,
                                 const double      exponent,
                                 const double      tension_cut_off)
    : K(bulk_modulus)
    , mu(viscosity)
    , density(density)
    , law(law)
    , kappa(exponent)
    , tension_cut_off(tension_cut_off)
    , J_max(volume_ratio_of_law(tension_cut_off))
  {
    AssertThrow(tension_cut_off <= 0,
                ExcMessage("The tension cut-off of a Newtonian fluid is a "
                           "gauge pressure at or below zero."));
  }



  void
  NewtonianFluid::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Newtonian fluid");
    prm.declare_entry("Bulk modulus",
                      "2.13e9",
                      Patterns::Double(1, 1e13),
                      "K_f in Pa (1 to 1e13); water 2.13e9. A "
                      "weakly compressible value (sound speed >= 10x the "
                      "flow speed) is the largest speed lever.");
    prm.declare_entry("Viscosity",
                      "8.9e-4",
                      Patterns::Double(0, 1e10),
                      "Dynamic viscosity mu in Pa s (>= 0, at most 1e10, "
                      "about that of bitumen at room temperature); water "
                      "8.9e-4.");
    prm.declare_entry("Pressure law",
                      "linear",
                      Patterns::Selection("linear|power"),
                      "linear: p = -K_f (J - 1), Eq. (16); power: p = "
                      "(K_f/kappa)((rho/rho_ref)^kappa - 1), Eq. (15).");
    prm.declare_entry("Power-law exponent",
                      "7",
                      Patterns::Double(0.01, 100),
                      "kappa of the power law (0.01 to 100).");
    prm.declare_entry("Allow tension",
                      "false",
                      Patterns::Bool(),
                      "Whether the pressure may become negative without "
                      "limit; if false it is cut off at the Tension cut-off.");
    prm.declare_entry(
      "Tension cut-off",
      "0",
      Patterns::Double(-1e12, 0),
      "The lowest gauge pressure the fluid carries, in Pa (at or below 0): "
      "below it the fluid cavitates, its volume grows without pulling. 0 "
      "(the default): no tension. Water below its surface holds about "
      "-p_atm + p_vapour = -99 kPa at 20 C. Points the free-surface "
      "detection flags stay at zero pressure. Leave at 0 when Allow tension "
      "is true.");
    prm.leave_subsection();
  }



  std::unique_ptr<NewtonianFluid>
  NewtonianFluid::create(ParameterHandler  &prm,
                         const double       density,
                         const std::string &path)
  {
    prm.enter_subsection("Newtonian fluid");
    const double K   = prm.get_double("Bulk modulus");
    const double mu  = prm.get_double("Viscosity");
    const auto   law = prm.get("Pressure law") == "linear" ? PressureLaw::linear
                                                           : PressureLaw::power;
    const double kappa   = prm.get_double("Power-law exponent");
    const bool   allow   = prm.get_bool("Allow tension");
    const double cut_off = prm.get_double("Tension cut-off");
    prm.leave_subsection();
    AssertThrow(!(allow && cut_off != 0),
                ExcMessage(path
                           + "/Newtonian fluid: Allow tension = true lets "
                             "the fluid pull without limit, and Tension "
                             "cut-off sets a limit; set one of them."));
    AssertThrow(K > 0,
                ExcMessage(path
                           + "/Newtonian fluid/Bulk modulus must be "
                             "positive."));
    AssertThrow(law == PressureLaw::linear || kappa > 0,
                ExcMessage(path
                           + "/Newtonian fluid/Power-law exponent must "
                             "be positive."));
    auto fluid = std::make_unique<NewtonianFluid>(
      K, mu, density, law, kappa, allow ? no_tension_limit : cut_off);
    fluid->path = path;
    return fluid;
  }



  double
  NewtonianFluid::pressure(const double J) const
  {
    return law == PressureLaw::linear ? -K * (J - 1.)
                                      : K / kappa * (std::pow(J, -kappa) - 1.);
  }



  double
  NewtonianFluid::volume_ratio_of_law(const double p) const
  {
    // The power law's pressure never falls below -K/kappa: no volume ratio
    // reaches a pressure at or below it.
    if (law == PressureLaw::linear)
      return 1. - p / K;
    return 1. + kappa * p / K > 0 ? std::pow(1. + kappa * p / K, -1. / kappa)
                                  : std::numeric_limits<double>::infinity();
  }



  double
  NewtonianFluid::volume_ratio_for_pressure(const double p) const
  {
    const double J = volume_ratio_of_law(p);
    if (!(std::isfinite(J) && J > 0.5 && J < 2))
      {
        std::ostringstream message;
        message << path << "/Newtonian fluid/Bulk modulus = " << K
                << " Pa is too small for the initial pressure " << p
                << " Pa: the fluid would start at a volume ratio " << J
                << " (0.5 to 2 are allowed); raise the Bulk modulus well "
                   "above the pressure.";
        AssertThrow(false, ExcMessage(message.str()));
      }
    return J;
  }



  void
  NewtonianFluid::update_stresses(const PointKinematics *kin,
                                  SymmetricTensor<2, 3> *stress,
                                  const unsigned int     n,
                                  const double /*dt*/) const
  {
    for (unsigned int i = 0; i < n; ++i)
      fluid_stress(kin[i].strain_rate, kin[i].volume_ratio, stress[i]);
  }



  void
  NewtonianFluid::update_stresses_of_run(const PointKinematics &shared,
                                         const double          *volume_ratio,
                                         SymmetricTensor<2, 3> *stress,
                                         const unsigned int     n,
                                         const double           dt) const
  {
    if (!is_this_class())
      return Material::update_stresses_of_run(
        shared, volume_ratio, stress, n, dt);
    for (unsigned int i = 0; i < n; ++i)
      fluid_stress(shared.strain_rate, volume_ratio[i], stress[i]);
  }



  double
  NewtonianFluid::wave_speed(const double rho) const
  {
    // Tangent bulk modulus dp/dJ * (-J): K (linear), K J^-kappa (power).
    const double J  = density / rho;
    const double Kt = law == PressureLaw::linear ? K : K * std::pow(J, -kappa);
    return std::sqrt(Kt / rho);
  }



  void
  NewtonianFluid::wave_speeds(const double      *rho,
                              double            *speed,
                              const unsigned int n) const
  {
    if (!is_this_class())
      return Material::wave_speeds(rho, speed, n);
    // This class's own wave_speed(), called directly (inlined, no virtual
    // call per point): the compiler takes the law's branch out of the loop
    // and SSE2 takes two points of the linear law per instruction.
    for (unsigned int i = 0; i < n; ++i)
      speed[i] = NewtonianFluid::wave_speed(rho[i]);
  }



  double
  NewtonianFluid::strain_energy_density(const SymmetricTensor<2, 3> &s) const
  {
    // Stored compression energy p^2/(2K) of the linear law.
    const double p = -trace(s) / 3.;
    return 0.5 * p * p / K;
  }

  double
  NewtonianFluid::volume_ratio_energy(const double J) const
  {
    // Above J_max the pressure is the constant p_c (the volume update keeps
    // J <= J_max, so only a state set from outside gets there).
    if (J > J_max)
      return volume_ratio_energy(J_max) - tension_cut_off * (J - J_max);
    if (law == PressureLaw::linear)
      return 0.5 * K * (1. - J) * (1. - J);
    // int_J^1 (K/kappa)(x^-kappa - 1) dx.
    const double integral_of_power
      = std::abs(kappa - 1.) < 1e-12
          ? -std::log(J)
          : (1. - std::pow(J, 1. - kappa)) / (1. - kappa);
    return K / kappa * (integral_of_power - (1. - J));
  }

  double
  NewtonianFluid::add_strain_energy(const SymmetricTensor<2, 3> *stress,
                                    const double                *volume,
                                    const double      *reference_volume,
                                    const unsigned int n,
                                    double             energy) const
  {
    if (!is_this_class())
      return Material::add_strain_energy(
        stress, volume, reference_volume, n, energy);
    for (unsigned int i = 0; i < n; ++i)
      energy += reference_volume[i]
                * volume_ratio_energy(volume[i] / reference_volume[i]);
    return energy;
  }



  double
  NewtonianFluid::dissipated_energy(const SymmetricTensor<2, 3> *old_stress,
                                    const SymmetricTensor<2, 3> *new_stress,
                                    const double                *old_volume,
                                    const double                *new_volume,
                                    const PointKinematics       &kinematics,
                                    const unsigned int           n,
                                    const double                 dt,
                                    const PointPlasticity *plasticity) const
  {
    // A class derived from this one (a Bingham mud) has its own stress and
    // books its own losses.
    if (!is_this_class())
      return Material::dissipated_energy(old_stress,
                                         new_stress,
                                         old_volume,
                                         new_volume,
                                         kinematics,
                                         n,
                                         dt,
                                         plasticity);
    const SymmetricTensor<2, 3> d_dev  = deviator(kinematics.strain_rate);
    const double                rate   = 2. * mu * (d_dev * d_dev) * dt;
    double                      volume = 0;
    for (unsigned int i = 0; i < n; ++i)
      volume += 0.5 * (old_volume[i] + new_volume[i]);
    return rate * volume;
  }



  FSGMPM_REGISTER_MATERIAL(NewtonianFluid,
                           "Newtonian fluid",
                           "weakly compressible Newtonian fluid, Eq. (13) "
                           "(subsection Newtonian fluid)")
} // namespace fsgmpm
