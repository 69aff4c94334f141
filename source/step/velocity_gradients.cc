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
      // power sum_c grad N_i^c . sum_k q_kc s_k . v_i, with s_k =
      // sum_p N_k(x_p) V_p sigma_p / Q_k and Q_k = sum_c q_kc, equals
      // sum_p V_p sigma_p : sum_k N_k(x_p) Lbar_k with Lbar_k = sum_c q_kc
      // L_c / Q_k (Stages::point_velocity_gradient).
      auto &Lbar = smoothing.nodal_velocity_gradient;
      if (Lbar.size() != grid.n_nodes())
        Lbar.assign(grid.n_nodes(), Tensor<2, dim>());
      for_each_node(nodes.active_nodes,
                    [&](const unsigned int i) { Lbar[i] = Tensor<2, dim>(); });
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        const auto &q = nodes.projection_weights[particles.occupied_slot(c)];
        const Tensor<2, dim> &L = smoothing.cell_velocity_gradient(c);
        for (unsigned int k = 0; k < dim + 1; ++k)
          Lbar[grid.cell_nodes[c][k]] += q[k] * L;
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
