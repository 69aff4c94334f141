#ifndef fsgmpm_membrane_membrane_mechanics_h
#define fsgmpm_membrane_membrane_mechanics_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <utility>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * Element mechanics of the membrane (Hamad et al. 2017): pure, stateless
   * functions. The strain always comes from the current node positions
   * against the rest geometry, so an element that went slack and came back
   * carries exactly the tension of its current length; nothing is
   * remembered between calls.
   *
   * Forces are the forces ON the nodes (-dW/dx), tension positive.
   */
  namespace MembraneMechanics
  {
    /**
     * 2D cable (plane strain, per metre out of plane):
     * T = EA max(0, (l - L)/L) with the engineering strain, tension only.
     * Returns T; f1 and f2 are assigned the forces on nodes 1 and 2,
     * f1 = +T t, f2 = -T t with t = (x2 - x1)/l: tension pulls the nodes
     * together. Throws unless rest_length > 0 and EA > 0 are finite.
     */
    double
    cable_forces(const Point<2> &x1,
                 const Point<2> &x2,
                 const double    rest_length,
                 const double    EA,
                 Tensor<1, 2>   &f1,
                 Tensor<1, 2>   &f2);

    /// In-plane membrane stress (N/m) in a local orthonormal frame:
    /// {s11, s22, s12}.
    using PlaneStress = std::array<double, 3>;

    /**
     * Principal stresses {sI, sII}, sI >= sII, paper Eq. (9):
     * sI,II = (s11 + s22)/2 +- sm, sm = sqrt(((s11 - s22)/2)^2 + s12^2).
     */
    std::pair<double, double>
    principal_stresses(const PlaneStress &s);

    /**
     * Compression cut-off, paper Eqs. (9)-(10). Both principal stresses
     * >= 0: unchanged; sI <= 0: zero; sII < 0 < sI: Eq. (10),
     * s11 = sI (1 - (sI - s11)/(2 sm)), s22 = sI (1 - (sI - s22)/(2 sm)),
     * s12 = sI s12/(2 sm), which is exactly the uniaxial stress sI n n^T
     * along the major principal direction n.
     */
    PlaneStress
    compression_cutoff(const PlaneStress &s);

    /**
     * Second Piola-Kirchhoff membrane stress {S11, S22, S12} (N/m) in an
     * orthonormal frame of the rest surface, from the images g0 = F t0,
     * g1 = F t1 of that frame: Green-Lagrange E = (F^T F - I)/2,
     * plane-stress Saint Venant-Kirchhoff with EA = E thickness and nu,
     * then the compression cut-off Eqs. (9)-(10). Shared by the
     * hand-written triangle and MembraneFE.
     */
    PlaneStress
    cut_off_svk_stress(const Tensor<1, 3> &g0,
                       const Tensor<1, 3> &g1,
                       const double        EA,
                       const double        nu);

    /**
     * Rest geometry of a 3-node triangle: Dm^{-1} with Dm = [X2 - X1,
     * X3 - X1] in an orthonormal frame of the rest plane (e1 along X2 - X1),
     * and the rest area A0.
     */
    struct TriangleReference
    {
      Tensor<2, 2> dm_inverse;
      double       area = 0;
    };

    /// Throws on a degenerate triangle (area <= 1e-14 longest edge^2).
    TriangleReference
    make_triangle_reference(const Point<3> &X1,
                            const Point<3> &X2,
                            const Point<3> &X3);

    /// What a triangle reports.
    struct TriangleResponse
    {
      /// Co-rotated Cauchy membrane stress (N/m) after the cut-off, in the
      /// current element frame (e1 along x2 - x1, e2 in the current plane).
      /// Zero if the current triangle has collapsed (area ratio <= 1e-12),
      /// where it is undefined; the forces stay valid.
      PlaneStress stress;
      /// Principal values of that stress.
      double major_principal, minor_principal;
    };

    /**
     * 3-node triangle, total Lagrangian and stateless: F = Ds Dm^{-1}
     * (3x2), Green-Lagrange E = (F^T F - I)/2, plane-stress Saint
     * Venant-Kirchhoff S = EA/(1 - nu^2) [[1, nu, 0], [nu, 1, 0],
     * [0, 0, (1 - nu)/2]] {E11, E22, 2 E12} (EA = E thickness, N/m), the
     * compression cut-off Eqs. (9)-(10) applied to S, and the nodal forces
     * [f2, f3] = -A0 F S Dm^{-T}, f1 = -(f2 + f3). The forces are assigned
     * to @p f (not added). Throws unless EA > 0 is finite and
     * -1 < nu < 1 (the plane-stress range).
     */
    TriangleResponse
    triangle_forces(const TriangleReference     &ref,
                    const Point<3>              &x1,
                    const Point<3>              &x2,
                    const Point<3>              &x3,
                    const double                 EA,
                    const double                 nu,
                    std::array<Tensor<1, 3>, 3> &f);
  } // namespace MembraneMechanics
} // namespace fsgmpm

#endif
