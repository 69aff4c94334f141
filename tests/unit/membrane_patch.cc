// Patch tests of the membrane element mechanics (no grid): a 2D cable and a
// 3-node triangle in 3D. (a) A uniform stretch gives the exact tension, the
// nodal forces sum to zero and equal minus a finite-difference gradient of
// the energy; (b) a rigid rotation of a stretched element keeps its stress
// and rotates its forces; (c) compression gives zero stress and force;
// (d) a wrinkled state (one negative principal stress, principal axes off
// the frame) is corrected exactly by Eqs. (9)-(10) of Hamad et al. (2017);
// (e) a compress-then-stretch cycle never remembers the slack (stateless);
// (f) bad input throws. Exact results are checked to 1e-12 relative.

#include <fsgmpm/membrane/membrane_mechanics.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace fsgmpm;
using namespace fsgmpm::MembraneMechanics;

namespace
{
  constexpr double EA = 2e5, nu = 0.3; // N/m, membrane or cable
  constexpr double tight = 1e-12;      // relative, for exact results

  Tensor<2, 3>
  unit()
  {
    Tensor<2, 3> I;
    for (unsigned int d = 0; d < 3; ++d)
      I[d][d] = 1;
    return I;
  }

  // Rotation by angle about an axis (Rodrigues).
  Tensor<2, 3>
  rotation(const Tensor<1, 3> &axis, const double angle)
  {
    const Tensor<1, 3> k = axis / axis.norm();
    Tensor<2, 3>       K;
    K[0][1] = -k[2];
    K[0][2] = k[1];
    K[1][0] = k[2];
    K[1][2] = -k[0];
    K[2][0] = -k[1];
    K[2][1] = k[0];
    return unit() + std::sin(angle) * K + (1 - std::cos(angle)) * K * K;
  }

  // Exact quarter turn (entries 0, +-1) about a coordinate axis.
  Tensor<2, 3>
  quarter_turn(const unsigned int axis)
  {
    Tensor<2, 3>       R;
    const unsigned int i = (axis + 1) % 3, j = (axis + 2) % 3;
    R[axis][axis] = 1;
    R[i][j]       = -1;
    R[j][i]       = 1;
    return R;
  }


  // x = X1 + c + A (X - X1) for each node: a homogeneous deformation.
  std::array<Point<3>, 3>
  deform(const std::array<Point<3>, 3> &X,
         const Tensor<2, 3>            &A,
         const Tensor<1, 3>            &c = Tensor<1, 3>())
  {
    std::array<Point<3>, 3> x;
    for (unsigned int i = 0; i < 3; ++i)
      x[i] = X[0] + c + A * (X[i] - X[0]);
    return x;
  }

  // Plane-stress Saint Venant-Kirchhoff S from a Green-Lagrange strain.
  PlaneStress
  svk(const double E11, const double E22, const double E12)
  {
    const double c = EA / (1 - nu * nu);
    return {{c * (E11 + nu * E22), c * (nu * E11 + E22), c * (1 - nu) * E12}};
  }

  // Energy W = A0 E:S/2 (no cut-off), written independently of the code
  // under test: its own rest frame (e1 along X3 - X1, not X2 - X1) and the
  // metric form C = Dm^{-T} (Ds^T Ds) Dm^{-1}.
  double
  triangle_energy(const std::array<Point<3>, 3> &X,
                  const std::array<Point<3>, 3> &x)
  {
    const Tensor<1, 3> A = X[2] - X[0], B = X[1] - X[0];
    const Tensor<1, 3> n  = cross_product_3d(A, B);
    const Tensor<1, 3> e1 = A / A.norm();
    const Tensor<1, 3> e2 = cross_product_3d(n / n.norm(), e1);
    Tensor<2, 2>       Dm, DsDs;
    Dm[0][0]             = A * e1;
    Dm[1][0]             = A * e2;
    Dm[0][1]             = B * e1;
    Dm[1][1]             = B * e2;
    const Tensor<1, 3> a = x[2] - x[0], b = x[1] - x[0];
    DsDs[0][0] = a * a;
    DsDs[0][1] = DsDs[1][0] = a * b;
    DsDs[1][1]              = b * b;
    const Tensor<2, 2> Di   = invert(Dm);
    const Tensor<2, 2> C    = transpose(Di) * DsDs * Di;
    const double       E11 = (C[0][0] - 1) / 2, E22 = (C[1][1] - 1) / 2,
                 E12     = C[0][1] / 2;
    const PlaneStress S  = svk(E11, E22, E12);
    const double      A0 = n.norm() / 2;
    return A0 / 2 * (E11 * S[0] + E22 * S[1] + 2 * E12 * S[2]);
  }

  std::array<Tensor<1, 3>, 3>
  forces(const std::array<Point<3>, 3> &X,
         const std::array<Point<3>, 3> &x,
         TriangleResponse              &r)
  {
    std::array<Tensor<1, 3>, 3> f;
    r = triangle_forces(
      make_triangle_reference(X[0], X[1], X[2]), x[0], x[1], x[2], EA, nu, f);
    return f;
  }

  double
  largest(const std::array<Tensor<1, 3>, 3> &f)
  {
    return std::max({f[0].norm(), f[1].norm(), f[2].norm()});
  }

  // Equilibrium, and f = -dW/dx by central differences (h = 1e-6 times the
  // size), both relative to the largest nodal force.
  void
  check_energy_gradient(const std::array<Point<3>, 3> &X,
                        const std::array<Point<3>, 3> &x)
  {
    TriangleResponse r;
    const auto       f     = forces(X, x, r);
    const double     scale = largest(f);
    ASSERT_GT(scale, 0);
    EXPECT_LE((f[0] + f[1] + f[2]).norm(), tight * scale);

    const double h   = 1e-6 * (X[1] - X[0]).norm();
    double       err = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int d = 0; d < 3; ++d)
        {
          auto xp = x, xm = x;
          xp[i][d] += h;
          xm[i][d] -= h;
          const double dW
            = (triangle_energy(X, xp) - triangle_energy(X, xm)) / (2 * h);
          err = std::max(err, std::abs(f[i][d] + dW));
        }
    std::printf("measured triangle: |sum f|/max|f| = %.3g, "
                "max |f + dW/dx|/max|f| = %.3g\n",
                (f[0] + f[1] + f[2]).norm() / scale,
                err / scale);
    EXPECT_LE(err, 1e-6 * scale);
  }

  // A general triangle, tilted out of every coordinate plane.
  const std::array<Point<3>, 3> tilted = {{Point<3>(0.1, -0.2, 0.3),
                                           Point<3>(1.3, 0.2, 0.5),
                                           Point<3>(0.4, 0.9, 1.1)}};

  // A triangle in the xy plane with X2 - X1 along x (rest frame = x, y).
  const std::array<Point<3>, 3> flat
    = {{Point<3>(0, 0, 0), Point<3>(2, 0, 0), Point<3>(0.5, 1.5, 0)}};

  // A taut in-plane state with shear: both principal stresses positive,
  // principal axes off the frame axes.
  Tensor<2, 3>
  taut_stretch()
  {
    Tensor<2, 3> A;
    A[0][0] = 1.10;
    A[0][1] = 0.04;
    A[1][0] = 0.02;
    A[1][1] = 1.06;
    A[2][2] = 1;
    return A;
  }

  // Cable of rest length 2 m, stretched to length_factor times that.
  double
  cable_tension(const double length_factor, Tensor<1, 2> &f1, Tensor<1, 2> &f2)
  {
    const double       L = 2;
    const Point<2>     x1(0.3, -0.2);
    const Tensor<1, 2> t({std::cos(0.4), std::sin(0.4)});
    return cable_forces(x1, x1 + length_factor * L * t, L, EA, f1, f2);
  }
} // namespace



// (a) cable: T = EA eps exactly, equilibrium, f = -dW/dx with
// W = EA (l - L)^2/(2 L).
TEST(MembranePatch, CableUniformStretch)
{
  const double       L = 2, eps = 0.05;
  const Point<2>     x1(0.3, -0.2);
  const Tensor<1, 2> t({std::cos(0.4), std::sin(0.4)});
  const Point<2>     x2 = x1 + (1 + eps) * L * t;
  Tensor<1, 2>       f1, f2;
  const double       T = cable_forces(x1, x2, L, EA, f1, f2);
  std::printf("measured cable tension %.15g N/m, expected EA eps = %.15g\n",
              T,
              EA * eps);
  EXPECT_NEAR(T, EA * eps, tight * EA * eps);
  EXPECT_LE((f1 + f2).norm(), tight * T);
  EXPECT_LE((f1 - T * t).norm(), tight * T); // pulls node 1 towards node 2

  auto W = [&](const Point<2> &a, const Point<2> &b) {
    const double l = (b - a).norm();
    return EA * (l - L) * (l - L) / (2 * L);
  };
  const double h   = 1e-6 * L;
  double       err = 0;
  for (unsigned int d = 0; d < 2; ++d)
    {
      Tensor<1, 2> e;
      e[d] = h;
      err
        = std::max(err,
                   std::abs(f1[d] + (W(x1 + e, x2) - W(x1 - e, x2)) / (2 * h)));
      err
        = std::max(err,
                   std::abs(f2[d] + (W(x1, x2 + e) - W(x1, x2 - e)) / (2 * h)));
    }
  std::printf("measured cable: max |f + dW/dx|/T = %.3g\n", err / T);
  EXPECT_LE(err, 1e-6 * T);
}

// (a) triangle, equibiaxial stretch lambda of a tilted triangle:
// S = EA/(1 - nu) (lambda^2 - 1)/2 and sigma = lambda^2 S/lambda^2 = S.
TEST(MembranePatch, TriangleEquibiaxialStretch)
{
  const double     lambda = 1.1;
  const auto       x      = deform(tilted, lambda * unit());
  TriangleResponse r;
  const auto       f = forces(tilted, x, r);
  const double     S = EA / (1 - nu) * (lambda * lambda - 1) / 2;
  std::printf("measured equibiaxial: sigma = {%.15g, %.15g, %.3g}, "
              "expected S = %.15g N/m\n",
              r.stress[0],
              r.stress[1],
              r.stress[2],
              S);
  EXPECT_NEAR(r.stress[0], S, tight * S);
  EXPECT_NEAR(r.stress[1], S, tight * S);
  EXPECT_NEAR(r.stress[2], 0, tight * S);
  EXPECT_NEAR(r.major_principal, S, tight * S);
  EXPECT_NEAR(r.minor_principal, S, tight * S);
  // Isotropic tension sigma pulls node i towards the opposite edge with
  // sigma |opposite edge|/2 (current geometry).
  for (unsigned int i = 0; i < 3; ++i)
    {
      const double edge = (x[(i + 2) % 3] - x[(i + 1) % 3]).norm();
      EXPECT_NEAR(f[i].norm(), S * edge / 2, tight * S * edge);
    }
  check_energy_gradient(tilted, x);
}

// (a) triangle, uniaxial stretch with the lateral size held (a state known
// without solving for the lateral contraction): S11 = EA/(1 - nu^2) E11,
// S22 = nu S11; Cauchy sigma11 = lambda S11, sigma22 = S22/lambda.
TEST(MembranePatch, TriangleUniaxialStretchLateralHeld)
{
  const double lambda = 1.05;
  Tensor<2, 3> A      = unit();
  A[0][0]             = lambda;
  const auto       x  = deform(flat, A);
  TriangleResponse r;
  forces(flat, x, r);
  const double S11 = EA / (1 - nu * nu) * (lambda * lambda - 1) / 2;
  const double S22 = nu * S11;
  std::printf("measured uniaxial (lateral held): sigma = {%.15g, %.15g, "
              "%.3g}, expected {%.15g, %.15g, 0} N/m\n",
              r.stress[0],
              r.stress[1],
              r.stress[2],
              lambda * S11,
              S22 / lambda);
  EXPECT_NEAR(r.stress[0], lambda * S11, tight * S11);
  EXPECT_NEAR(r.stress[1], S22 / lambda, tight * S11);
  EXPECT_NEAR(r.stress[2], 0, tight * S11);
  check_energy_gradient(flat, x);
}

// (a) a general taut state with shear on the tilted triangle, rotated and
// moved: the forces are still minus the energy gradient.
TEST(MembranePatch, TriangleGeneralTautStateForcesAreEnergyGradient)
{
  const auto x
    = deform(tilted,
             rotation(Tensor<1, 3>({1., 2., 3.}), 0.7) * taut_stretch(),
             Tensor<1, 3>({0.5, -1., 2.}));
  TriangleResponse r;
  forces(tilted, x, r);
  ASSERT_GT(r.minor_principal, 0); // taut: the cut-off is inactive
  check_energy_gradient(tilted, x);
}

// (b) cable: a quarter turn in the plane keeps T and rotates the forces.
TEST(MembranePatch, CableRigidRotation)
{
  Tensor<1, 2>   f1, f2, g1, g2;
  const double   L = 2;
  const Point<2> x1(0.3, -0.2), x2(2.4, 0.5);
  const double   T       = cable_forces(x1, x2, L, EA, f1, f2);
  auto           quarter = [](const Tensor<1, 2> &v) {
    return Tensor<1, 2>({-v[1], v[0]});
  };
  const double Tr
    = cable_forces(Point<2>(quarter(x1)), Point<2>(quarter(x2)), L, EA, g1, g2);
  std::printf("measured cable quarter turn: T = %.15g, rotated %.15g N/m\n",
              T,
              Tr);
  ASSERT_GT(T, 0);
  EXPECT_NEAR(Tr, T, tight * T);
  EXPECT_LE((g1 - quarter(f1)).norm(), tight * T);
  EXPECT_LE((g2 - quarter(f2)).norm(), tight * T);
}

// (b) triangle: quarter turns about x (out of the plane) and z (in the
// plane) and a general rotation keep the co-rotated stress and rotate the
// forces.
TEST(MembranePatch, TriangleRigidRotation)
{
  const auto         x = deform(flat, taut_stretch());
  TriangleResponse   r;
  const auto         f       = forces(flat, x, r);
  const double       scale   = largest(f);
  const Tensor<2, 3> turns[] = {quarter_turn(0),
                                quarter_turn(2),
                                rotation(Tensor<1, 3>({1., -2., 0.5}), 2.1)};
  const char        *names[]
    = {"quarter turn about x", "quarter turn about z", "general rotation"};
  for (unsigned int k = 0; k < 3; ++k)
    {
      const Tensor<2, 3>     &R = turns[k];
      std::array<Point<3>, 3> y;
      for (unsigned int i = 0; i < 3; ++i)
        y[i] = Point<3>(R * x[i]);
      TriangleResponse rr;
      const auto       g  = forces(flat, y, rr);
      double           df = 0;
      for (unsigned int i = 0; i < 3; ++i)
        df = std::max(df, (g[i] - R * f[i]).norm());
      std::printf("measured %s: principal {%.15g, %.15g} -> {%.15g, %.15g} "
                  "N/m, max |f' - R f|/max|f| = %.3g\n",
                  names[k],
                  r.major_principal,
                  r.minor_principal,
                  rr.major_principal,
                  rr.minor_principal,
                  df / scale);
      EXPECT_NEAR(rr.major_principal,
                  r.major_principal,
                  tight * r.major_principal);
      EXPECT_NEAR(rr.minor_principal,
                  r.minor_principal,
                  tight * r.major_principal);
      for (unsigned int c = 0; c < 3; ++c)
        EXPECT_NEAR(rr.stress[c], r.stress[c], tight * r.major_principal);
      EXPECT_LE(df, tight * scale);
    }
}

// (c) compression carries nothing: zero stress and exactly zero force.
TEST(MembranePatch, CompressionCarriesNothing)
{
  Tensor<1, 2> f1, f2;
  const double T = cable_tension(0.9, f1, f2);
  EXPECT_EQ(T, 0);
  EXPECT_EQ(f1.norm(), 0);
  EXPECT_EQ(f2.norm(), 0);

  // Shrunk in both directions (with some shear), and shortened with the
  // lateral size held (then S22 = nu S11 < 0 too).
  Tensor<2, 3> shrink  = 0.9 * unit();
  shrink[0][1]         = 0.02;
  Tensor<2, 3> shorten = unit();
  shorten[0][0]        = 0.9;
  const auto &X        = flat;
  for (const auto &A : {shrink, shorten})
    {
      TriangleResponse r;
      const auto       f = forces(X, deform(X, A), r);
      std::printf("measured compressed triangle: principal {%.3g, %.3g} N/m, "
                  "max|f| = %.3g N\n",
                  r.major_principal,
                  r.minor_principal,
                  largest(f));
      for (unsigned int c = 0; c < 3; ++c)
        EXPECT_EQ(r.stress[c], 0);
      EXPECT_EQ(largest(f), 0);
    }
}

// Branches of the cut-off and Eq. (9).
TEST(MembranePatch, CutoffBranches)
{
  const PlaneStress taut = {{3., 1., 1.}}; // principal 2 +- sqrt(2) > 0
  const auto        p    = principal_stresses(taut);
  EXPECT_NEAR(p.first, 2 + std::sqrt(2.), tight * 4);
  EXPECT_NEAR(p.second, 2 - std::sqrt(2.), tight * 4);
  EXPECT_EQ(compression_cutoff(taut), taut);

  const PlaneStress zero  = {{0., 0., 0.}};
  const PlaneStress slack = {{-3., -1., 1.}}; // -2 +- sqrt(2) < 0
  EXPECT_EQ(compression_cutoff(slack), zero);
  // Isotropic (no Mohr radius), the boundary sII = 0, and zero.
  EXPECT_EQ(compression_cutoff(PlaneStress{{-1., -1., 0.}}), zero);
  EXPECT_EQ(compression_cutoff(PlaneStress{{1., 1., 0.}}),
            (PlaneStress{{1., 1., 0.}}));
  EXPECT_EQ(compression_cutoff(PlaneStress{{2., 0., 0.}}),
            (PlaneStress{{2., 0., 0.}}));
  EXPECT_EQ(compression_cutoff(zero), zero);
}

// (d) Eq. (10) on a wrinkled stress with shear, s = {3, -1, 2} kN/m:
// sI,II = 1 +- 2 sqrt(2), major direction at 22.5 degrees; by hand,
// s' = sI n n^T = {1.5 + 1.25 sqrt(2), -0.5 + 0.75 sqrt(2), 1 + sqrt(2)/4}.
TEST(MembranePatch, CutoffEquation10ByHand)
{
  const double      k = 1e3, r2 = std::sqrt(2.);
  const PlaneStress s = {{3 * k, -1 * k, 2 * k}};
  const PlaneStress c = compression_cutoff(s);
  const PlaneStress hand
    = {{(1.5 + 1.25 * r2) * k, (-0.5 + 0.75 * r2) * k, (1 + r2 / 4) * k}};
  const auto ps = principal_stresses(s), pc = principal_stresses(c);
  std::printf("measured Eq. (10): {%.15g, %.15g, %.15g}, by hand "
              "{%.15g, %.15g, %.15g} N/m; principal {%.15g, %.3g}, "
              "predictor major %.15g\n",
              c[0],
              c[1],
              c[2],
              hand[0],
              hand[1],
              hand[2],
              pc.first,
              pc.second,
              ps.first);
  for (unsigned int i = 0; i < 3; ++i)
    EXPECT_NEAR(c[i], hand[i], tight * k);
  EXPECT_NEAR(ps.first, (1 + 2 * r2) * k, tight * k);
  EXPECT_NEAR(pc.first, ps.first, tight * k);
  EXPECT_NEAR(pc.second, 0, tight * k);

  // Same major direction n = (cos 22.5, sin 22.5): s' n = sI n, s' m = 0
  // for m normal to n.
  const double th = M_PI / 8, n0 = std::cos(th), n1 = std::sin(th);
  EXPECT_NEAR(0.5 * std::atan2(2 * s[2], s[0] - s[1]), th, tight);
  EXPECT_NEAR(0.5 * std::atan2(2 * c[2], c[0] - c[1]), th, tight);
  EXPECT_NEAR(c[0] * n0 + c[2] * n1, ps.first * n0, tight * k);
  EXPECT_NEAR(c[2] * n0 + c[1] * n1, ps.first * n1, tight * k);
  EXPECT_NEAR(-c[0] * n1 + c[2] * n0, 0, tight * k);
  EXPECT_NEAR(-c[2] * n1 + c[1] * n0, 0, tight * k);
  // The corrected stress is taut (to round-off): a second cut-off keeps it.
  const PlaneStress cc = compression_cutoff(c);
  for (unsigned int i = 0; i < 3; ++i)
    EXPECT_NEAR(cc[i], c[i], tight * k);
}

// (d) triangle in a wrinkled state: stretch x, compress y strongly, shear
// (F = [[1.2, 0.3], [0, 0.7]] on the right rest triangle, Dm = I,
// A0 = 1/2), then a general rigid motion. Expected by hand: S from F,
// Eq. (10), sigma = F S' F^T/det F, forces [f2, f3] = -A0 R F S'.
TEST(MembranePatch, TriangleWrinkledStateFollowsEquation10)
{
  const std::array<Point<3>, 3> X
    = {{Point<3>(0, 0, 0), Point<3>(1, 0, 0), Point<3>(0, 1, 0)}};
  const double F[2][2] = {{1.2, 0.3}, {0., 0.7}};
  Tensor<2, 3> A;
  A[0][0]              = F[0][0];
  A[0][1]              = F[0][1];
  A[1][1]              = F[1][1];
  A[2][2]              = 1;
  const Tensor<2, 3> R = rotation(Tensor<1, 3>({0.3, 1., -0.4}), 1.3);
  const auto         x = deform(X, R * A, Tensor<1, 3>({1., 2., 3.}));
  TriangleResponse   r;
  const auto         f = forces(X, x, r);

  // Predictor S (C = F^T F), then Eq. (10) by hand.
  const double C11 = F[0][0] * F[0][0], C12 = F[0][0] * F[0][1],
               C22      = F[0][1] * F[0][1] + F[1][1] * F[1][1];
  const PlaneStress S   = svk((C11 - 1) / 2, (C22 - 1) / 2, C12 / 2);
  const double      sm  = std::hypot((S[0] - S[1]) / 2, S[2]);
  const double      sI  = (S[0] + S[1]) / 2 + sm;
  const double      sII = (S[0] + S[1]) / 2 - sm;
  ASSERT_LT(sII, 0);
  ASSERT_GT(sI, 0);
  ASSERT_GT(std::abs(S[2]), 0.1 * sI); // principal axes off the frame axes
  const PlaneStress Sc = {{sI * (1 - (sI - S[0]) / (2 * sm)),
                           sI * (1 - (sI - S[1]) / (2 * sm)),
                           sI * S[2] / (2 * sm)}};

  // sigma = F Sc F^T/J in the current frame (x, y before the rotation,
  // since F maps e1 onto x and det F > 0).
  const double J        = F[0][0] * F[1][1];
  const double Sm[2][2] = {{Sc[0], Sc[2]}, {Sc[2], Sc[1]}};
  double       sigma[2][2];
  for (unsigned int a = 0; a < 2; ++a)
    for (unsigned int b = 0; b < 2; ++b)
      {
        sigma[a][b] = 0;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            sigma[a][b] += F[a][i] * Sm[i][j] * F[b][j] / J;
      }
  // Major direction n of S, pushed forward: F n, sigma_I = sI |F n|^2/J.
  const double th = 0.5 * std::atan2(2 * S[2], S[0] - S[1]);
  const double Fn[2]
    = {F[0][0] * std::cos(th) + F[0][1] * std::sin(th), F[1][1] * std::sin(th)};
  const double major = sI * (Fn[0] * Fn[0] + Fn[1] * Fn[1]) / J;

  std::printf("measured wrinkled triangle: predictor S principal {%.6g, "
              "%.6g} N/m, sigma = {%.15g, %.15g, %.15g}, expected {%.15g, "
              "%.15g, %.15g} N/m, principal {%.15g, %.3g}, expected "
              "{%.15g, 0}\n",
              sI,
              sII,
              r.stress[0],
              r.stress[1],
              r.stress[2],
              sigma[0][0],
              sigma[1][1],
              sigma[0][1],
              r.major_principal,
              r.minor_principal,
              major);
  EXPECT_NEAR(r.stress[0], sigma[0][0], tight * sI);
  EXPECT_NEAR(r.stress[1], sigma[1][1], tight * sI);
  EXPECT_NEAR(r.stress[2], sigma[0][1], tight * sI);
  EXPECT_NEAR(r.major_principal, major, tight * sI);
  EXPECT_NEAR(r.minor_principal, 0, tight * sI);
  // Major direction of sigma = direction of F n (up to sign).
  const double ths
    = 0.5 * std::atan2(2 * r.stress[2], r.stress[0] - r.stress[1]);
  const double norm = std::hypot(Fn[0], Fn[1]);
  EXPECT_NEAR(std::abs(std::cos(ths) * Fn[0] + std::sin(ths) * Fn[1]) / norm,
              1,
              tight);

  // Forces: [f2, f3] = -A0 R F Sc (Dm = I), f1 = -(f2 + f3).
  double scale = 0;
  for (unsigned int j = 0; j < 2; ++j)
    {
      Tensor<1, 3> p;
      for (unsigned int a = 0; a < 2; ++a)
        for (unsigned int i = 0; i < 2; ++i)
          p[a] += F[a][i] * Sm[i][j];
      const Tensor<1, 3> expected = -0.5 * (R * p);
      scale                       = std::max(scale, expected.norm());
      EXPECT_LE((f[j + 1] - expected).norm(), tight * expected.norm());
    }
  EXPECT_LE((f[0] + f[1] + f[2]).norm(), tight * scale);
}

// (e) compress-then-stretch cycle, lengths 1.0 -> 0.8 -> 0.99 -> 1.0 ->
// 1.01 times rest: no tension up to the rest length, exactly EA 0.01
// (cable) and the equibiaxial value (triangle) at 1.01: the slack is never
// remembered.
TEST(MembranePatch, CompressThenStretchCycle)
{
  const double factors[] = {1.0, 0.8, 0.99, 1.0, 1.01};
  for (const double k : factors)
    {
      Tensor<1, 2>     f1, f2;
      const double     T = cable_tension(k, f1, f2);
      TriangleResponse r;
      const auto       f = forces(tilted, deform(tilted, k * unit()), r);
      const double     S = EA / (1 - nu) * (k * k - 1) / 2;
      std::printf("measured cycle %.2f: cable T = %.15g N/m, triangle "
                  "principal {%.15g, %.15g} N/m, max|f| = %.3g N\n",
                  k,
                  T,
                  r.major_principal,
                  r.minor_principal,
                  largest(f));
      if (k <= 1)
        {
          EXPECT_EQ(T, 0);
          EXPECT_EQ(f1.norm(), 0);
          EXPECT_NEAR(r.major_principal, 0, tight * EA);
          EXPECT_NEAR(r.minor_principal, 0, tight * EA);
          EXPECT_LE(largest(f), tight * EA);
        }
      else
        {
          EXPECT_NEAR(T, EA * 0.01, tight * EA * 0.01);
          EXPECT_NEAR(r.major_principal, S, tight * S);
          EXPECT_NEAR(r.minor_principal, S, tight * S);
        }
    }
}

// A triangle crushed onto a line (node 3 onto node 1) while stretched
// along it has no current frame: its stress is reported as zero, but its
// forces stay finite, in equilibrium, and keep the line taut.
TEST(MembranePatch, CollapsedTriangleKeepsForces)
{
  const std::array<Point<3>, 3> x = {{flat[0], Point<3>(2.4, 0, 0), flat[0]}};
  TriangleResponse              r;
  const auto                    f = forces(flat, x, r);
  std::printf("measured collapsed triangle: stress {%.3g, %.3g, %.3g} N/m, "
              "f2 = (%.6g, %.6g, %.6g) N\n",
              r.stress[0],
              r.stress[1],
              r.stress[2],
              f[1][0],
              f[1][1],
              f[1][2]);
  for (unsigned int c = 0; c < 3; ++c)
    EXPECT_EQ(r.stress[c], 0);
  EXPECT_TRUE(std::isfinite(largest(f)));
  EXPECT_LE((f[0] + f[1] + f[2]).norm(), tight * largest(f));
  EXPECT_LT(f[1][0], 0); // node 2 pulled back towards node 1
}

// Rest geometry: A0, and Dm reproduces the rest edge lengths and angle.
TEST(MembranePatch, TriangleReference)
{
  const auto ref = make_triangle_reference(tilted[0], tilted[1], tilted[2]);
  const Tensor<1, 3> a = tilted[1] - tilted[0], b = tilted[2] - tilted[0];
  const double       A0 = cross_product_3d(a, b).norm() / 2;
  const Tensor<2, 2> Dm = invert(ref.dm_inverse);
  EXPECT_NEAR(ref.area, A0, tight * A0);
  EXPECT_NEAR(determinant(Dm), 2 * A0, tight * A0);
  EXPECT_NEAR(Dm[0][0] * Dm[0][0] + Dm[1][0] * Dm[1][0],
              a * a,
              tight * (a * a));
  EXPECT_NEAR(Dm[0][1] * Dm[0][1] + Dm[1][1] * Dm[1][1],
              b * b,
              tight * (b * b));
  EXPECT_NEAR(Dm[0][0] * Dm[0][1] + Dm[1][0] * Dm[1][1],
              a * b,
              tight * (a * a));
}

// (f) bad input throws.
TEST(MembranePatch, BadInputThrows)
{
  const Point<3> O(0, 0, 0), P(1, 0, 0), Q(2, 0, 0);
  EXPECT_THROW(make_triangle_reference(O, P, Q), ExceptionBase); // collinear
  EXPECT_THROW(make_triangle_reference(O, O, P), ExceptionBase); // coincident
  EXPECT_THROW(make_triangle_reference(O, O, O), ExceptionBase);
  // A sliver of area 5e-16 m^2 against a 1 m edge (limit 1e-14 m^2).
  EXPECT_THROW(make_triangle_reference(O, P, Point<3>(0.5, 1e-15, 0)),
               ExceptionBase);
  EXPECT_NO_THROW(make_triangle_reference(O, P, Point<3>(0.5, 1e-12, 0)));

  const auto ref = make_triangle_reference(flat[0], flat[1], flat[2]);
  std::array<Tensor<1, 3>, 3> f;
  for (const double bad : {0., -1., std::nan(""), HUGE_VAL})
    EXPECT_THROW(triangle_forces(ref, flat[0], flat[1], flat[2], bad, nu, f),
                 ExceptionBase);
  for (const double bad : {-1., 1., 1.5, std::nan("")})
    EXPECT_THROW(triangle_forces(ref, flat[0], flat[1], flat[2], EA, bad, f),
                 ExceptionBase);
  EXPECT_THROW(
    triangle_forces(TriangleReference(), flat[0], flat[1], flat[2], EA, nu, f),
    ExceptionBase);

  Tensor<1, 2>   f1, f2;
  const Point<2> a(0, 0), b(1, 0);
  for (const double bad : {0., -1., std::nan(""), HUGE_VAL})
    {
      EXPECT_THROW(cable_forces(a, b, bad, EA, f1, f2), ExceptionBase);
      EXPECT_THROW(cable_forces(a, b, 1., bad, f1, f2), ExceptionBase);
    }
  try
    {
      make_triangle_reference(O, P, Q);
    }
  catch (const ExceptionBase &e)
    {
      std::printf("measured message: %s\n", e.what());
    }
}
