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
   */
  inline Tensor<2, 3>
  incremental_rotation(const Tensor<2, 3> &spin, const double dt)
  {
    const Tensor<2, 3> I = unit_symmetric_tensor<3>();
    return invert(I - 0.5 * dt * spin) * (I + 0.5 * dt * spin);
  }

  /// sigma <- R sigma R^T for an orthogonal R.
  inline SymmetricTensor<2, 3>
  rotate_stress(const SymmetricTensor<2, 3> &sigma, const Tensor<2, 3> &R)
  {
    return symmetrize(R * Tensor<2, 3>(sigma) * transpose(R));
  }
} // namespace fsgmpm

#endif
