#include <deal.II/base/exceptions.h>

#include <fsgmpm/materials/hill_rotation.h>
#include <fsgmpm/materials/linear_elastic.h>

#include <cmath>

namespace fsgmpm
{
  LinearElastic::LinearElastic(const double E,
                               const double nu,
                               const double density)
    : E(E)
    , nu(nu)
    , density(density)
    , lambda(E * nu / ((1 + nu) * (1 - 2 * nu)))
    , mu(E / (2 * (1 + nu)))
    , K(E / (3 * (1 - 2 * nu)))
  {}



  void
  LinearElastic::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear elastic");
    prm.declare_entry("Young's modulus",
                      "1e6",
                      Patterns::Double(0),
                      "Young's modulus E in Pa (> 0).");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      Patterns::Double(-1, 0.5),
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
      {
        const SymmetricTensor<2, 3> &d   = kin[i].strain_rate;
        const double                 trd = trace(d);
        const SymmetricTensor<2, 3>  rotated
          = rotate_stress(stress[i], kin[i].rotation);
        stress[i] = rotated
                    + dt
                        * (lambda * trd * unit_symmetric_tensor<3>()
                           + 2 * mu * d - trd * rotated);
      }
  }



  double
  LinearElastic::wave_speed(const double /*rho*/) const
  {
    // With the reference density: conservative under compression, and a
    // solid that has come apart (volume grown at the apex) does not carry
    // faster waves.
    return std::sqrt((K + 4. / 3. * mu) / density);
  }



  double
  LinearElastic::strain_energy_density(const SymmetricTensor<2, 3> &s) const
  {
    const double tr = trace(s);
    // eps = (1+nu)/E s - nu/E tr(s) I
    return 0.5 * ((1 + nu) / E * (s * s) - nu / E * tr * tr);
  }
} // namespace fsgmpm
