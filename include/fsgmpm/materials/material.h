#ifndef fsgmpm_materials_material_h
#define fsgmpm_materials_material_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cstdint>
#include <string>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * Kinematics of one material point over a time step, always in 3x3 form
   * (in 2D plane strain the zz, xz and yz components are zero).
   */
  struct PointKinematics
  {
    SymmetricTensor<2, 3> strain_rate; ///< symmetric part of grad v
    /// Exactly orthogonal incremental rotation of the step from the spin
    /// W = (grad v - grad v^T)/2 (hill_rotation.h), computed by the stress
    /// stage once per cell (per point with the nodal stress projection);
    /// the identity for a material whose
    /// Material::rotates_stress() is false.
    Tensor<2, 3> rotation;
    /// J = V/V_ref after this step's volume update (with the same,
    /// possibly NMD-smoothed, volumetric strain rate as strain_rate).
    double volume_ratio = 1.;
  };

  /**
   * The plastic state that the points keep for the output (the
   * plastic_strain and yielding fields), for the n points of one
   * Material::dissipated_energy() call: a material that yields adds each
   * point's equivalent plastic strain increment and sets its flag.
   */
  struct PointPlasticity
  {
    /// Accumulated equivalent plastic strain, the sum over the steps of
    /// sqrt(2/3 dev(de_p) : dev(de_p)) (the plastic shear strain of soil
    /// mechanics; gamma_p / sqrt(3) in simple shear).
    double *strain;
    /// 1 where the point yielded in this step, else 0.
    std::uint8_t *yielding;
  };



  /**
   * Interface of a constitutive model. A material updates the Cauchy stress
   * (tension positive, 3x3 also in 2D) of a contiguous run of points that
   * all belong to it; one virtual call per run, not per point (so too the
   * energies' add_strain_energy() and the time step's wave_speeds(); the
   * stress stage's admissible_volume_ratio() is still called per point).
   * A material knows nothing about the grid.
   */
  class Material
  {
  public:
    virtual ~Material() = default;

    virtual std::string
    name() const = 0;

    /// Update stresses of n points: kinematics[i] drives stress[i].
    virtual void
    update_stresses(const PointKinematics *kinematics,
                    SymmetricTensor<2, 3> *stress,
                    const unsigned int     n,
                    const double           dt) const = 0;

    /**
     * update_stresses() of n points that share their strain rate and
     * rotation (those of @p shared, whose volume_ratio is not read), point
     * i with the volume ratio @p volume_ratio[i]: the stress stage's call
     * for a cell's run of points of the material (without the nodal
     * projection, a cell's points share its velocity gradient). The
     * default copies @p shared for each point and calls update_stresses();
     * a material that reads little of the kinematics overrides it without
     * the copies (128 B per point).
     */
    virtual void
    update_stresses_of_run(const PointKinematics &shared,
                           const double          *volume_ratio,
                           SymmetricTensor<2, 3> *stress,
                           const unsigned int     n,
                           const double           dt) const;

    /// Fastest wave speed at the given mass density (for the time step).
    virtual double
    wave_speed(const double density) const = 0;

    /// speed[i] = wave_speed(density[i]) for i < n: the time step calls
    /// this once per run of points of the material. The default calls
    /// wave_speed() per point; a material whose speed is a few operations
    /// overrides it with a loop the compiler vectorises (the same bits).
    virtual void
    wave_speeds(const double      *density,
                double            *speed,
                const unsigned int n) const
    {
      for (unsigned int i = 0; i < n; ++i)
        speed[i] = wave_speed(density[i]);
    }

    /// Stored (recoverable) energy per unit volume at the given stress.
    virtual double
    strain_energy_density(const SymmetricTensor<2, 3> &stress) const = 0;

    /// @p energy plus the stored energy of n points, added in the order
    /// i = 0, ..., n - 1 (so a run's sum continues the caller's with the
    /// same bits as a loop over its points): the energies call this once
    /// per run of points of the material. The default, for a material whose
    /// state is its stress, adds volume[i] strain_energy_density(stress[i]);
    /// a fluid's state is its volume ratio volume[i] / reference_volume[i]
    /// (the nodal pressure average overwrites the pressure its stress
    /// holds), and it overrides this.
    virtual double
    add_strain_energy(const SymmetricTensor<2, 3> *stress,
                      const double                *volume,
                      const double * /*reference_volume*/,
                      const unsigned int n,
                      double             energy) const
    {
      for (unsigned int i = 0; i < n; ++i)
        energy += volume[i] * strain_energy_density(stress[i]);
      return energy;
    }

    /// Whether dissipated_energy() can be non-zero: the stress update
    /// keeps the old stresses and volumes for it only then. A material
    /// that overrides dissipated_energy() overrides this too.
    virtual bool
    dissipates() const
    {
      return false;
    }

    /**
     * The energy (J; J/m in 2D) that the stress update of n points
     * dissipated: plastic work in an elastoplastic material, viscous work
     * in a fluid (monitors.csv's material_dissipation). The points had
     * @p old_stress and @p old_volume and now have @p new_stress and
     * @p new_volume, updated with @p kinematics over @p dt. The default, for
     * an elastic material, is zero; a material that dissipates overrides
     * it. Where the points keep their plastic state (@p plasticity not
     * null), a material that yields also updates it.
     */
    virtual double
    dissipated_energy(const SymmetricTensor<2, 3> * /*old_stress*/,
                      const SymmetricTensor<2, 3> * /*new_stress*/,
                      const double * /*old_volume*/,
                      const double * /*new_volume*/,
                      const PointKinematics & /*kinematics*/,
                      const unsigned int /*n*/,
                      const double /*dt*/,
                      const PointPlasticity * /*plasticity*/ = nullptr) const
    {
      return 0.;
    }

    /// Whether the material yields (the points then keep their plastic
    /// strain and yield flag for the output; dissipated_energy() fills
    /// them).
    virtual bool
    yields() const
    {
      return false;
    }

    /// Mass density at which the material is created.
    virtual double
    reference_density() const = 0;

    /// Dynamic viscosity (Pa s) for the viscous time-step limit.
    virtual double
    viscosity() const
    {
      return 0.;
    }

    /// Fluids: the volume ratio J = V/V_ref at which the material carries
    /// the pressure p (for a hydrostatic initial state). Solids: 1.
    virtual double
    volume_ratio_for_pressure(const double /*pressure*/) const
    {
      return 1.;
    }

    /// The admissible volume ratio for a trial J (after the volume update):
    /// a fluid that cannot carry tension cannot expand beyond its reference
    /// volume either (no energy-free expansion at zero pressure).
    virtual double
    admissible_volume_ratio(const double J) const
    {
      return J;
    }

    /// Whether update_stresses() reads PointKinematics::rotation (the
    /// stress stage then computes it; else it passes the identity). True
    /// unless a material says otherwise: a stress that is isotropic plus
    /// a function of the strain rate alone needs no rotation.
    virtual bool
    rotates_stress() const
    {
      return true;
    }

    /// Whether the material is a fluid (free-surface detection applies).
    virtual bool
    is_fluid() const
    {
      return false;
    }
  };
} // namespace fsgmpm

#endif
