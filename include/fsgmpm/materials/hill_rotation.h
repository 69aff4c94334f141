#ifndef fsgmpm_materials_hill_rotation_h
#define fsgmpm_materials_hill_rotation_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * The rotational part of the Hill stress rate, paper Eq. (6):
   * sigma <- R sigma R^T with the exactly orthogonal Hughes-Winget rotation
   * R = (I - dt W/2)^{-1} (I + dt W/2). A rigid rotation therefore leaves the
   * principal stresses unchanged to round-off, however large dt W is.
   *
   * Evaluated in closed form (the Cayley transform of the skew matrix
   * A = dt W/2 with axial vector a, A^2 = a a^T - |a|^2 I):
   * R = I + 2 (A + A^2) / (1 + |a|^2), no inverse needed.
   */
  inline Tensor<2, 3>
  incremental_rotation(const Tensor<2, 3> &spin, const double dt)
  {
    const double h    = 0.5 * dt;
    const double a[3] = {h * spin[2][1], h * spin[0][2], h * spin[1][0]};
    const double a2   = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    const double f    = 2. / (1. + a2);
    Tensor<2, 3> R;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        R[i][j] = (i == j ? 1. : 0.)
                  + f * (h * spin[i][j] + a[i] * a[j] - (i == j ? a2 : 0.));
    return R;
  }

  /// sigma <- R sigma R^T for an orthogonal R.
  inline SymmetricTensor<2, 3>
  rotate_stress(const SymmetricTensor<2, 3> &sigma, const Tensor<2, 3> &R)
  {
    return symmetrize(R * Tensor<2, 3>(sigma) * transpose(R));
  }
} // namespace fsgmpm

#endif
