#ifndef fsgmpm_materials_newtonian_fluid_h
#define fsgmpm_materials_newtonian_fluid_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/materials/material.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <typeinfo>

namespace fsgmpm
{
  /**
   * Weakly compressible Newtonian fluid, paper Eqs. (11)-(16):
   * sigma = -p I + 2 mu dev(d) (Stokes' hypothesis, Eq. 13), with the
   * pressure a function of the volume ratio J = V/V_ref = rho_ref/rho:
   *   linear (Eq. 16):  p = -K_f (J - 1)
   *   power  (Eq. 15):  p = (K_f/kappa) (J^-kappa - 1)   (Tait form; same
   *                     bulk modulus K_f at the reference state)
   * The volume is updated by the stress stage with the same (NMD-smoothed)
   * volumetric strain rate, so pressure and density stay consistent.
   * Tension policy: p >= p_c, the tension cut-off (a gauge pressure <= 0;
   * 0, the default, is cavitation at zero gauge pressure, -infinity no
   * limit). The volume ratio is capped where the law reaches p_c, so the
   * cloud cannot expand further without pulling. Points the free-surface
   * detection flags are reset to zero pressure whatever p_c.
   */
  class NewtonianFluid : public Material
  {
  public:
    enum class PressureLaw
    {
      linear,
      power
    };

    NewtonianFluid(const double      bulk_modulus,
                   const double      viscosity,
                   const double      density,
                   const PressureLaw law,
                   const double      exponent,
                   const double      tension_cut_off);

    /// A bool would convert silently to a cut-off of 0 or 1 Pa: pass
    /// 0. or no_tension_limit instead.
    NewtonianFluid(const double,
                   const double,
                   const double,
                   const PressureLaw,
                   const double,
                   const bool)
      = delete;

    /// The tension_cut_off of a fluid that may pull without limit.
    static constexpr double no_tension_limit
      = -std::numeric_limits<double>::infinity();

    static void
    declare_parameters(ParameterHandler &prm);
    static std::unique_ptr<NewtonianFluid>
    create(ParameterHandler  &prm,
           const double       density,
           const std::string &path);

    std::string
    name() const override
    {
      return "Newtonian fluid";
    }

    void
    update_stresses(const PointKinematics *kinematics,
                    SymmetricTensor<2, 3> *stress,
                    const unsigned int     n,
                    const double           dt) const override;

    /// update_stresses() with the run's one strain rate, without copies.
    /// A derived class (step-2's Bingham mud) gets the base class's copies
    /// and its own update_stresses().
    void
    update_stresses_of_run(const PointKinematics &shared,
                           const double          *volume_ratio,
                           SymmetricTensor<2, 3> *stress,
                           const unsigned int     n,
                           const double           dt) const override;

    double
    wave_speed(const double density) const override;

    /// wave_speed() in a loop without a call per point, which the compiler
    /// vectorises for the linear law. A derived class that overrides
    /// wave_speed() gets the base class's virtual call per point.
    void
    wave_speeds(const double      *density,
                double            *speed,
                const unsigned int n) const override;

    double
    strain_energy_density(const SymmetricTensor<2, 3> &stress) const override;

    /// The stored energy of the fluid's state: V_ref e(J) with
    /// e(J) = int_J^1 p(J') dJ' (volume_ratio_energy()), J = volume /
    /// reference_volume, whose rate is minus the pressure times the
    /// volumetric strain rate that updated J (NMD's smoothed one where it
    /// is on). It does not read the stress, whose pressure the nodal
    /// pressure average (ANP) has overwritten with a smoothed one: the
    /// energy of that smoothed pressure is not the energy the points hold
    /// (a column's acoustic perturbation drifted 7 %, 66 % with the
    /// smoothing stabilisation, by that reading; 2 % and 3 % by this one).
    /// A derived class that overrides strain_energy_density() (step-2's
    /// Bingham mud) gets the base class's stress-based sum instead.
    double
    add_strain_energy(const SymmetricTensor<2, 3> *stress,
                      const double                *volume,
                      const double                *reference_volume,
                      const unsigned int           n,
                      double                       energy) const override;

    /// e(J) = int_J^1 p(J') dJ' per unit reference volume, with the tension
    /// cut-off (p = p_c above J_max): K (1 - J)^2 / 2 for the linear law
    /// up to J_max.
    double
    volume_ratio_energy(const double J) const;

    double
    reference_density() const override
    {
      return density;
    }

    bool
    dissipates() const override
    {
      return is_this_class() && mu > 0;
    }

    /// The viscous work 2 mu dev(d) : dev(d) V dt: the pressure is the
    /// gradient of the stored energy of J (volume_ratio_energy()) and
    /// dissipates nothing.
    double
    dissipated_energy(const SymmetricTensor<2, 3> *old_stress,
                      const SymmetricTensor<2, 3> *new_stress,
                      const double                *old_volume,
                      const double                *new_volume,
                      const PointKinematics       &kinematics,
                      const unsigned int           n,
                      const double                 dt,
                      const PointPlasticity       *plasticity
                      = nullptr) const override;

    double
    viscosity() const override
    {
      return mu;
    }

    /// Throws, naming Bulk modulus, if the pressure would compress the
    /// fluid to a non-positive volume.
    double
    volume_ratio_for_pressure(const double pressure) const override;

    double
    admissible_volume_ratio(const double J) const override
    {
      return std::min(J, J_max);
    }

    bool
    is_fluid() const override
    {
      return true;
    }

    /// Eq. (13) needs no rotation: false for this class only. A class
    /// derived from it (tutorial step-2's Bingham mud) may rotate an
    /// elastic stress and gets the rotation unless it overrides this.
    bool
    rotates_stress() const override
    {
      return !is_this_class();
    }

    /// Pressure at volume ratio J (before the tension cut-off).
    double
    pressure(const double J) const;

    const double      K, mu, density;
    const PressureLaw law;
    const double      kappa;
    /// p_c: the lowest gauge pressure the fluid carries (<= 0).
    const double tension_cut_off;
    /// The volume ratio at which the law reaches p_c (1 for p_c = 0,
    /// infinity where the law never reaches it).
    const double J_max;
    /// The body's parameter path ("Bodies/Body 0"), for messages.
    std::string path;

  private:
    /// The law inverted: the volume ratio at pressure p (infinity where
    /// the power law never reaches p). Declared members K, law and kappa
    /// are set before J_max, which the constructor takes from it.
    double
    volume_ratio_of_law(const double p) const;

    /// Eq. (13): sigma = -p I + 2 mu dev(d) at the volume ratio J, written
    /// out component by component (the same operations as deviator(),
    /// cheaper).
    void
    fluid_stress(const SymmetricTensor<2, 3> &d,
                 const double                 J,
                 SymmetricTensor<2, 3>       &s) const
    {
      const double p      = std::max(pressure(J), tension_cut_off);
      const double two_mu = 2. * mu;
      const double mean   = trace(d) / 3;
      for (unsigned int a = 0; a < 3; ++a)
        {
          s[a][a] = two_mu * (d[a][a] - mean) - p;
          for (unsigned int b = a + 1; b < 3; ++b)
            s[a][b] = two_mu * d[a][b];
        }
    }

    /// Whether this object is a NewtonianFluid itself, not of a class
    /// derived from it: only then do the overrides above that skip
    /// strain_energy_density() or the rotation apply.
    bool
    is_this_class() const
    {
      return typeid(*this) == typeid(NewtonianFluid);
    }
  };
} // namespace fsgmpm

#endif
