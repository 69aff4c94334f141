#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    void
    g2p(const BackgroundGrid<dim> &grid,
        const NodalFields<dim>    &nodes,
        const double               dt,
        ParticleStore<dim>        &particles)
    {
      CellLoops::for_each_occupied_cell(particles, [&](const unsigned int c) {
        Tensor<1, dim> a[dim + 1];
        for (unsigned int k = 0; k < dim + 1; ++k)
          a[k] = nodes.acceleration[grid.cell_nodes[c][k]];
        for (unsigned int p = particles.cell_start[c];
             p < particles.cell_start[c + 1];
             ++p)
          {
            const auto     lambda = grid.barycentric(c, particles.position[p]);
            Tensor<1, dim> dv;
            for (unsigned int k = 0; k < dim + 1; ++k)
              dv += lambda[k] * a[k];
            particles.velocity[p] += dt * dv;
          }
      });
    }

    template void
    g2p<2>(const BackgroundGrid<2> &,
           const NodalFields<2> &,
           const double,
           ParticleStore<2> &);
    template void
    g2p<3>(const BackgroundGrid<3> &,
           const NodalFields<3> &,
           const double,
           ParticleStore<3> &);
  } // namespace Stages
} // namespace fsgmpm
