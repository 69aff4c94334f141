#ifndef fsgmpm_io_membrane_fe_output_h
#define fsgmpm_io_membrane_fe_output_h

#include <fsgmpm/membrane/membrane.h>

#include <string>

namespace fsgmpm
{
  /**
   * The membrane's finite elements through deal.II's DataOut (Output/
   * Membrane output = finite elements): the cells of MembraneFE in their
   * current shape (a MappingFEField on the node positions; quadratic cells
   * at degree 2, written as VTK Lagrange cells), with per cell the
   * principal membrane stresses "tension" and "minor_tension" (N/m,
   * MembraneFE's quadrature average; minor 0 for cables), the same
   * average of the Cauchy membrane stress tensor "tension_tensor" (N/m,
   * dim x dim in x-y-z, so that any component can be taken, e.g. a tube's
   * hoop tension), "stretch" (current/rest length in 2D, square root of
   * the area ratio in 3D), and
   * per support point "velocity" and "displacement" (from the rest
   * position, which includes the initial strain). Written atomically.
   */
  template <int dim>
  void
  write_membrane_fe_vtu(const Membrane<dim> &membrane, const std::string &file);
} // namespace fsgmpm

#endif
