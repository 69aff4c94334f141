// Mohr-Coulomb material point (prescribed velocity gradient, no grid)
// against closed-form answers (issue 4): (i) triaxial and plane-strain
// compression reach the Mohr-Coulomb limit within 0.5%; (ii) the plastic
// volumetric strain follows psi; (iii) a stressed point under rigid
// rotation keeps its principal stresses to 1e-8 over a full turn; (iv) a
// tension path returns to the apex c cot(phi); (v) returns to the edges
// (triaxial compression and extension) are exact.

#include <fsgmpm/materials/hill_rotation.h>
#include <fsgmpm/materials/mohr_coulomb.h>
#include <gtest/gtest.h>

using namespace fsgmpm;

namespace
{
  constexpr double E = 1e7, nu = 0.3, phi = 30, c = 1e4;
  const double     sphi = std::sin(phi * M_PI / 180),
               cphi     = std::cos(phi * M_PI / 180);

  // Drive one point with a constant strain rate d (and spin w) for n steps.
  SymmetricTensor<2, 3>
  drive(const MohrCoulomb           &m,
        SymmetricTensor<2, 3>        s,
        const SymmetricTensor<2, 3> &d,
        const Tensor<2, 3>          &w,
        const double                 dt,
        const unsigned int           n)
  {
    PointKinematics k;
    k.strain_rate = d;
    k.spin        = w;
    k.rotation    = incremental_rotation(w, dt);
    for (unsigned int i = 0; i < n; ++i)
      m.update_stresses(&k, &s, 1, dt);
    return s;
  }

  // Axial (most compressive) stress at failure for a given largest
  // principal stress s1: f = 0 solved for s3.
  double
  mc_limit(const double s1)
  {
    return (s1 * (1 + sphi) - 2 * c * cphi) / (1 - sphi);
  }
} // namespace

TEST(MohrCoulomb, TriaxialCompressionReachesTheLimit)
{
  const MohrCoulomb     m(E, nu, phi, 0, c, 2000);
  const double          p = 1e5;
  SymmetricTensor<2, 3> d;
  d[1][1] = -1; // axial y; lateral rates keep the lateral stress elastically
  d[0][0] = d[2][2] = nu;
  const auto s
    = drive(m, -p * unit_symmetric_tensor<3>(), d, Tensor<2, 3>(), 1e-5, 5000);
  const auto e = eigenvalues(s);
  std::cout << "[ measured ] triaxial: lateral " << e[0] << ", " << e[1]
            << " Pa, axial " << e[2] << " Pa, limit " << mc_limit(e[0]) << " Pa"
            << std::endl;
  EXPECT_NEAR(e[0], e[1], 1e-8 * p);
  EXPECT_NEAR(e[2] / mc_limit(e[0]), 1., 0.005);
  EXPECT_LT(e[2], -2 * p); // well beyond the confining stress: it yielded
}

TEST(MohrCoulomb, PlaneStrainCompressionReachesTheLimit)
{
  const MohrCoulomb     m(E, nu, phi, 0, c, 2000);
  const double          p = 1e5;
  SymmetricTensor<2, 3> d;
  d[1][1] = -1;
  d[0][0] = nu / (1 - nu); // zz rate zero: plane strain
  const auto s
    = drive(m, -p * unit_symmetric_tensor<3>(), d, Tensor<2, 3>(), 1e-5, 5000);
  const auto e = eigenvalues(s);
  std::cout << "[ measured ] plane strain: s1 " << e[0] << ", s2 " << e[1]
            << " (zz " << s[2][2] << "), s3 " << e[2] << " Pa, limit "
            << mc_limit(e[0]) << " Pa" << std::endl;
  EXPECT_NEAR(e[2] / mc_limit(e[0]), 1., 0.005);
  EXPECT_LT(e[2], -2 * p);
}

TEST(MohrCoulomb, PlasticVolumetricStrainFollowsDilatancy)
{
  for (const double psi : {0., 10., 30.})
    {
      const MohrCoulomb     m(E, nu, phi, psi, c, 2000);
      SymmetricTensor<2, 3> trial; // beyond yield, distinct principal stresses
      trial[0][0] = -1e5;
      trial[1][1] = -4e5;
      trial[2][2] = -2e5;
      trial[0][1] = 3e4;
      MohrCoulomb::Return kind;
      const auto          s = m.return_mapping(trial, kind);
      ASSERT_EQ(kind, MohrCoulomb::Return::plane);
      EXPECT_NEAR(m.yield_function(s), 0, 1e-9 * 4e5);
      // Plastic strain = C^-1 (trial - returned).
      const SymmetricTensor<2, 3> ds = trial - s;
      const SymmetricTensor<2, 3> dep
        = (1 + nu) / E * ds - nu / E * trace(ds) * unit_symmetric_tensor<3>();
      const auto   e     = eigenvalues(dep);
      const double ratio = trace(dep) / (e[0] - e[2]);
      // Plastic strain = dgamma dg/dsigma: its trace (dilation positive)
      // over the difference of its extreme principal values is sin(psi).
      EXPECT_NEAR(ratio, std::sin(psi * M_PI / 180), 1e-10) << "psi = " << psi;
    }
}

TEST(MohrCoulomb, RigidRotationKeepsPrincipalStresses)
{
  const MohrCoulomb     m(E, nu, phi, 0, c, 2000);
  SymmetricTensor<2, 3> s;
  s[0][0]             = -1e5;
  s[1][1]             = -1.6e5;
  s[2][2]             = -1.2e5;
  s[0][1]             = 2e4;
  const auto   before = eigenvalues(s);
  const double omega = 2 * M_PI, dt = 1e-3; // one turn in 1000 steps
  Tensor<2, 3> w;
  w[0][1]          = -omega;
  w[1][0]          = omega;
  const auto r     = drive(m, s, SymmetricTensor<2, 3>(), w, dt, 1000);
  const auto after = eigenvalues(r);
  for (unsigned int i = 0; i < 3; ++i)
    EXPECT_NEAR(after[i], before[i], 1e-8 * std::abs(before[2]));
}

TEST(MohrCoulomb, TensionReturnsToTheApex)
{
  const MohrCoulomb   m(E, nu, phi, 0, c, 2000);
  MohrCoulomb::Return kind;
  const auto s = m.return_mapping(1e6 * unit_symmetric_tensor<3>(), kind);
  EXPECT_EQ(kind, MohrCoulomb::Return::apex);
  const double apex = c * cphi / sphi;
  for (unsigned int i = 0; i < 3; ++i)
    EXPECT_NEAR(s[i][i], apex, 1e-12 * apex);
  EXPECT_NEAR(s[0][1], 0, 1e-12 * apex);
}

TEST(MohrCoulomb, EdgeReturnsAreExact)
{
  for (const double psi : {0., 20.})
    {
      const MohrCoulomb  m(E, nu, phi, psi, c, 2000);
      MohrCoulombSurface f = m.yield;
      // Triaxial compression: s1 = s2 > s3.
      SymmetricTensor<2, 3> txc;
      txc[0][0] = txc[2][2] = -1e5;
      txc[1][1]             = -8e5;
      MohrCoulomb::Return kind;
      auto                s = m.return_mapping(txc, kind);
      EXPECT_EQ(kind, MohrCoulomb::Return::edge_compression);
      auto e = eigenvalues(s);
      EXPECT_EQ(e[0], e[1]);
      EXPECT_NEAR(f.value({{e[0], e[1], e[2]}}, 0, 2), 0, 1e-10 * 8e5);
      EXPECT_NEAR(f.value({{e[0], e[1], e[2]}}, 1, 2), 0, 1e-10 * 8e5);
      // Triaxial extension: s1 > s2 = s3.
      SymmetricTensor<2, 3> txe;
      txe[0][0] = -1e5;
      txe[1][1] = txe[2][2] = -8e5;
      s                     = m.return_mapping(txe, kind);
      EXPECT_EQ(kind, MohrCoulomb::Return::edge_extension);
      e = eigenvalues(s);
      EXPECT_EQ(e[1], e[2]);
      EXPECT_NEAR(f.value({{e[0], e[1], e[2]}}, 0, 2), 0, 1e-10 * 8e5);
      EXPECT_NEAR(f.value({{e[0], e[1], e[2]}}, 0, 1), 0, 1e-10 * 8e5);
    }
}

// A point that comes apart at the apex stops growing at the cap, and the
// time-step wave speed follows the stiffness-to-mass ratio V/m of an
// expanded point (and keeps the reference density under compression).
TEST(MohrCoulomb, VolumeCapAndWaveSpeed)
{
  const double      rho = 1500, J_max = 1.2;
  const MohrCoulomb m(E, nu, phi, 0, 0, rho, J_max);
  EXPECT_EQ(m.admissible_volume_ratio(116.), J_max);
  EXPECT_EQ(m.admissible_volume_ratio(1.05), 1.05);
  EXPECT_EQ(m.admissible_volume_ratio(0.99), 0.99);
  const double M = m.elasticity.p_wave_modulus();
  EXPECT_NEAR(m.wave_speed(rho / J_max), std::sqrt(M * J_max / rho), 1e-12);
  EXPECT_NEAR(m.wave_speed(1.1 * rho), std::sqrt(M / rho), 1e-12);
  // Unit tests and direct construction: no cap unless asked for.
  const MohrCoulomb uncapped(E, nu, phi, 0, 0, rho);
  EXPECT_EQ(uncapped.admissible_volume_ratio(116.), 116.);
}
