#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    void
    velocity_gradients(const BackgroundGrid<dim> &grid,
                       const NodalFields<dim>    &nodes,
                       SmoothingFields<dim>      &smoothing,
                       const ParticleStore<dim>  &particles)
    {
      // Linear simplices: grad v is constant in a cell.
      smoothing.number_occupied_cells(particles);
      CellLoops::for_each_occupied_cell(particles, [&](const unsigned int c) {
        const auto     grad = grid.shape_gradients(c);
        Tensor<2, dim> L;
        for (unsigned int k = 0; k < dim + 1; ++k)
          L += outer_product(nodes.velocity[grid.cell_nodes[c][k]], grad[k]);
        smoothing.cell_velocity_gradient(c) = L;
      });
    }



    template <int dim>
    void
    nodal_velocity_gradients(const BackgroundGrid<dim> &grid,
                             const NodalFields<dim>    &nodes,
                             SmoothingFields<dim>      &smoothing,
                             const ParticleStore<dim>  &particles)
    {
      // The adjoint of p2g's nodal stress projection: the internal-force
      // power sum_c grad N_i^c . theta_c int_c sum_j N_j s_j dV . v_i
      // equals sum_p V_p sigma_p : sum_j N_j(x_p) Lbar_j with
      // Lbar_j = sum_c theta_c (V_c / (dim + 1)) L_c / V_j over the
      // occupied cells, and the points' own part (1 - theta_c) with L_c
      // (Stages::point_velocity_gradient).
      auto &Lbar = smoothing.nodal_velocity_gradient;
      if (Lbar.size() != grid.n_nodes())
        Lbar.assign(grid.n_nodes(), Tensor<2, dim>());
      for_each_node(nodes.active_nodes,
                    [&](const unsigned int i) { Lbar[i] = Tensor<2, dim>(); });
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        const Tensor<2, dim> share
          = (CellLoops::projection_share(grid, particles, c)
             * CellLoops::cell_volume(grid, particles, c) / (dim + 1))
            * smoothing.cell_velocity_gradient(c);
        for (const unsigned int n : grid.cell_nodes[c])
          Lbar[n] += share;
      });
      CellLoops::parallel_range(nodes.active_nodes.size(),
                                [&](const unsigned int b,
                                    const unsigned int e) {
                                  for (unsigned int a = b; a < e; ++a)
                                    {
                                      const unsigned int i
                                        = nodes.active_nodes[a];
                                      if (nodes.support_volume[i] > 0)
                                        Lbar[i] /= nodes.support_volume[i];
                                    }
                                });
    }

    template void
    velocity_gradients<2>(const BackgroundGrid<2> &,
                          const NodalFields<2> &,
                          SmoothingFields<2> &,
                          const ParticleStore<2> &);
    template void
    velocity_gradients<3>(const BackgroundGrid<3> &,
                          const NodalFields<3> &,
                          SmoothingFields<3> &,
                          const ParticleStore<3> &);
    template void
    nodal_velocity_gradients<2>(const BackgroundGrid<2> &,
                                const NodalFields<2> &,
                                SmoothingFields<2> &,
                                const ParticleStore<2> &);
    template void
    nodal_velocity_gradients<3>(const BackgroundGrid<3> &,
                                const NodalFields<3> &,
                                SmoothingFields<3> &,
                                const ParticleStore<3> &);
  } // namespace Stages
} // namespace fsgmpm
