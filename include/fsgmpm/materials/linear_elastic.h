#ifndef fsgmpm_materials_linear_elastic_h
#define fsgmpm_materials_linear_elastic_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/materials/isotropic_elasticity.h>
#include <fsgmpm/materials/material.h>

namespace fsgmpm
{
  /**
   * Isotropic linear (hypo)elasticity with the Hill rate of paper Eq. (6):
   * sigma^{n+1} = R sigma^n R^T + dt (D : d - tr(d) R sigma^n R^T),
   * d the strain rate, D = lambda I x I + 2 G II.
   */
  class LinearElastic : public Material
  {
  public:
    LinearElastic(const double youngs_modulus,
                  const double poisson_ratio,
                  const double density);

    static void
    declare_parameters(ParameterHandler &prm);
    /// Read and validate; @p path names the subsection in error messages.
    static std::unique_ptr<LinearElastic>
    create(ParameterHandler  &prm,
           const double       density,
           const std::string &path);

    std::string
    name() const override
    {
      return "linear elastic";
    }

    void
    update_stresses(const PointKinematics *kinematics,
                    SymmetricTensor<2, 3> *stress,
                    const unsigned int     n,
                    const double           dt) const override;

    double
    wave_speed(const double density) const override;

    double
    strain_energy_density(const SymmetricTensor<2, 3> &stress) const override;

    double
    reference_density() const override
    {
      return density;
    }

    const double              density;
    const IsotropicElasticity elasticity;
  };
} // namespace fsgmpm

#endif
