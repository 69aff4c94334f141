// Mohr-Coulomb material point (prescribed velocity gradient, no grid)
// against closed-form answers: (i) triaxial and plane-strain
// compression reach the Mohr-Coulomb limit within 0.5%; (ii) the plastic
// volumetric strain follows psi; (iii) a stressed point under rigid
// rotation keeps its principal stresses to 1e-8 over a full turn; (iv) a
// tension path returns to the apex c cot(phi); (v) returns to the edges
// (triaxial compression and extension) are exact; (vi) for 4000 random
// trial stresses (fixed seed) with associated flow the return is the
// point of the yield surface closest to the trial in the elastic energy
// norm: checked against a brute-force projection that enumerates every
// plane, every edge and the apex of the hexagonal pyramid in principal
// space (the feasible candidate nearest the trial), and against 64
// sampled surface points around the returned one; the kind of return
// (plane, edge, apex) matches the brute force's active set, for general
// and for plane-strain trials (every other one); (vii) the closed-form
// principal stresses of a plane-strain stress (principal_stresses()) are
// deal.II's eigenvectors() to round-off.

#include <fsgmpm/materials/hill_rotation.h>
#include <fsgmpm/materials/mohr_coulomb.h>
#include <fsgmpm/materials/principal_stresses.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <iomanip>
#include <limits>
#include <random>
#include <vector>

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

// The closed form of the Hughes-Winget rotation (Cayley transform) equals
// (I - A)^{-1} (I + A), A = dt W / 2, and is orthogonal, for a general 3D
// spin from small to very large dt |W| (measured: 2e-16 and 4e-16).
TEST(HillRotation, ClosedFormEqualsTheInverseForm)
{
  Tensor<2, 3> w;
  w[0][1]              = 0.3;
  w[0][2]              = -1.1;
  w[1][2]              = 0.7;
  w                    = w - transpose(w);
  const Tensor<2, 3> I = unit_symmetric_tensor<3>();
  for (const double dt : {1e-6, 1e-2, 1., 1e2})
    {
      const Tensor<2, 3> R = incremental_rotation(w, dt);
      const Tensor<2, 3> R_inverse_form
        = invert(I - 0.5 * dt * w) * (I + 0.5 * dt * w);
      EXPECT_LT((R - R_inverse_form).norm(), 1e-14) << "dt = " << dt;
      EXPECT_LT((R * transpose(R) - I).norm(), 1e-14) << "dt = " << dt;
    }
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


namespace
{
  using Principal = std::array<double, 3>;

  // Brute-force closest point of the Mohr-Coulomb pyramid (all six
  // planes f_ij = (s_i - s_j) + (s_i + s_j) sin(phi) - 2 c cos(phi) <= 0,
  // unsorted principal stresses) to the trial t in the energy norm
  // |d|^2 = d . C^-1 d: every single plane and every pair of planes
  // (an edge) is projected onto, the apex is added, and the feasible
  // candidate nearest t wins (a convex set: the nearest feasible
  // active-set projection is the projection). Returns the point and the
  // number of planes active there (1: plane, 2: edge, 6: apex).
  struct BruteForce
  {
    double E, nu, sphi, k; // k = 2 c cos(phi)

    double
    f(const Principal &s, const unsigned i, const unsigned j) const
    {
      return (s[i] - s[j]) + (s[i] + s[j]) * sphi - k;
    }
    double
    f_max(const Principal &s) const
    {
      double m = -std::numeric_limits<double>::infinity();
      for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j)
          if (i != j)
            m = std::max(m, f(s, i, j));
      return m;
    }
    Principal
    normal(const unsigned i, const unsigned j) const
    {
      Principal n = {{0, 0, 0}};
      n[i]        = 1 + sphi;
      n[j]        = -(1 - sphi);
      return n;
    }
    // C v and |v|^2 in the energy norm.
    Principal
    C(const Principal &v) const
    {
      const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
                   mu2    = E / (1 + nu);
      const double tr     = v[0] + v[1] + v[2];
      return {{lambda * tr + mu2 * v[0],
               lambda * tr + mu2 * v[1],
               lambda * tr + mu2 * v[2]}};
    }
    double
    energy(const Principal &a, const Principal &b) const
    {
      const Principal d  = {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
      const double    tr = d[0] + d[1] + d[2];
      return ((1 + nu) * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
              - nu * tr * tr)
             / E;
    }
    static double
    dot(const Principal &a, const Principal &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    std::pair<Principal, unsigned int>
    project(const Principal &t, const double scale) const
    {
      std::vector<std::pair<unsigned, unsigned>> planes;
      for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j)
          if (i != j)
            planes.emplace_back(i, j);
      double                             best = 1e300;
      std::pair<Principal, unsigned int> result;
      auto consider = [&](const Principal &s, const unsigned int active) {
        if (f_max(s) > 1e-9 * scale)
          return;
        const double e = energy(s, t);
        if (e < best)
          {
            best   = e;
            result = {s, active};
          }
      };
      // Minimise |s - t|^2 subject to n_a . s = k: s = t - sum l_a C n_a.
      for (unsigned a = 0; a < planes.size(); ++a)
        {
          const Principal na  = normal(planes[a].first, planes[a].second);
          const Principal Cna = C(na);
          const double    l
            = f(t, planes[a].first, planes[a].second) / dot(na, Cna);
          consider({{t[0] - l * Cna[0], t[1] - l * Cna[1], t[2] - l * Cna[2]}},
                   1);
          for (unsigned b = a + 1; b < planes.size(); ++b)
            {
              const Principal nb  = normal(planes[b].first, planes[b].second);
              const Principal Cnb = C(nb);
              const double    m00 = dot(na, Cna), m01 = dot(na, Cnb),
                           m11 = dot(nb, Cnb);
              const double det = m00 * m11 - m01 * m01;
              if (std::abs(det) < 1e-12 * m00 * m11)
                continue; // parallel planes (none for phi > 0)
              const double fa = f(t, planes[a].first, planes[a].second),
                           fb = f(t, planes[b].first, planes[b].second);
              const double la = (fa * m11 - m01 * fb) / det,
                           lb = (m00 * fb - m01 * fa) / det;
              consider({{t[0] - la * Cna[0] - lb * Cnb[0],
                         t[1] - la * Cna[1] - lb * Cnb[1],
                         t[2] - la * Cna[2] - lb * Cnb[2]}},
                       2);
            }
        }
      const double apex = k / (2 * sphi);
      consider({{apex, apex, apex}}, 6);
      return result;
    }
  };
} // namespace

TEST(MohrCoulomb, RandomTrialsReturnToTheClosestPointInTheEnergyNorm)
{
  std::mt19937 generator(20240513);
  auto         uniform = [&](const double a, const double b) {
    return a + (b - a) * (generator() / 4294967296.);
  };
  unsigned int counts[5]      = {0, 0, 0, 0, 0};
  double       worst_distance = 0, worst_surface = 0, worst_sample = 1e300;
  unsigned int n_trials = 0;
  for (const auto &[E_, nu_, phi_, c_] :
       {std::array<double, 4>{{1e7, 0.3, 30, 1e4}},
        std::array<double, 4>{{5e6, 0.45, 40, 0}},
        std::array<double, 4>{{2e7, 0.1, 15, 5e4}}})
    {
      const MohrCoulomb m(E_, nu_, phi_, phi_, c_, 2000);
      const BruteForce  brute{E_,
                             nu_,
                             std::sin(phi_ * M_PI / 180),
                             2 * c_ * std::cos(phi_ * M_PI / 180)};
      for (unsigned int trial_no = 0; trial_no < 1400; ++trial_no)
        {
          // Mean stress from tension beyond the apex to deep compression,
          // deviator up to 1.5 times that scale, random orientation.
          const double          scale = 4e5;
          SymmetricTensor<2, 3> trial;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = i; j < 3; ++j)
              trial[i][j] = uniform(-0.75, 0.75) * scale;
          // Every other trial in plane strain (the 2D points' stresses):
          // the return's closed-form principal stresses.
          if (trial_no % 2 == 1)
            trial[0][2] = trial[1][2] = 0;
          trial += uniform(-1, 0.4) * scale * unit_symmetric_tensor<3>();
          MohrCoulomb::Return kind;
          const auto          s = m.return_mapping(trial, kind);
          ++counts[static_cast<int>(kind)];
          ++n_trials;
          const auto      eig = eigenvectors(trial);
          const Principal t   = {{eig[0].first, eig[1].first, eig[2].first}};
          const double    size
            = std::abs(t[0]) + std::abs(t[2]) + brute.k; // stress scale
          const auto [p, active] = brute.project(t, size);
          // Brute force in principal space, rebuilt on the trial's axes.
          SymmetricTensor<2, 3> expected;
          for (unsigned int i = 0; i < 3; ++i)
            expected
              += p[i] * symmetrize(outer_product(eig[i].second, eig[i].second));
          const bool elastic = brute.f_max(t) <= 0;
          if (elastic)
            expected = trial;
          const double distance = (s - expected).norm() / size;
          worst_distance        = std::max(worst_distance, distance);
          EXPECT_LT(distance, 1e-9) << "trial " << trial << ", returned " << s
                                    << ", brute force " << expected;
          // Kind of return against the brute force's active set.
          const MohrCoulomb::Return expected_kind
            = elastic       ? MohrCoulomb::Return::elastic
              : active == 1 ? MohrCoulomb::Return::plane
              : active == 6 ? MohrCoulomb::Return::apex
              : p[0] - p[1] < p[1] - p[2]
                ? MohrCoulomb::Return::edge_compression
                : MohrCoulomb::Return::edge_extension;
          EXPECT_EQ(static_cast<int>(kind), static_cast<int>(expected_kind))
            << "trial " << trial;
          if (elastic)
            continue;
          // The returned stress is on the surface (principal values on the
          // trial's axes, which it shares: deal.II's closed-form
          // eigenvalues() loses 1e-8 at the repeated roots of an edge) ...
          Principal returned;
          for (unsigned int i = 0; i < 3; ++i)
            returned[i] = eig[i].second * (s * eig[i].second);
          worst_surface
            = std::max(worst_surface, std::abs(brute.f_max(returned)) / size);
          EXPECT_NEAR(brute.f_max(returned), 0, 1e-10 * size);
          // ... and no sampled surface point near it is closer: points
          // around it (scales from 1e-6 to 1 of the distance) moved onto
          // the surface along the hydrostatic axis.
          const double d2 = brute.energy(returned, t);
          const double r  = std::sqrt(brute.energy(returned, t) * E_);
          for (unsigned int k = 0; k < 64; ++k)
            {
              const double h     = r * std::pow(10., -uniform(0, 6));
              Principal    q     = {{returned[0] + h * uniform(-1, 1),
                                     returned[1] + h * uniform(-1, 1),
                                     returned[2] + h * uniform(-1, 1)}};
              const double shift = -brute.f_max(q) / (2 * brute.sphi);
              for (auto &x : q)
                x += shift;
              const double dq = brute.energy(q, t);
              worst_sample    = std::min(worst_sample, (dq - d2) / d2);
              EXPECT_GE(dq, d2 * (1 - 1e-9)) << "trial " << trial;
            }
        }
    }
  std::cout << "[ measured ] " << n_trials << " random trials: " << counts[0]
            << " elastic, " << counts[1] << " plane, " << counts[2]
            << " compression edge, " << counts[3] << " extension edge, "
            << counts[4] << " apex; worst |returned - brute force| / scale "
            << worst_distance << ", worst |f| / scale " << worst_surface
            << ", closest sampled surface point (d_q - d)/d " << worst_sample
            << std::endl;
  // Every kind of return is exercised.
  for (const unsigned int n : counts)
    EXPECT_GE(n, 10u);
}



// The principal stresses of a plane-strain stress in closed form
// (principal_stresses(), used by the return mapping) against deal.II's
// eigenvectors() (QL with implicit shifts): the values to 4e-15 of the
// tensor's size (measured 1.6e-15), the directions unit and orthogonal to
// 1e-15, the tensor rebuilt from them to 1e-15, and each direction deal.II's
// up to its sign (1 - |cos| below 1e-15) where the values are apart. Against
// the values in extended precision (long double), the closed form's error is
// printed beside deal.II's and must not be larger than 1e-15. Random tensors
// (fixed seed) and the degenerate ones: isotropic in the plane, no shear
// with either diagonal entry the larger, s_zz equal to an in-plane value,
// zero.
TEST(MohrCoulomb, PlaneStrainPrincipalStressesAreDealIIs)
{
  std::mt19937 generator(777);
  auto         uniform = [&](const double a, const double b) {
    return a + (b - a) * (generator() / 4294967296.);
  };
  std::vector<SymmetricTensor<2, 3>> cases;
  for (unsigned int k = 0; k < 2000; ++k)
    {
      SymmetricTensor<2, 3> s;
      s[0][0] = uniform(-1e6, 1e5);
      s[1][1] = uniform(-1e6, 1e5);
      s[2][2] = uniform(-1e6, 1e5);
      s[0][1] = uniform(-5e5, 5e5) * (k % 5 == 0 ? 1e-9 : 1.);
      cases.push_back(s);
    }
  const auto diagonal = [](const double a, const double b, const double c) {
    SymmetricTensor<2, 3> s;
    s[0][0] = a;
    s[1][1] = b;
    s[2][2] = c;
    return s;
  };
  cases.push_back(diagonal(-3e5, -3e5, -1e5));
  cases.push_back(diagonal(-1e5, -4e5, -2e5));
  cases.push_back(diagonal(-4e5, -1e5, -2e5));
  cases.push_back(diagonal(-2e5, -1e5, -2e5));
  cases.push_back(diagonal(0, 0, 0));
  double worst_value = 0, worst_unit = 0, worst_rebuilt = 0, worst_axis = 0;
  double worst_mine = 0, worst_dealii = 0; // against extended precision
  for (const auto &s : cases)
    {
      const auto            mine = principal_stresses(s);
      const auto            ref  = eigenvectors(s);
      const double          size = std::max(s.norm(), 1e-300);
      SymmetricTensor<2, 3> rebuilt;
      for (unsigned int i = 0; i < 3; ++i)
        {
          worst_value = std::max(worst_value,
                                 std::abs(mine[i].first - ref[i].first) / size);
          worst_unit
            = std::max(worst_unit, std::abs(mine[i].second.norm() - 1));
          worst_unit
            = std::max(worst_unit,
                       std::abs(mine[i].second * mine[(i + 1) % 3].second));
          rebuilt
            += mine[i].first
               * symmetrize(outer_product(mine[i].second, mine[i].second));
          const double gap_below
            = i == 0 ? 1e300 : ref[i - 1].first - ref[i].first;
          const double gap_above
            = i == 2 ? 1e300 : ref[i].first - ref[i + 1].first;
          if (std::min(gap_below, gap_above) > 1e-6 * size)
            worst_axis = std::max(worst_axis,
                                  1 - std::abs(mine[i].second * ref[i].second));
        }
      worst_rebuilt = std::max(worst_rebuilt, (rebuilt - s).norm() / size);
      // The in-plane values and s_zz in long double, sorted descending.
      const long double m = 0.5L * ((long double)s[0][0] + s[1][1]);
      const long double h = 0.5L * ((long double)s[0][0] - s[1][1]);
      const long double r
        = std::sqrt(h * h + (long double)s[0][1] * (long double)s[0][1]);
      std::array<long double, 3> exact = {{m + r, m - r, s[2][2]}};
      std::sort(exact.begin(), exact.end(), std::greater<long double>());
      for (unsigned int i = 0; i < 3; ++i)
        {
          worst_mine
            = std::max(worst_mine,
                       double(std::abs(mine[i].first - exact[i]) / size));
          worst_dealii
            = std::max(worst_dealii,
                       double(std::abs(ref[i].first - exact[i]) / size));
        }
      for (unsigned int i = 0; i < 2; ++i)
        EXPECT_GE(mine[i].first, mine[i + 1].first);
    }
  std::cout << "[ measured ] values " << worst_value << ", unit/orthogonal "
            << worst_unit << ", rebuilt " << worst_rebuilt
            << ", axes 1 - |cos| " << worst_axis
            << "; against long double: closed form " << worst_mine
            << ", deal.II " << worst_dealii << std::endl;
  EXPECT_LT(worst_value, 4e-15);
  EXPECT_LT(worst_mine, 1e-15);
  EXPECT_LT(worst_unit, 1e-15);
  EXPECT_LT(worst_rebuilt, 1e-15);
  EXPECT_LT(worst_axis, 1e-15);
  // A tensor with out-of-plane shear is deal.II's own answer.
  SymmetricTensor<2, 3> general = diagonal(-1e5, -2e5, -3e5);
  general[0][2]                 = 4e4;
  const auto a = principal_stresses(general), b = eigenvectors(general);
  for (unsigned int i = 0; i < 3; ++i)
    {
      EXPECT_EQ(a[i].first, b[i].first);
      EXPECT_EQ(a[i].second, b[i].second);
    }
}

// The plastic work booked by dissipated_energy() (monitors.csv's
// material_dissipation): simple shear of a cohesive, frictionless soil
// (phi = 0, psi = 0, c = 10 kPa, so that yield is tau = c) from zero stress
// to gamma = 0.05 in 5 000 steps, the stretching d_xy = gamma_dot / 2 with
// no spin. Elastic-perfectly plastic: tau rises as G gamma to c at
// gamma_y = c / G, then stays, and the dissipated work per unit volume is
// c (gamma - gamma_y) (the stored c^2 / (2 G) is the rest of the work).
// Measured: the booked sum equals it to 1e-13 (the return mapping splits
// the yield step exactly); nothing is booked before the yield step.
// Tolerance 1e-10.
TEST(MohrCoulomb, PlasticWorkIsBooked)
{
  const MohrCoulomb     m(E, nu, 0, 0, c, 2000);
  const double          G = E / (2 * (1 + nu)), gamma_dot = 1, dt = 1e-5;
  const unsigned int    n = 5000;
  PointKinematics       k;
  SymmetricTensor<2, 3> s;
  k.strain_rate[0][1] = gamma_dot / 2;
  k.rotation          = unit_symmetric_tensor<3>();
  const double volume = 1;
  double       booked = 0, booked_elastic = 0;
  // The point's plastic state: the equivalent plastic strain of simple
  // shear is gamma_p / sqrt(3), gamma_p = gamma - c / G; the point yields
  // from the step that reaches gamma_y on.
  double          plastic_strain = 0;
  std::uint8_t    yielding       = 0;
  PointPlasticity state{&plastic_strain, &yielding};
  unsigned int    elastic_steps_yielding = 0, plastic_steps_not = 0;
  for (unsigned int i = 0; i < n; ++i)
    {
      const SymmetricTensor<2, 3> old = s;
      m.update_stresses(&k, &s, 1, dt);
      const double w
        = m.dissipated_energy(&old, &s, &volume, &volume, k, 1, dt, &state);
      booked += w;
      if ((i + 1) * dt * gamma_dot < c / G)
        {
          booked_elastic += std::abs(w);
          elastic_steps_yielding += yielding;
        }
      else if (i * dt * gamma_dot > c / G)
        plastic_steps_not += (yielding == 0);
    }
  const double gamma = n * dt * gamma_dot;
  const double exact = c * (gamma - c / G);
  std::cout << "[ measured ] simple shear to " << gamma << ": tau " << s[0][1]
            << " Pa (c = " << c << "), plastic work booked " << booked
            << " J/m^3, exact " << exact << " (ratio " << booked / exact
            << "), before yield " << booked_elastic
            << ", ratio - 1 = " << std::setprecision(3) << booked / exact - 1
            << std::endl;
  EXPECT_NEAR(s[0][1] / c, 1., 1e-9);
  EXPECT_NEAR(booked / exact, 1., 1e-10);
  EXPECT_LT(booked_elastic, 1e-12 * exact);
  const double exact_strain = (gamma - c / G) / std::sqrt(3.);
  std::cout << "[ measured ] equivalent plastic strain " << plastic_strain
            << ", exact " << exact_strain
            << " (ratio - 1 = " << plastic_strain / exact_strain - 1 << ")"
            << std::endl;
  EXPECT_NEAR(plastic_strain / exact_strain, 1., 1e-10);
  EXPECT_EQ(elastic_steps_yielding, 0u);
  EXPECT_EQ(plastic_steps_not, 0u);
}
