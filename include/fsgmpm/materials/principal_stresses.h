#ifndef fsgmpm_materials_principal_stresses_h
#define fsgmpm_materials_principal_stresses_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>
#include <utility>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * The principal values of a symmetric 3 x 3 tensor in descending order,
   * each with its unit principal direction: what deal.II's eigenvectors()
   * returns. A plane-strain tensor (s_xz = s_yz = 0 exactly, as the stress
   * of every 2D point is: the plane-strain rotation and strain rate have
   * no out-of-plane shear) splits into its in-plane 2 x 2 block and s_zz
   * with e_z. The block is solved in closed form, with one square root for
   * the values and one for the direction, instead of deal.II's QL
   * iteration with implicit shifts (which took a third of a 2D soil run in
   * the Mohr-Coulomb return mapping). Any other tensor goes to
   * eigenvectors(). The two agree to round-off (unit test
   * MohrCoulomb.PlaneStrainPrincipalStressesAreDealIIs).
   */
  inline std::array<std::pair<double, Tensor<1, 3>>, 3>
  principal_stresses(const SymmetricTensor<2, 3> &s)
  {
    if (s[0][2] != 0 || s[1][2] != 0)
      return eigenvectors(s);
    // In the plane: mean m, half difference h, shear b; the values m +- r
    // with r = sqrt(h^2 + b^2).
    const double m = 0.5 * (s[0][0] + s[1][1]);
    const double h = 0.5 * (s[0][0] - s[1][1]);
    const double b = s[0][1];
    const double r = std::sqrt(h * h + b * b);
    // The direction of m + r from whichever row of (s - (m + r) I) is the
    // larger (no cancellation): (r + h, b) if h >= 0, else (b, r - h).
    double x = 1, y = 0;
    if (r > 0)
      {
        x                  = h >= 0 ? r + h : b;
        y                  = h >= 0 ? b : r - h;
        const double scale = 1. / std::sqrt(x * x + y * y);
        x *= scale;
        y *= scale;
      }
    std::array<std::pair<double, Tensor<1, 3>>, 3> e;
    e[0].first     = m + r;
    e[0].second[0] = x;
    e[0].second[1] = y;
    e[1].first     = m - r;
    e[1].second[0] = -y;
    e[1].second[1] = x;
    e[2].first     = s[2][2];
    e[2].second[2] = 1;
    // Descending: s_zz's place among the two in-plane values.
    if (e[2].first > e[1].first)
      std::swap(e[1], e[2]);
    if (e[1].first > e[0].first)
      std::swap(e[0], e[1]);
    return e;
  }
} // namespace fsgmpm

#endif
