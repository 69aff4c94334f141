#include <deal.II/base/exceptions.h>

#include <fsgmpm/base/real_interval.h>
#include <fsgmpm/materials/linear_elastic.h>
#include <fsgmpm/materials/material_factory.h>

#include <cmath>

namespace fsgmpm
{
  LinearElastic::LinearElastic(const double E,
                               const double nu,
                               const double density)
    : density(density)
    , elasticity(E, nu)
  {}



  void
  LinearElastic::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear elastic");
    prm.declare_entry("Young's modulus",
                      "1e6",
                      RealInterval::above(0, 1e13),
                      "Young's modulus E in Pa (> 0, at most 1e13).");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      RealInterval(-1, 0.5, true, true),
                      "Poisson's ratio nu, -1 < nu < 0.5 (0.5, the "
                      "incompressible limit, is not allowed in an explicit "
                      "code).");
    prm.leave_subsection();
  }



  std::unique_ptr<LinearElastic>
  LinearElastic::create(ParameterHandler  &prm,
                        const double       density,
                        const std::string &path)
  {
    prm.enter_subsection("Linear elastic");
    const double E  = prm.get_double("Young's modulus");
    const double nu = prm.get_double("Poisson's ratio");
    prm.leave_subsection();
    AssertThrow(E > 0,
                ExcMessage(path
                           + "/Linear elastic/Young's modulus must be "
                             "positive; got "
                           + std::to_string(E) + "."));
    AssertThrow(nu > -1 && nu < 0.5,
                ExcMessage(path
                           + "/Linear elastic/Poisson's ratio must lie "
                             "in the open interval (-1, 0.5); got "
                           + std::to_string(nu) + "."));
    return std::make_unique<LinearElastic>(E, nu, density);
  }



  void
  LinearElastic::update_stresses(const PointKinematics *kin,
                                 SymmetricTensor<2, 3> *stress,
                                 const unsigned int     n,
                                 const double           dt) const
  {
    for (unsigned int i = 0; i < n; ++i)
      stress[i] = elasticity.hill_predictor(stress[i], kin[i], dt);
  }



  double
  LinearElastic::wave_speed(const double /*rho*/) const
  {
    // With the reference density: conservative under compression.
    return std::sqrt(elasticity.p_wave_modulus() / density);
  }



  double
  LinearElastic::strain_energy_density(const SymmetricTensor<2, 3> &s) const
  {
    return elasticity.strain_energy_density(s);
  }

  FSGMPM_REGISTER_MATERIAL(LinearElastic,
                           "linear elastic",
                           "isotropic hypoelasticity with the Hill rate, Eq. "
                           "(6) (subsection Linear elastic)")
} // namespace fsgmpm
