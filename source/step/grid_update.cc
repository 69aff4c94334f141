#include <fsgmpm/base/compensated_sum.h>
#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

#include <cmath>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    GridUpdateResult
    grid_update(const NodalConstraints<dim>     &constraints,
                const Tensor<1, dim>            &gravity,
                const double                     alpha,
                const double                     dt,
                NodalFields<dim>                &nodes,
                const std::vector<std::uint8_t> *counted_nodes,
                const BackgroundGrid<dim>       *grid,
                const double                     contact_volume_fraction)
    {
      GridUpdateResult r;
      // The damping work is booked at every node as dt F_damping . v_old:
      // the damping opposes v_old component by component, so each node's
      // share is a loss, also at a node that a point's corner barely
      // reaches, where v_mid (force / tiny mass) is not the material's
      // velocity (a grid node of 4e-7 kg under 68 N in the 3D geotube slab
      // booked -426 J in one step with v_mid; the points' kinetic energy
      // was 34 J).
      // Compensated, so that it does not depend on the order of the nodes
      // or on how they are split over processes (it steers the damping).
      // The loops over the nodes run in parallel, their sums in fixed
      // chunks (CellLoops::compensated_sums): the same for any number of
      // threads.
      const auto &active = nodes.active_nodes;
      if (constraints.has_unilateral_walls())
        nodes.use(nodes.wall_contact);
      const bool remember_contact = !nodes.wall_contact.empty();
      // Mass scaling's fictitious inertia (sized only when it is used).
      const bool scaled = !nodes.added_mass.empty();
      // Two fields meeting: the damping reads both fields' force.
      const bool two_fields = alpha > 0 && grid != nullptr
                              && grid->n_velocity_fields() == 2
                              && nodes.contact_volume.size() > 0;
      const unsigned int n_base = grid != nullptr ? grid->n_base_nodes() : 0;
      // Nodes with (almost) no mass carry no information; the remap of
      // Eq. (20) gives them a velocity consistent with their particles.
      const auto sums = CellLoops::compensated_sums<4>(
        active.size(), [&](const unsigned int a, auto &sums) {
          const unsigned int i = active[a];
          const double       m = nodes.mass[i];
          if (m <= 0)
            return;
          // F_ext of Eq. (4): gravity, m_i g.
          const Tensor<1, dim> external = m * gravity;
          // v_old is the unconstrained mapped velocity, so that the
          // acceleration a = (v_new - v_old)/dt carries the wall's effect
          // back to the particles in Eq. (19).
          const Tensor<1, dim> v_old = nodes.momentum[i] / m;

          const Tensor<1, dim> unbalanced = external - nodes.internal_force[i];
          Tensor<1, dim>       damped     = unbalanced;
          if (two_fields
              && fields_meet(*grid, nodes, i % n_base, contact_volume_fraction))
            {
              const unsigned int other = (i < n_base) ? i + n_base : i - n_base;
              const double       m_o   = nodes.mass[other];
              damped
                = (m / (m + m_o))
                  * (unbalanced + m_o * gravity - nodes.internal_force[other]);
            }
          // Local non-viscous damping: opposes the motion with a fraction of
          // the unbalanced force, component by component.
          Tensor<1, dim> damping;
          if (alpha > 0)
            for (unsigned int d = 0; d < dim; ++d)
              if (v_old[d] != 0)
                damping[d]
                  = -alpha * std::abs(damped[d]) * (v_old[d] > 0 ? 1. : -1.);

          // Mass scaling: the fictitious inertia is directional.
          Tensor<1, dim> v_new = v_old;
          if (!scaled || nodes.added_mass[i].norm() == 0)
            v_new += (dt / m) * (unbalanced + damping);
          else
            v_new += dt
                     * (invert(m * unit_symmetric_tensor<dim>()
                               + nodes.added_mass[i])
                        * (unbalanced + damping));
          const std::uint8_t contact = constraints.apply(i, v_new);
          if (remember_contact)
            nodes.wall_contact[i] = contact;
          nodes.velocity[i]     = v_new;
          nodes.acceleration[i] = (v_new - v_old) / dt;

          if (counted_nodes != nullptr && (*counted_nodes)[i] == 0)
            return;
          const Tensor<1, dim> v_mid = 0.5 * (v_old + v_new);
          sums[0].add(dt * (external * v_mid));
          sums[1].add(-dt * (damping * v_old));

          Tensor<1, dim> free_unbalanced = unbalanced;
          Tensor<1, dim> free_external   = external;
          constraints.project_out(i, free_unbalanced);
          constraints.project_out(i, free_external);
          sums[2].add(free_unbalanced.norm_square());
          sums[3].add(free_external.norm_square());
        });
      r.external_work_increment = sums[0];
      r.damping_work_increment  = sums[1];
      r.unbalanced_norm_sq      = sums[2];
      r.external_norm_sq        = sums[3];
      return r;
    }

    template GridUpdateResult
    grid_update<2>(const NodalConstraints<2> &,
                   const Tensor<1, 2> &,
                   const double,
                   const double,
                   NodalFields<2> &,
                   const std::vector<std::uint8_t> *,
                   const BackgroundGrid<2> *,
                   const double);
    template GridUpdateResult
    grid_update<3>(const NodalConstraints<3> &,
                   const Tensor<1, 3> &,
                   const double,
                   const double,
                   NodalFields<3> &,
                   const std::vector<std::uint8_t> *,
                   const BackgroundGrid<3> *,
                   const double);
  } // namespace Stages
} // namespace fsgmpm
