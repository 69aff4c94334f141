#include <deal.II/base/exceptions.h>

#include <fsgmpm/membrane/membrane_mechanics.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace fsgmpm
{
  namespace MembraneMechanics
  {
    namespace
    {
      std::string
      str(const double x)
      {
        std::ostringstream s;
        s << x;
        return s.str();
      }

      void
      check_stiffness(const double EA)
      {
        AssertThrow(std::isfinite(EA) && EA > 0,
                    ExcMessage("Membrane: the stiffness EA (Young's modulus "
                               "times thickness or area) must be positive "
                               "and finite; got "
                               + str(EA) + "."));
      }

      void
      check_poisson_ratio(const double nu)
      {
        AssertThrow(nu > -1 && nu < 1,
                    ExcMessage("Membrane: Poisson's ratio must lie in "
                               "(-1, 1), the range where the plane-stress "
                               "stiffness is positive definite; got "
                               + str(nu) + "."));
      }
    } // namespace



    double
    cable_forces(const Point<2> &x1,
                 const Point<2> &x2,
                 const double    rest_length,
                 const double    EA,
                 Tensor<1, 2>   &f1,
                 Tensor<1, 2>   &f2)
    {
      AssertThrow(std::isfinite(rest_length) && rest_length > 0,
                  ExcMessage("Membrane: a cable's rest length must be "
                             "positive and finite; got "
                             + str(rest_length) + "."));
      check_stiffness(EA);

      const Tensor<1, 2> d = x2 - x1;
      const double       l = d.norm();
      // Tension only, from the current length alone: a slack cable carries
      // nothing, whatever it went through before.
      const double T
        = l > rest_length ? EA * (l - rest_length) / rest_length : 0.;
      // l > rest_length > 0 whenever T > 0, so t = d/l is defined.
      f1 = T > 0 ? (T / l) * d : Tensor<1, 2>();
      f2 = -f1;
      return T;
    }



    std::pair<double, double>
    principal_stresses(const PlaneStress &s)
    {
      // Eq. (9): centre and radius of Mohr's circle.
      const double mean = (s[0] + s[1]) / 2;
      const double sm   = std::hypot((s[0] - s[1]) / 2, s[2]);
      return {mean + sm, mean - sm};
    }



    PlaneStress
    compression_cutoff(const PlaneStress &s)
    {
      const double      mean = (s[0] + s[1]) / 2;
      const double      sm   = std::hypot((s[0] - s[1]) / 2, s[2]);
      const double      sI = mean + sm, sII = mean - sm;
      const PlaneStress zero = {{0., 0., 0.}};

      // An (almost) isotropic stress has no principal direction; its sign
      // decides alone (both principal values then share it).
      if (sm <= 1e-14 * std::abs(sI) + std::numeric_limits<double>::min())
        return mean >= 0 ? s : zero;
      if (sII >= 0) // taut in every direction
        return s;
      if (sI <= 0) // slack in every direction: the membrane wrinkles freely
        return zero;

      // Wrinkled (sII < 0 < sI), Eq. (10): keep sI along its direction and
      // drop sII. Here 2 sm = sI - sII > sI > 0.
      const double r = sI / (2 * sm);
      return {{sI - r * (sI - s[0]), sI - r * (sI - s[1]), r * s[2]}};
    }



    TriangleReference
    make_triangle_reference(const Point<3> &X1,
                            const Point<3> &X2,
                            const Point<3> &X3)
    {
      const Tensor<1, 3> a = X2 - X1, b = X3 - X1;
      const Tensor<1, 3> n    = cross_product_3d(a, b);
      const double       area = n.norm() / 2;
      const double       longest
        = std::max({a.norm_square(), b.norm_square(), (X3 - X2).norm_square()});
      // The message is only built if the check fails.
      auto degenerate = [&]() {
        std::ostringstream s;
        s << "Membrane: degenerate triangle with nodes (" << X1 << "), (" << X2
          << "), (" << X3 << "): rest area " << area
          << " m^2 is (nearly) zero against its longest edge squared, "
          << longest << " m^2; the nodes are collinear or coincide.";
        return s.str();
      };
      AssertThrow(std::isfinite(area) && area > 1e-14 * longest,
                  ExcMessage(degenerate()));

      // Orthonormal frame of the rest plane, e1 along X2 - X1; Dm is then
      // upper triangular with det Dm = 2 A0 > 0.
      const double       la = a.norm();
      const Tensor<1, 3> e1 = a / la;
      const Tensor<1, 3> e2 = cross_product_3d(n / n.norm(), e1);
      Tensor<2, 2>       dm;
      dm[0][0] = la;
      dm[0][1] = e1 * b;
      dm[1][0] = 0;
      dm[1][1] = e2 * b;

      TriangleReference ref;
      ref.dm_inverse = invert(dm);
      ref.area       = area;
      return ref;
    }



    PlaneStress
    cut_off_svk_stress(const Tensor<1, 3> &g0,
                       const Tensor<1, 3> &g1,
                       const double        EA,
                       const double        nu)
    {
      // Green-Lagrange strain E = (F^T F - I)/2 and plane-stress Saint
      // Venant-Kirchhoff S; neither sees a rigid rotation.
      const double E11 = (g0 * g0 - 1) / 2, E22 = (g1 * g1 - 1) / 2,
                   E12 = (g0 * g1) / 2;
      const double c   = EA / (1 - nu * nu);
      // Cut-off on S, Eqs. (9)-(10): S and E share the rest frame, and
      // principal values and directions of S do not depend on that frame.
      return compression_cutoff(
        {{c * (E11 + nu * E22), c * (nu * E11 + E22), c * (1 - nu) * E12}});
    }



    TriangleResponse
    triangle_forces(const TriangleReference     &ref,
                    const Point<3>              &x1,
                    const Point<3>              &x2,
                    const Point<3>              &x3,
                    const double                 EA,
                    const double                 nu,
                    std::array<Tensor<1, 3>, 3> &f)
    {
      check_stiffness(EA);
      check_poisson_ratio(nu);
      AssertThrow(ref.area > 0,
                  ExcMessage("Membrane: the triangle reference has no area; "
                             "make it with make_triangle_reference()."));

      // F = Ds Dm^{-1} (3x2), stored as its two columns g0, g1: the images
      // of the rest-frame axes.
      const Tensor<2, 2> &Di = ref.dm_inverse;
      const Tensor<1, 3>  d1 = x2 - x1, d2 = x3 - x1;
      const Tensor<1, 3>  g0 = Di[0][0] * d1 + Di[1][0] * d2;
      const Tensor<1, 3>  g1 = Di[0][1] * d1 + Di[1][1] * d2;

      const PlaneStress S = cut_off_svk_stress(g0, g1, EA, nu);

      // First Piola-Kirchhoff P = F S (3x2) and [f2, f3] = -A0 P Dm^{-T}:
      // while taut, exactly -dW/dx with W = A0 E:S/2.
      const Tensor<1, 3> p0 = S[0] * g0 + S[2] * g1;
      const Tensor<1, 3> p1 = S[2] * g0 + S[1] * g1;
      f[1]                  = -ref.area * (Di[0][0] * p0 + Di[0][1] * p1);
      f[2]                  = -ref.area * (Di[1][0] * p0 + Di[1][1] * p1);
      f[0]                  = -(f[1] + f[2]);

      // Cauchy membrane stress sigma = F S F^T / J (J = current/rest area)
      // in the current frame e1 = d1/|d1|, e2 = n x e1: sigma_ab =
      // (F^T e_a) . S (F^T e_b) / J.
      TriangleResponse   response;
      const Tensor<1, 3> n = cross_product_3d(g0, g1); // parallel to d1 x d2
      const double       J = n.norm();
      if (J > 1e-12)
        {
          const Tensor<1, 3> e1 = d1 / d1.norm();
          const Tensor<1, 3> e2 = cross_product_3d(n / J, e1);
          const double       u0 = g0 * e1, u1 = g1 * e1; // F^T e1
          const double       v0 = g0 * e2, v1 = g1 * e2; // F^T e2
          response.stress
            = {{(S[0] * u0 * u0 + 2 * S[2] * u0 * u1 + S[1] * u1 * u1) / J,
                (S[0] * v0 * v0 + 2 * S[2] * v0 * v1 + S[1] * v1 * v1) / J,
                (S[0] * u0 * v0 + S[2] * (u0 * v1 + u1 * v0) + S[1] * u1 * v1)
                  / J}};
        }
      else
        response.stress = {{0., 0., 0.}};
      const auto principal     = principal_stresses(response.stress);
      response.major_principal = principal.first;
      response.minor_principal = principal.second;
      return response;
    }
  } // namespace MembraneMechanics
} // namespace fsgmpm
