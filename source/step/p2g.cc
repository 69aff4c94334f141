#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    void
    p2g(const BackgroundGrid<dim>   &grid,
        const ParticleStore<dim>    &particles,
        NodalFields<dim>            &nodes,
        const StressIntegration      integration,
        const std::function<void()> &synchronise)
    {
      const bool project = (integration == StressIntegration::nodal_projection);
      nodes.reset_active();
      if (project)
        {
          nodes.use(nodes.volume_stress);
          nodes.use(nodes.support_volume);
          nodes.use(nodes.point_volume);
          Assert(grid.node_volume.size() == grid.n_nodes(),
                 ExcMessage("The nodal stress projection needs the grid's "
                            "nodal volumes (compute_node_volumes())."));
        }
      for (const unsigned int c : particles.occupied_cells)
        nodes.activate(grid.cell_nodes[c]);

      const bool apic = particles.has_affine_velocity();
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        double         m[dim + 1] = {};
        Tensor<1, dim> mv[dim + 1];
        // Eq. (3): F_int,i = sum_p V_p sigma_p grad N_i, constant gradients.
        Tensor<2, dim>          volume_stress;
        Tensor<2, dim>          nodal_volume_stress[dim + 1];
        double                  nodal_point_volume[dim + 1] = {};
        const CellGeometry<dim> geometry
          = CellLoops::geometry(grid, particles, c);
        for (unsigned int p = particles.cell_begin(c);
             p < particles.cell_end(c);
             ++p)
          {
            const auto   lambda = geometry.barycentric(particles.position[p]);
            const double mp     = particles.mass[p];
            for (unsigned int k = 0; k < dim + 1; ++k)
              {
                m[k] += lambda[k] * mp;
                mv[k] += (lambda[k] * mp) * particles.velocity[p];
              }
            // APIC's affine part (Jiang et al. 2015, Eq. 11 with D_p^-1
            // folded into C_p): an affine velocity field over the cell
            // maps to the nodes exactly, so resolved motion is not
            // smoothed as in PIC.
            if (apic)
              for (unsigned int k = 0; k < dim + 1; ++k)
                mv[k] += (lambda[k] * mp)
                         * (particles.affine_velocity[p]
                            * (grid.node_positions[grid.cell_nodes[c][k]]
                               - particles.position[p]));
            Tensor<2, dim> Vs;
            const double   V = particles.volume[p];
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                Vs[i][j] = V * particles.stress[p][i][j];
            volume_stress += Vs;
            if (project)
              for (unsigned int k = 0; k < dim + 1; ++k)
                {
                  nodal_volume_stress[k] += lambda[k] * Vs;
                  nodal_point_volume[k] += lambda[k] * V;
                }
          }
        const auto grad = geometry.shape_gradients();
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            const unsigned int n = grid.cell_nodes[c][k];
            nodes.mass[n] += m[k];
            nodes.momentum[n] += mv[k];
            nodes.internal_force[n] += volume_stress * grad[k];
            if (project)
              {
                nodes.volume_stress[n] += nodal_volume_stress[k];
                nodes.support_volume[n] += geometry.volume / (dim + 1);
                nodes.point_volume[n] += nodal_point_volume[k];
              }
          }
      });

      if (!project)
        return;
      if (synchronise)
        synchronise();
      // Second pass: with the nodal shares Theta_k (projection_share())
      // the points keep w_p = 1 - sum_k N_k(x_p) Theta_k of their own
      // stresses, and the cell integrates the projected part,
      // sum_k Theta_k (s_k V_c / (dim + 1) - sum_p N_k(x_p) V_p sigma_p),
      // s_k = volume_stress_k / support_volume_k, int_c N_k dV =
      // V_c / (dim + 1), times the constant gradients.
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        double share[dim + 1];
        bool   any = false;
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            const unsigned int n = grid.cell_nodes[c][k];
            share[k] = CellLoops::projection_share(nodes.point_volume[n],
                                                   grid.node_volume[n]);
            any      = any || share[k] > 0;
          }
        if (!any)
          return;
        const CellGeometry<dim> geometry
          = CellLoops::geometry(grid, particles, c);
        Tensor<2, dim> cell_stress;
        for (unsigned int k = 0; k < dim + 1; ++k)
          if (share[k] > 0)
            {
              const unsigned int n = grid.cell_nodes[c][k];
              cell_stress += (share[k] * geometry.volume / (dim + 1)
                              / nodes.support_volume[n])
                             * nodes.volume_stress[n];
            }
        for (unsigned int p = particles.cell_begin(c);
             p < particles.cell_end(c);
             ++p)
          {
            const auto lambda    = geometry.barycentric(particles.position[p]);
            double     projected = 0;
            for (unsigned int k = 0; k < dim + 1; ++k)
              projected += lambda[k] * share[k];
            const double w = projected * particles.volume[p];
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                cell_stress[i][j] -= w * particles.stress[p][i][j];
          }
        const auto grad = geometry.shape_gradients();
        for (unsigned int k = 0; k < dim + 1; ++k)
          nodes.internal_force[grid.cell_nodes[c][k]] += cell_stress * grad[k];
      });
    }

    template void
    p2g<2>(const BackgroundGrid<2> &,
           const ParticleStore<2> &,
           NodalFields<2> &,
           StressIntegration,
           const std::function<void()> &);
    template void
    p2g<3>(const BackgroundGrid<3> &,
           const ParticleStore<3> &,
           NodalFields<3> &,
           StressIntegration,
           const std::function<void()> &);
  } // namespace Stages
} // namespace fsgmpm
