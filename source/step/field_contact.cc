#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

#include <cmath>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    void
    contact_normals(const BackgroundGrid<dim> &grid,
                    const ParticleStore<dim>  &particles,
                    NodalFields<dim>          &nodes)
    {
      if (grid.n_velocity_fields() == 1)
        return;
      AssertThrow(
        grid.node_volume.size() == grid.n_nodes(),
        ExcMessage(
          "The multi-field contact reads the grid's nodal volumes: call "
          "BackgroundGrid::compute_node_volumes() once "
          "before the first step."));
      nodes.use(nodes.contact_normal);
      nodes.use(nodes.contact_volume);
      for (const unsigned int i : nodes.active_nodes)
        {
          nodes.contact_normal[grid.base_node(i)] = Tensor<1, dim>();
          nodes.contact_volume[grid.base_node(i)] = 0;
        }
      // The points' volume at each node, both fields together (copies of a
      // cell have different colours: no race on the base node).
      CellLoops::scatter_by_colour(grid, particles, [&](const unsigned int c) {
        const auto share = CellLoops::volume_shares(grid, particles, c);
        for (unsigned int k = 0; k < dim + 1; ++k)
          nodes.contact_volume[grid.base_node(grid.cell_nodes[c][k])]
            += share[k];
      });
      // n_i = -sum_c V_c grad(rho_0)|_c over the occupied cells around node
      // i, rho_0 = m_0,j / V_j field 0's nodal density interpolated
      // linearly: the outward normal of field 0 (the container, the base),
      // from its smoothed nodal mass rather than from the cells' own masses
      // (Bardenhagen's sum_c M_c grad N_i^c), whose direction jumps with
      // every point that crosses an edge; and field 0's alone, not the
      // difference of both fields' gradients, which tilts at the corners of
      // the other body and brakes it there. A block sliding frictionless on
      // an incline (field_contact; 1 cm cells, 4 points per cell) moved 7.2
      // mm with Bardenhagen's normal, 18.8 mm with the smoothed difference
      // and 24.53 mm with this one, against 24.525 mm exact.
      // Each base cell once: occupied_cells is ascending, so a copy is
      // skipped when a copy of a lower field holds points (it came first).
      for (const unsigned int c : particles.occupied_cells)
        {
          bool lower_copy_occupied = false;
          for (unsigned int f = 0; f < grid.field_of_cell(c); ++f)
            {
              const unsigned int cf = grid.cell_in_field(c, f);
              lower_copy_occupied
                = lower_copy_occupied
                  || particles.cell_end(cf) > particles.cell_begin(cf);
            }
          if (lower_copy_occupied)
            continue;
          const unsigned int      cb = grid.cell_in_field(c, 0);
          const CellGeometry<dim> geometry
            = CellLoops::geometry(grid, particles, cb);
          const auto     grad = geometry.shape_gradients();
          Tensor<1, dim> gradient;
          for (unsigned int k = 0; k < dim + 1; ++k)
            {
              const unsigned int i = grid.cell_nodes[cb][k];
              gradient -= (nodes.mass[i] / grid.node_volume[i]) * grad[k];
            }
          for (unsigned int k = 0; k < dim + 1; ++k)
            nodes.contact_normal[grid.cell_nodes[cb][k]]
              += geometry.volume * gradient;
        }
    }



    template <int dim>
    void
    field_contact(const BackgroundGrid<dim>       &grid,
                  const NodalConstraints<dim>     &constraints,
                  const double                     friction,
                  const double                     volume_fraction,
                  const double                     dt,
                  const bool                       update_acceleration,
                  NodalFields<dim>                &nodes,
                  const Tensor<1, dim>            &gravity,
                  CompensatedSum                  *unbalanced_norm_sq,
                  const std::vector<std::uint8_t> *counted_nodes)
    {
      if (grid.n_velocity_fields() == 1)
        return;

      const unsigned int n_base = grid.n_base_nodes();
      // What the contact did at each node in the grid update (1: held the
      // normal approach, 2: stuck), kept for the remap of the same step.
      nodes.use(nodes.field_contact_state);
      for (const unsigned int i : nodes.active_nodes)
        {
          if (i >= n_base)
            continue;
          const std::uint8_t state = nodes.field_contact_state[i];
          if (update_acceleration)
            nodes.field_contact_state[i] = 0;
          if (!fields_meet(grid, nodes, i, volume_fraction))
            continue;
          const unsigned int   j  = i + n_base;
          const double         m0 = nodes.mass[i], m1 = nodes.mass[j];
          const Tensor<1, dim> n
            = nodes.contact_normal[i] / nodes.contact_normal[i].norm();
          Tensor<1, dim>      &v0   = nodes.velocity[i];
          Tensor<1, dim>      &v1   = nodes.velocity[j];
          const Tensor<1, dim> v_cm = (m0 * v0 + m1 * v1) / (m0 + m1);
          const Tensor<1, dim> dv   = v0 - v_cm;
          const double         dn   = dv * n;
          Tensor<1, dim>       change;
          if (!update_acceleration && state != 0)
            // Held in the grid update: held in the remap too, both ways
            // (normal relative velocity zero; no relative motion where it
            // stuck), without a second friction impulse. Letting the
            // remapped velocities part where the grid update pressed the
            // fields together returned more energy than the impact took
            // (the discs of field_contact: +1.5% at the default volume
            // fraction, +44% with Bardenhagen's test).
            change = (state == 2) ? -dv : -dn * n;
          else
            {
              if (dn <= 0)
                continue; // separating or sliding apart: no contact force
              // Field 0's velocity change: the normal approach removed, the
              // tangential slip reduced by mu times the normal impulse
              // (stick if that is enough to stop it). Field 1 takes the
              // opposite momentum.
              const Tensor<1, dim> slip  = dv - dn * n;
              const double         s     = slip.norm();
              const bool           stick = (s <= friction * dn);
              change = stick ? -dv : -dn * n - (friction * dn / s) * slip;
              if (update_acceleration)
                nodes.field_contact_state[i] = stick ? 2 : 1;
            }
          const Tensor<1, dim> old0 = v0, old1 = v1;
          v0 += change;
          v1 -= (m0 / m1) * change;
          const bool walls = !nodes.wall_contact.empty();
          constraints.apply_kinematic(i, v0, walls ? nodes.wall_contact[i] : 0);
          constraints.apply_kinematic(j, v1, walls ? nodes.wall_contact[j] : 0);
          if (update_acceleration)
            {
              nodes.acceleration[i] += (v0 - old0) / dt;
              nodes.acceleration[j] += (v1 - old1) / dt;
            }
          if (unbalanced_norm_sq != nullptr)
            for (const auto &[k, dv_k] :
                 {std::make_pair(i, v0 - old0), std::make_pair(j, v1 - old1)})
              if (counted_nodes == nullptr || (*counted_nodes)[k] != 0)
                {
                  Tensor<1, dim> before
                    = nodes.mass[k] * gravity - nodes.internal_force[k];
                  Tensor<1, dim> after = before + (nodes.mass[k] / dt) * dv_k;
                  constraints.project_out(k, before);
                  constraints.project_out(k, after);
                  unbalanced_norm_sq->add(after.norm_square()
                                          - before.norm_square());
                }
        }
    }



    template void
    contact_normals<2>(const BackgroundGrid<2> &,
                       const ParticleStore<2> &,
                       NodalFields<2> &);
    template void
    contact_normals<3>(const BackgroundGrid<3> &,
                       const ParticleStore<3> &,
                       NodalFields<3> &);
    template void
    field_contact<2>(const BackgroundGrid<2> &,
                     const NodalConstraints<2> &,
                     const double,
                     const double,
                     const double,
                     const bool,
                     NodalFields<2> &,
                     const Tensor<1, 2> &,
                     CompensatedSum *,
                     const std::vector<std::uint8_t> *);
    template void
    field_contact<3>(const BackgroundGrid<3> &,
                     const NodalConstraints<3> &,
                     const double,
                     const double,
                     const double,
                     const bool,
                     NodalFields<3> &,
                     const Tensor<1, 3> &,
                     CompensatedSum *,
                     const std::vector<std::uint8_t> *);
  } // namespace Stages
} // namespace fsgmpm
