#include <deal.II/base/exceptions.h>

#include <fsgmpm/base/real_interval.h>
#include <fsgmpm/materials/hill_rotation.h>
#include <fsgmpm/materials/material_factory.h>
#include <fsgmpm/materials/mohr_coulomb.h>
#include <fsgmpm/materials/principal_stresses.h>

#include <cmath>
#include <limits>

namespace fsgmpm
{
  namespace
  {
    double
    dot(const std::array<double, 3> &a, const std::array<double, 3> &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    constexpr double degree = M_PI / 180.;
  } // namespace



  MohrCoulomb::MohrCoulomb(const double E,
                           const double nu,
                           const double phi,
                           const double psi,
                           const double c,
                           const double density,
                           const double max_volume_ratio)
    : density(density)
    , elasticity(E, nu)
    , yield{std::sin(phi * degree), 2 * c * std::cos(phi * degree)}
    , potential{std::sin(psi * degree), 0.}
    , apex(phi > 0 ? c / std::tan(phi * degree)
                   : std::numeric_limits<double>::infinity())
    , max_volume_ratio(max_volume_ratio)
  {}



  void
  MohrCoulomb::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mohr-Coulomb");
    prm.declare_entry("Young's modulus",
                      "5e6",
                      RealInterval::above(0, 1e13),
                      "Young's modulus E in Pa (> 0, at most 1e13).");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      RealInterval(-1, 0.5, true, true),
                      "Poisson's ratio, -1 < nu < 0.5.");
    prm.declare_entry("Friction angle",
                      "30",
                      RealInterval(0, 90, false, true),
                      "phi in degrees, 0 <= phi < 90.");
    prm.declare_entry("Dilatancy angle",
                      "0",
                      RealInterval(0, 90, false, true),
                      "psi in degrees, 0 <= psi <= phi.");
    prm.declare_entry("Cohesion",
                      "0",
                      Patterns::Double(0, 1e13),
                      "c in Pa (>= 0, at most 1e13).");
    prm.declare_entry("Maximum volume ratio",
                      "1.2",
                      RealInterval::above(1, 1e6),
                      "Cap on a point's volume ratio V/V0 (> 1, at most "
                      "1e6): points "
                      "that come apart at the apex (tension) stop growing "
                      "here; uncapped they reached 100 V0 at a flow front "
                      "and made the run unstable when pushed back into "
                      "contact.");
    prm.leave_subsection();
  }



  std::unique_ptr<MohrCoulomb>
  MohrCoulomb::create(ParameterHandler  &prm,
                      const double       density,
                      const std::string &path)
  {
    prm.enter_subsection("Mohr-Coulomb");
    const double E     = prm.get_double("Young's modulus");
    const double nu    = prm.get_double("Poisson's ratio");
    const double phi   = prm.get_double("Friction angle");
    const double psi   = prm.get_double("Dilatancy angle");
    const double c     = prm.get_double("Cohesion");
    const double J_max = prm.get_double("Maximum volume ratio");
    prm.leave_subsection();
    const std::string p = path + "/Mohr-Coulomb/";
    AssertThrow(E > 0, ExcMessage(p + "Young's modulus must be positive."));
    AssertThrow(nu > -1 && nu < 0.5,
                ExcMessage(p + "Poisson's ratio must lie in (-1, 0.5)."));
    AssertThrow(phi >= 0 && phi < 90,
                ExcMessage(p
                           + "Friction angle must lie in [0, 90) degrees; "
                             "got "
                           + std::to_string(phi) + "."));
    AssertThrow(psi >= 0 && psi <= phi,
                ExcMessage(p + "Dilatancy angle must lie in [0, phi]; got "
                           + std::to_string(psi) + "."));
    AssertThrow(phi > 0 || c > 0,
                ExcMessage(p + "Friction angle and " + p
                           + "Cohesion are both 0: a material with no "
                             "friction and no cohesion has no strength."));
    AssertThrow(J_max > 1,
                ExcMessage(p + "Maximum volume ratio must exceed 1; got "
                           + std::to_string(J_max) + "."));
    return std::make_unique<MohrCoulomb>(E, nu, phi, psi, c, density, J_max);
  }



  std::array<double, 3>
  MohrCoulomb::elastic(const std::array<double, 3> &v) const
  {
    const double tr = v[0] + v[1] + v[2];
    const double l = elasticity.lambda, m2 = 2 * elasticity.mu;
    return {{l * tr + m2 * v[0], l * tr + m2 * v[1], l * tr + m2 * v[2]}};
  }



  double
  MohrCoulomb::yield_function(const SymmetricTensor<2, 3> &stress) const
  {
    const auto e = eigenvalues(stress); // descending
    return yield.value({{e[0], e[1], e[2]}}, 0, 2);
  }



  SymmetricTensor<2, 3>
  MohrCoulomb::return_mapping(const SymmetricTensor<2, 3> &trial,
                              Return                      &kind) const
  {
    // Descending principal values with their directions (closed form in
    // plane strain: principal_stresses.h).
    const auto                  eig = principal_stresses(trial);
    const std::array<double, 3> s
      = {{eig[0].first, eig[1].first, eig[2].first}};
    const double scale = std::abs(s[0]) + std::abs(s[2]) + yield.cohesion_term;
    kind               = Return::elastic;
    if (yield.value(s, 0, 2) <= 1e-14 * scale)
      return trial;

    auto rebuild = [&](const std::array<double, 3> &p) {
      SymmetricTensor<2, 3> r;
      for (unsigned int i = 0; i < 3; ++i)
        r += p[i] * symmetrize(outer_product(eig[i].second, eig[i].second));
      return r;
    };
    auto ordered = [&](const std::array<double, 3> &p) {
      const double tol = 1e-12 * scale;
      return p[0] >= p[1] - tol && p[1] >= p[2] - tol;
    };

    // Main plane (0, 2).
    const auto            a  = yield.gradient(0, 2);
    const auto            Db = elastic(potential.gradient(0, 2));
    const double          dg = yield.value(s, 0, 2) / dot(a, Db);
    std::array<double, 3> p;
    for (unsigned int i = 0; i < 3; ++i)
      p[i] = s[i] - dg * Db[i];
    if (ordered(p))
      {
        kind = Return::plane;
        return rebuild(p);
      }

    // Edge: the second active plane is (1, 2) if the return crossed
    // s1 = s2 (triaxial compression), else (0, 1) (triaxial extension).
    const bool     compression = p[0] < p[1];
    const unsigned bi = compression ? 1 : 0, bj = compression ? 2 : 1;
    const auto     ab  = yield.gradient(bi, bj);
    const auto     Dbb = elastic(potential.gradient(bi, bj));
    const double   m00 = dot(a, Db), m01 = dot(a, Dbb);
    const double   m10 = dot(ab, Db), m11 = dot(ab, Dbb);
    const double   fa = yield.value(s, 0, 2), fb = yield.value(s, bi, bj);
    const double   det = m00 * m11 - m01 * m10;
    const double   ga  = (fa * m11 - m01 * fb) / det;
    const double   gb  = (m00 * fb - m10 * fa) / det;
    for (unsigned int i = 0; i < 3; ++i)
      p[i] = s[i] - ga * Db[i] - gb * Dbb[i];
    const double mean = (p[0] + p[1] + p[2]) / 3.;
    if (ga >= 0 && gb >= 0 && ordered(p) && mean <= apex)
      {
        kind = compression ? Return::edge_compression : Return::edge_extension;
        // The two principal stresses of the edge are equal exactly.
        if (compression)
          p[0] = p[1] = 0.5 * (p[0] + p[1]);
        else
          p[1] = p[2] = 0.5 * (p[1] + p[2]);
        return rebuild(p);
      }

    // Apex (tension): every principal stress at c cot(phi).
    Assert(std::isfinite(apex), ExcInternalError());
    kind = Return::apex;
    return apex * unit_symmetric_tensor<3>();
  }



  void
  MohrCoulomb::update_stresses(const PointKinematics *kin,
                               SymmetricTensor<2, 3> *stress,
                               const unsigned int     n,
                               const double           dt) const
  {
    Return kind;
    for (unsigned int i = 0; i < n; ++i)
      // Elastic predictor with the Hill rate, then the return mapping.
      stress[i]
        = return_mapping(elasticity.hill_predictor(stress[i], kin[i], dt),
                         kind);
  }



  double
  MohrCoulomb::wave_speed(const double rho) const
  {
    // The nodal stiffness-to-mass ratio of a point scales with V/m = 1/rho:
    // an expanded point (up to max_volume_ratio) is stiffer per mass; a
    // compressed one is bounded by the reference density (conservative).
    return std::sqrt(elasticity.p_wave_modulus() / std::min(rho, density));
  }



  double
  MohrCoulomb::dissipated_energy(const SymmetricTensor<2, 3> *old_stress,
                                 const SymmetricTensor<2, 3> *new_stress,
                                 const double * /*old_volume*/,
                                 const double          *new_volume,
                                 const PointKinematics &kinematics,
                                 const unsigned int     n,
                                 const double           dt,
                                 const PointPlasticity *plasticity) const
  {
    const double E = elasticity.E, nu = elasticity.nu;
    double       work = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        // The plastic strain increment C^-1 : (sigma_trial - sigma^{n+1}).
        const SymmetricTensor<2, 3> excess
          = elasticity.hill_predictor(old_stress[i], kinematics, dt)
            - new_stress[i];
        const SymmetricTensor<2, 3> plastic_strain
          = (1 + nu) / E * excess
            - nu / E * trace(excess) * unit_symmetric_tensor<3>();
        work += new_volume[i] * (new_stress[i] * plastic_strain);
        if (plasticity != nullptr)
          {
            const SymmetricTensor<2, 3> shear = deviator(plastic_strain);
            const double increment = std::sqrt(2. / 3. * (shear * shear));
            plasticity->strain[i] += increment;
            // An elastic step leaves the predictor (to round-off).
            plasticity->yielding[i]
              = (excess.norm() > 1e-10 * new_stress[i].norm()
                 && excess.norm() > 0);
          }
      }
    return work;
  }



  double
  MohrCoulomb::strain_energy_density(const SymmetricTensor<2, 3> &s) const
  {
    return elasticity.strain_energy_density(s);
  }

  FSGMPM_REGISTER_MATERIAL(MohrCoulomb,
                           "Mohr-Coulomb",
                           "linear elastic-perfectly plastic soil, Eqs. "
                           "(5)-(8) (subsection Mohr-Coulomb)")
} // namespace fsgmpm
