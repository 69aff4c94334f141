#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

#include <limits>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    void
    p2g(const BackgroundGrid<dim>               &grid,
        const ParticleStore<dim>                &particles,
        NodalFields<dim>                        &nodes,
        const StressIntegration                  integration,
        const std::function<void(unsigned int)> &synchronise)
    {
      const bool project = (integration == StressIntegration::nodal_projection);
      nodes.reset_active();
      if (project)
        {
          nodes.use(nodes.volume_stress);
          nodes.use(nodes.support_volume);
          nodes.use(nodes.lumped_volume);
          nodes.use(nodes.occupied_volume);
          nodes.projection_weights.resize(particles.occupied_cells.size());
        }
      for (const unsigned int c : particles.occupied_cells)
        nodes.activate(grid.cell_nodes[c]);

      const bool apic = particles.has_affine_velocity();
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        double         m[dim + 1] = {};
        Tensor<1, dim> mv[dim + 1];
        // Eq. (3): F_int,i = sum_p V_p sigma_p grad N_i, constant gradients.
        Tensor<2, dim>              volume_stress;
        Tensor<2, dim>              nodal_volume_stress[dim + 1];
        std::array<double, dim + 1> lumped{};
        const CellGeometry<dim>     geometry
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
            if (project)
              for (unsigned int k = 0; k < dim + 1; ++k)
                {
                  lumped[k] += lambda[k] * V;
                  nodal_volume_stress[k] += lambda[k] * Vs;
                }
            else
              volume_stress += Vs;
          }
        const auto grad = geometry.shape_gradients();
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            const unsigned int n = grid.cell_nodes[c][k];
            nodes.mass[n] += m[k];
            nodes.momentum[n] += mv[k];
            if (project)
              {
                nodes.volume_stress[n] += nodal_volume_stress[k];
                nodes.lumped_volume[n] += lumped[k];
                nodes.occupied_volume[n] += geometry.volume / (dim + 1);
              }
            else
              nodes.internal_force[n] += volume_stress * grad[k];
          }
        if (project)
          nodes.projection_weights[particles.occupied_slot(c)] = lumped;
      });

      if (!project)
        return;
      if (synchronise)
        synchronise(1);
      // The material fill of every active node: the points of all fields
      // at its base node over the grid's nodal volume (in a fixed order of
      // the fields, so that it does not depend on the threads).
      AssertThrow(grid.node_volume.size() == grid.n_nodes(),
                  ExcMessage("The nodal stress projection reads the grid's "
                             "nodal volumes: call "
                             "BackgroundGrid::compute_node_volumes() once "
                             "before the first step."));
      nodes.use(nodes.material_fill);
      CellLoops::parallel_range(
        nodes.active_nodes.size(),
        [&](const unsigned int b, const unsigned int e) {
          for (unsigned int a = b; a < e; ++a)
            {
              const unsigned int i    = nodes.active_nodes[a];
              const unsigned int base = grid.base_node(i);
              double             v    = 0;
              for (unsigned int f = 0; f < grid.n_velocity_fields(); ++f)
                v += nodes.lumped_volume[base + f * grid.n_base_nodes()];
              nodes.material_fill[i] = v / grid.node_volume[i];
            }
        });
      // Second pass: each cell's quadrature weights q_kc, between its own
      // (V_c / (dim + 1)) and its points' (sum_p N_k(x_p) V_p) by the fill
      // of its nodes (CellLoops::geometric_quadrature_share: the smaller of
      // the field's own fill and the material fill, so the cell's own
      // weights are used only where every node has Theta = 1), and their
      // nodal sums.
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        double min_fill = std::numeric_limits<double>::max();
        for (const unsigned int n : grid.cell_nodes[c])
          min_fill
            = std::min({min_fill,
                        nodes.lumped_volume[n] / nodes.occupied_volume[n],
                        nodes.material_fill[n]});
        const double gamma = CellLoops::geometric_quadrature_share(min_fill);
        const double own
          = CellLoops::cell_volume(grid, particles, c) / (dim + 1);
        auto &q = nodes.projection_weights[particles.occupied_slot(c)];
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            q[k] = gamma * own + (1. - gamma) * q[k];
            nodes.support_volume[grid.cell_nodes[c][k]] += q[k];
          }
      });
      if (synchronise)
        synchronise(2);
      // Third pass: the projected volume-stress density sum_k Theta_k N_k
      // s_k (s_k = volume_stress_k / support_volume_k, the q-weighted
      // average of the points' stresses, Theta_k the node's share,
      // CellLoops::projection_share) integrated with the weights q_kc, plus
      // each point's own share w_p = 1 - sum_k N_k(x_p) Theta_k of V_p
      // sigma_p, times the constant gradients. Under a uniform stress a
      // cell gets sum_k q_kc sigma: its own volume times sigma inside, its
      // points' volume times sigma where it is partly filled.
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        const auto    &q = nodes.projection_weights[particles.occupied_slot(c)];
        Tensor<2, dim> cell_stress;
        std::array<double, dim + 1> share;
        bool                        points_share = false;
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            const unsigned int n = grid.cell_nodes[c][k];
            share[k] = CellLoops::projection_share(nodes.material_fill[n]);
            points_share |= (share[k] < 1.);
            if (nodes.support_volume[n] > 0 && share[k] > 0)
              cell_stress += (share[k] * q[k] / nodes.support_volume[n])
                             * nodes.volume_stress[n];
          }
        const CellGeometry<dim> geometry
          = CellLoops::geometry(grid, particles, c);
        if (points_share)
          for (unsigned int p = particles.cell_begin(c);
               p < particles.cell_end(c);
               ++p)
            {
              const auto lambda = geometry.barycentric(particles.position[p]);
              double     w      = 1.;
              for (unsigned int k = 0; k < dim + 1; ++k)
                w -= lambda[k] * share[k];
              const double wV = w * particles.volume[p];
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  cell_stress[i][j] += wV * particles.stress[p][i][j];
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
           const std::function<void(unsigned int)> &);
    template void
    p2g<3>(const BackgroundGrid<3> &,
           const ParticleStore<3> &,
           NodalFields<3> &,
           StressIntegration,
           const std::function<void(unsigned int)> &);
  } // namespace Stages
} // namespace fsgmpm
