#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

#include <algorithm>
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
        const std::function<void(unsigned int)> &synchronise,
        const std::vector<double>               &stabilisation)
    {
      const bool project = (integration == StressIntegration::nodal_projection);
      // The share alpha of a point's mean stress that stays with its own
      // cell (the projection's counterpart of the NMD + ANP blend): the
      // averages have a null space in which the points pack without
      // pressure, and alpha gives it a stiffness.
      const bool stabilise
        = project
          && std::any_of(stabilisation.begin(),
                         stabilisation.end(),
                         [](const double alpha) { return alpha > 0; });
      nodes.reset_active();
      if (stabilise)
        {
          nodes.use(nodes.stabilised_trace);
          nodes.projection_own_trace.resize(particles.occupied_cells.size());
        }
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
        double                      stabilised[dim + 1] = {};
        double                      own_trace           = 0;
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
            if (stabilise)
              {
                const double alpha = stabilisation[particles.material_id[p]];
                if (alpha > 0)
                  {
                    const double t = alpha * trace(Vs) / dim;
                    own_trace += t;
                    for (unsigned int k = 0; k < dim + 1; ++k)
                      stabilised[k] += lambda[k] * t;
                  }
              }
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
                if (stabilise)
                  nodes.stabilised_trace[n] += stabilised[k];
              }
            else
              nodes.internal_force[n] += volume_stress * grad[k];
          }
        if (project)
          nodes.projection_weights[particles.occupied_slot(c)] = lumped;
        if (stabilise)
          nodes.projection_own_trace[particles.occupied_slot(c)] = own_trace;
      });

      if (!project)
        return;
      if (synchronise)
        synchronise(1);
      // Second pass: each cell's quadrature weights q_kc, between its own
      // (V_c / (dim + 1)) and its points' (sum_p N_k(x_p) V_p) by the fill
      // of its nodes (CellLoops::geometric_quadrature_share), and their
      // nodal sums.
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        double min_fill = std::numeric_limits<double>::max();
        for (const unsigned int n : grid.cell_nodes[c])
          min_fill
            = std::min(min_fill,
                       nodes.lumped_volume[n] / nodes.occupied_volume[n]);
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
      // Third pass: the projected volume-stress density sum_k N_k s_k
      // (s_k = volume_stress_k / support_volume_k, the q-weighted average
      // of the points' stresses) integrated with the weights q_kc, times
      // the constant gradients. A uniform stress is reproduced at every
      // node, so a cell gets sum_k q_kc sigma: its own volume times sigma
      // inside, its points' volume times sigma where it is partly filled.
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        const auto    &q = nodes.projection_weights[particles.occupied_slot(c)];
        Tensor<2, dim> cell_stress;
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            const unsigned int n = grid.cell_nodes[c][k];
            if (nodes.support_volume[n] > 0)
              {
                cell_stress
                  += (q[k] / nodes.support_volume[n]) * nodes.volume_stress[n];
                if (stabilise)
                  for (unsigned int d = 0; d < dim; ++d)
                    cell_stress[d][d] -= (q[k] / nodes.support_volume[n])
                                         * nodes.stabilised_trace[n];
              }
          }
        // The share alpha of the mean stress in the cell's own points.
        if (stabilise)
          for (unsigned int d = 0; d < dim; ++d)
            cell_stress[d][d]
              += nodes.projection_own_trace[particles.occupied_slot(c)];
        const auto grad
          = CellLoops::geometry(grid, particles, c).shape_gradients();
        for (unsigned int k = 0; k < dim + 1; ++k)
          nodes.internal_force[grid.cell_nodes[c][k]] += cell_stress * grad[k];
      });
    }

    template void
    p2g<2>(const BackgroundGrid<2> &,
           const ParticleStore<2> &,
           NodalFields<2> &,
           StressIntegration,
           const std::function<void(unsigned int)> &,
           const std::vector<double> &);
    template void
    p2g<3>(const BackgroundGrid<3> &,
           const ParticleStore<3> &,
           NodalFields<3> &,
           StressIntegration,
           const std::function<void(unsigned int)> &,
           const std::vector<double> &);
  } // namespace Stages
} // namespace fsgmpm
