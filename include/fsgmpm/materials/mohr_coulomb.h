#ifndef fsgmpm_materials_mohr_coulomb_h
#define fsgmpm_materials_mohr_coulomb_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/materials/isotropic_elasticity.h>
#include <fsgmpm/materials/material.h>

#include <algorithm>
#include <array>
#include <limits>
#include <memory>

namespace fsgmpm
{
  /**
   * Mohr-Coulomb yield criterion in principal stresses (tension positive,
   * s1 >= s2 >= s3), paper Eq. (7): f = (s1 - s3) + (s1 + s3) sin(phi)
   * - 2 c cos(phi); the plastic potential g has the same form with the
   * dilatancy psi (Eq. 8). Apex at s = c cot(phi).
   */
  struct MohrCoulombSurface
  {
    double sin_angle, cohesion_term; // sin(phi or psi), 2 c cos(phi)

    /// Value for the plane through principal stresses i (larger) and j.
    double
    value(const std::array<double, 3> &s,
          const unsigned               i,
          const unsigned               j) const
    {
      return (s[i] - s[j]) + (s[i] + s[j]) * sin_angle - cohesion_term;
    }

    /// Gradient of that plane with respect to the principal stresses.
    std::array<double, 3>
    gradient(const unsigned i, const unsigned j) const
    {
      std::array<double, 3> n = {{0, 0, 0}};
      n[i]                    = 1 + sin_angle;
      n[j]                    = -(1 - sin_angle);
      return n;
    }
  };

  /**
   * Linear elastic-perfectly plastic Mohr-Coulomb soil, paper Eqs. (5)-(8),
   * with the Hill stress rate (Eq. 6, exactly orthogonal rotation) and a
   * return mapping in principal stresses with the exact returns to the main
   * plane, to the two edges (triaxial compression s1 = s2, triaxial
   * extension s2 = s3) and to the apex (tension). Non-associated: the flow
   * direction is the gradient of g (dilatancy psi). sigma_zz is a full
   * member of the state in plane strain.
   */
  class MohrCoulomb : public Material
  {
  public:
    MohrCoulomb(const double youngs_modulus,
                const double poisson_ratio,
                const double friction_angle_degrees,
                const double dilatancy_angle_degrees,
                const double cohesion,
                const double density,
                const double max_volume_ratio
                = std::numeric_limits<double>::infinity());

    static void
    declare_parameters(ParameterHandler &prm);
    static std::unique_ptr<MohrCoulomb>
    create(ParameterHandler  &prm,
           const double       density,
           const std::string &path);

    std::string
    name() const override
    {
      return "Mohr-Coulomb";
    }

    void
    update_stresses(const PointKinematics *kinematics,
                    SymmetricTensor<2, 3> *stress,
                    const unsigned int     n,
                    const double           dt) const override;

    double
    wave_speed(const double density) const override;

    /// A point that has come apart at the apex (cohesionless soil in
    /// tension) does not grow without bound: its volume ratio is capped at
    /// max_volume_ratio. Uncapped, points at a flow front reached J = 100
    /// and, pushed back into contact, carried stress over a hundredfold
    /// volume (hundredfold nodal forces on light nodes): the run blew up.
    double
    admissible_volume_ratio(const double J) const override
    {
      return std::min(J, max_volume_ratio);
    }

    double
    strain_energy_density(const SymmetricTensor<2, 3> &stress) const override;

    bool
    dissipates() const override
    {
      return true;
    }

    /// The plastic work of the return mapping, sigma^{n+1} : C^-1 :
    /// (sigma_trial - sigma^{n+1}) V^{n+1}, sigma_trial the elastic
    /// predictor from the old stress (backward Euler's sigma : d^p dt V);
    /// the same plastic strain increment C^-1 : (sigma_trial - sigma^{n+1})
    /// into @p plasticity.
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

    bool
    yields() const override
    {
      return true;
    }

    double
    reference_density() const override
    {
      return density;
    }

    /// Where the return mapping ended.
    enum class Return
    {
      elastic,
      plane,
      edge_compression, ///< s1 = s2 (triaxial compression)
      edge_extension,   ///< s2 = s3 (triaxial extension)
      apex
    };

    /// Return mapping of a trial stress onto the yield surface. Also
    /// reports the kind of return (for tests).
    SymmetricTensor<2, 3>
    return_mapping(const SymmetricTensor<2, 3> &trial, Return &kind) const;

    /// Yield function of a stress (principal stresses sorted inside).
    double
    yield_function(const SymmetricTensor<2, 3> &stress) const;

    const double              density;
    const IsotropicElasticity elasticity;
    const MohrCoulombSurface  yield, potential;
    const double              apex; ///< c cot(phi) (infinite for phi = 0)
    const double              max_volume_ratio;

  private:
    /// Elastic matrix in principal space times a vector.
    std::array<double, 3>
    elastic(const std::array<double, 3> &v) const;
  };
} // namespace fsgmpm

#endif
