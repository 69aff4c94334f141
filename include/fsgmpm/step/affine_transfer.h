#ifndef fsgmpm_step_affine_transfer_h
#define fsgmpm_step_affine_transfer_h

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/particles/particle_store.h>

namespace fsgmpm
{
  namespace Stages
  {
    /**
     * APIC's affine part of a point's momentum at the nodes of its cell
     * (Jiang et al. 2015, Eq. 11 with D_p^-1 folded into C_p):
     * mv_k += N_k(x_p) m_p C_p (x_k - x_p). Together with the translation
     * part, a velocity field that is affine over the cell maps to the
     * nodes exactly, so resolved motion is not smoothed as in PIC.
     */
    template <int dim, typename Weights>
    inline void
    add_affine_momentum(const BackgroundGrid<dim> &grid,
                        const unsigned int         c,
                        const Weights             &lambda,
                        const double               mass,
                        const ParticleStore<dim>  &particles,
                        const unsigned int         p,
                        Tensor<1, dim>            *momentum)
    {
      const Tensor<2, dim> &C = particles.affine_velocity[p];
      const Point<dim>     &x = particles.position[p];
      for (unsigned int k = 0; k < dim + 1; ++k)
        momentum[k] += (lambda[k] * mass)
                       * (C * (grid.node_positions[grid.cell_nodes[c][k]] - x));
    }
  } // namespace Stages
} // namespace fsgmpm

#endif
