#ifndef fsgmpm_materials_isotropic_elasticity_h
#define fsgmpm_materials_isotropic_elasticity_h

#include <deal.II/base/symmetric_tensor.h>

#include <fsgmpm/materials/hill_rotation.h>
#include <fsgmpm/materials/material.h>

namespace fsgmpm
{
  /**
   * Isotropic linear elasticity shared by the solid materials: the elastic
   * predictor with the Hill rate of paper Eq. (6),
   * sigma^{n+1} = R sigma^n R^T + dt (D : d - tr(d) R sigma^n R^T),
   * D = lambda I x I + 2 mu II, and the stored energy.
   */
  struct IsotropicElasticity
  {
    IsotropicElasticity(const double E, const double nu)
      : E(E)
      , nu(nu)
      , lambda(E * nu / ((1 + nu) * (1 - 2 * nu)))
      , mu(E / (2 * (1 + nu)))
      , K(E / (3 * (1 - 2 * nu)))
    {}

    SymmetricTensor<2, 3>
    hill_predictor(const SymmetricTensor<2, 3> &sigma,
                   const PointKinematics       &k,
                   const double                 dt) const
    {
      const double                trd     = trace(k.strain_rate);
      const SymmetricTensor<2, 3> rotated = rotate_stress(sigma, k.rotation);
      return rotated
             + dt
                 * (lambda * trd * unit_symmetric_tensor<3>()
                    + 2 * mu * k.strain_rate - trd * rotated);
    }

    /// P-wave modulus K + 4/3 mu (for the wave speed).
    double
    p_wave_modulus() const
    {
      return K + 4. / 3. * mu;
    }

    /// sigma : C^-1 : sigma / 2.
    double
    strain_energy_density(const SymmetricTensor<2, 3> &s) const
    {
      const double tr = trace(s);
      return 0.5 * ((1 + nu) / E * (s * s) - nu / E * tr * tr);
    }

    const double E, nu, lambda, mu, K;
  };
} // namespace fsgmpm

#endif
