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
        double                  points_volume = 0;
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
              {
                points_volume += V;
                for (unsigned int k = 0; k < dim + 1; ++k)
                  nodal_volume_stress[k] += lambda[k] * Vs;
              }
          }
        // With the projection, the points' own part (1 - theta_c) here,
        // the projected part in the second pass.
        if (project)
          volume_stress
            *= 1. - CellLoops::projection_share(points_volume, geometry.volume);
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
              }
          }
      });

      if (!project)
        return;
      if (synchronise)
        synchronise();
      // Second pass: theta_c times the cell integral of the projected
      // volume-stress density sum_j N_j s_j (s_j = volume_stress_j /
      // support_volume_j), int_c N_j dV = V_c / (dim + 1), times the
      // constant gradients.
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        const double theta = CellLoops::projection_share(grid, particles, c);
        if (theta == 0)
          return;
        Tensor<2, dim> cell_stress;
        for (const unsigned int n : grid.cell_nodes[c])
          cell_stress += nodes.volume_stress[n] / nodes.support_volume[n];
        const CellGeometry<dim> geometry
          = CellLoops::geometry(grid, particles, c);
        cell_stress *= theta * geometry.volume / (dim + 1);
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
