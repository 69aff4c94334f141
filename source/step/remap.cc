#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

#include <algorithm>
#include <vector>

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
          const MembraneCoupling<dim> *membrane,
          const bool                   affine)
    {
      // APIC's affine term in Eq. (20), sum_p N_i m_p (v_p + C_p (x_i -
      // x_p)) with v_p and C_p the grid-updated velocity and gradient, is
      // m_i v_i on linear simplices: the grid-updated velocity is kept.
      // Blended to the mass average at nodes whose points fill less than a
      // quarter of their volume (weight fill / (1/4)), where the mass
      // average suppresses the small-mass instability (a full affine remap,
      // i.e. USL, was unstable in free fall: doc/accuracy_vs_cost.md).
      // Scratch kept between steps. The scatter below runs on worker
      // threads, where a thread_local names another thread's (empty)
      // vector: it writes through this reference.
      thread_local std::vector<Tensor<1, dim>> updated_velocity_scratch;
      thread_local std::vector<double>         filled_volume_scratch;
      std::vector<Tensor<1, dim>> &updated_velocity = updated_velocity_scratch;
      std::vector<double>         &filled_volume    = filled_volume_scratch;
      if (affine)
        {
          AssertThrow(grid.node_volume.size() == grid.n_nodes(),
                      ExcMessage(
                        "The affine remap reads the grid's nodal volumes: call "
                        "BackgroundGrid::compute_node_volumes() once "
                        "before the first step."));
          updated_velocity.resize(grid.n_nodes());
          filled_volume.resize(grid.n_nodes());
          for_each_node(nodes.active_nodes, [&](const unsigned int i) {
            updated_velocity[i] = nodes.velocity[i];
            filled_volume[i]    = 0;
          });
        }
      for_each_node(nodes.active_nodes, [&](const unsigned int i) {
        nodes.momentum[i] = Tensor<1, dim>();
      });

      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        Tensor<1, dim>          mv[dim + 1];
        const CellGeometry<dim> geometry
          = CellLoops::geometry(grid, particles, c);
        for (unsigned int p = particles.cell_begin(c);
             p < particles.cell_end(c);
             ++p)
          {
            const auto lambda = geometry.barycentric(particles.position[p]);
            for (unsigned int k = 0; k < dim + 1; ++k)
              mv[k] += (lambda[k] * particles.mass[p]) * particles.velocity[p];
          }
        for (unsigned int k = 0; k < dim + 1; ++k)
          nodes.momentum[grid.cell_nodes[c][k]] += mv[k];
        if (affine)
          {
            const auto share = CellLoops::volume_shares(grid, particles, c);
            for (unsigned int k = 0; k < dim + 1; ++k)
              filled_volume[grid.cell_nodes[c][k]] += share[k];
          }
      });

      if (membrane != nullptr)
        membrane->remap(nodes);

      // Eq. (20) with the lumped mass matrix. Walls act kinematically only:
      // the friction impulse was applied once, in the grid update; a node
      // that static friction held there stays at rest.
      for_each_node(nodes.active_nodes, [&](const unsigned int i) {
        if (nodes.mass[i] > 0)
          {
            nodes.velocity[i] = nodes.momentum[i] / nodes.mass[i];
            if (affine)
              {
                const double weight
                  = std::min(1., 4. * filled_volume[i] / grid.node_volume[i]);
                nodes.velocity[i] = weight * updated_velocity[i]
                                    + (1 - weight) * nodes.velocity[i];
              }
            constraints.apply_kinematic(i,
                                        nodes.velocity[i],
                                        nodes.wall_contact.empty()
                                          ? 0
                                          : nodes.wall_contact[i]);
          }
      });
    }

    template void
    remap<2>(const BackgroundGrid<2> &,
             const ParticleStore<2> &,
             const NodalConstraints<2> &,
             NodalFields<2> &,
             const MembraneCoupling<2> *,
             bool);
    template void
    remap<3>(const BackgroundGrid<3> &,
             const ParticleStore<3> &,
             const NodalConstraints<3> &,
             NodalFields<3> &,
             const MembraneCoupling<3> *,
             bool);
  } // namespace Stages
} // namespace fsgmpm
