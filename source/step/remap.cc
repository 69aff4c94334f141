#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    void
    remap(const BackgroundGrid<dim>   &grid,
          const ParticleStore<dim>    &particles,
          const NodalConstraints<dim> &constraints,
          NodalFields<dim>            &nodes,
          const Membrane<dim>         *membrane)
    {
      for (const unsigned int i : nodes.active_nodes)
        nodes.momentum[i] = Tensor<1, dim>();

      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        Tensor<1, dim> mv[dim + 1];
        for (unsigned int p = particles.cell_start[c];
             p < particles.cell_start[c + 1];
             ++p)
          {
            const auto lambda = grid.barycentric(c, particles.position[p]);
            for (unsigned int k = 0; k < dim + 1; ++k)
              mv[k] += (lambda[k] * particles.mass[p]) * particles.velocity[p];
          }
        for (unsigned int k = 0; k < dim + 1; ++k)
          nodes.momentum[grid.cell_nodes[c][k]] += mv[k];
      });

      if (membrane != nullptr)
        membrane_remap(grid, *membrane, nodes);

      // Eq. (20) with the lumped mass matrix. Walls act kinematically only:
      // the friction impulse was applied once, in the grid update.
      for (const unsigned int i : nodes.active_nodes)
        if (nodes.mass[i] > 0)
          {
            nodes.velocity[i] = nodes.momentum[i] / nodes.mass[i];
            constraints.apply_kinematic(i, nodes.velocity[i]);
          }
    }

    template void
    remap<2>(const BackgroundGrid<2> &,
             const ParticleStore<2> &,
             const NodalConstraints<2> &,
             NodalFields<2> &,
             const Membrane<2> *);
    template void
    remap<3>(const BackgroundGrid<3> &,
             const ParticleStore<3> &,
             const NodalConstraints<3> &,
             NodalFields<3> &,
             const Membrane<3> *);
  } // namespace Stages
} // namespace fsgmpm
