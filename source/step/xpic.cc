#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

namespace fsgmpm
{
  namespace Stages
  {
    template <int dim>
    void
    xpic_correction(
      const BackgroundGrid<dim>                                &grid,
      const ParticleStore<dim>                                 &particles,
      const NodalConstraints<dim>                              &constraints,
      const NodalFields<dim>                                   &nodes,
      const unsigned int                                        order,
      XpicFields<dim>                                          &xpic,
      const std::function<void(std::vector<Tensor<1, dim>> &)> &synchronise)
    {
      // XPIC(m) (Hammerquist and Nairn 2017): with S the interpolation to
      // the points and A = M_L^-1 S^T M_p S the round trip grid -> points
      // -> grid (the consistent mass over the lumped one), the grid velocity
      //   v* = sum_{k=1}^m (-1)^(k+1) C(m, k) A^(k-1) v^n
      // is the m-term Neumann series of A^-1 v^n, so S v* is the points'
      // velocity with its grid-resolved part kept to 1 - (1 - a)^m for a
      // mode that one round trip keeps to a (PIC: a, about 1 - (kh)^2/6 on
      // linear elements), and its sub-cell (null-space) part dropped as in
      // PIC. The points take S (v^L - v^n + v*): the correction stored here
      // is v* - v^n, with the walls' constrained components removed.
      AssertThrow(order >= 2, ExcMessage("XPIC order 1 is PIC's blend."));
      const unsigned int n = nodes.mass.size();
      for (auto *v : {&xpic.correction, &xpic.previous, &xpic.next})
        if (v->size() != n)
          v->assign(n, Tensor<1, dim>());
      if (xpic.point_mass.size() != n)
        xpic.point_mass.assign(n, 0.);
      const auto &active = nodes.active_nodes;
      // k = 1: C(m, 1) v^n.
      for_each_node(active, [&](const unsigned int i) {
        const double m = nodes.mass[i];
        xpic.previous[i]
          = m > 0 ? (order / m) * nodes.momentum[i] : Tensor<1, dim>();
      });
      if (synchronise)
        synchronise(xpic.previous);
      for_each_node(active, [&](const unsigned int i) {
        xpic.correction[i] = ((order - 1.) / order) * xpic.previous[i];
      });
      double sign = -1;
      for (unsigned int k = 2; k <= order; ++k, sign = -sign)
        {
          // The points' nodal mass sum_p N_i m_p is the same in every
          // pass: summed in the first.
          const bool first = (k == 2);
          for_each_node(active, [&](const unsigned int i) {
            xpic.next[i] = Tensor<1, dim>();
            if (first)
              xpic.point_mass[i] = 0;
          });
          // sum_p N_i m_p (S u)(x_p) (and in the first pass sum_p N_i m_p).
          CellLoops::scatter_by_colour(
            grid, particles, [&](const unsigned int c) {
              Tensor<1, dim>          u[dim + 1], mu[dim + 1];
              double                  mass[dim + 1] = {};
              const CellGeometry<dim> geometry
                = CellLoops::geometry(grid, particles, c);
              for (unsigned int q = 0; q < dim + 1; ++q)
                u[q] = xpic.previous[grid.cell_nodes[c][q]];
              for (unsigned int p = particles.cell_begin(c);
                   p < particles.cell_end(c);
                   ++p)
                {
                  const auto lambda
                    = geometry.barycentric(particles.position[p]);
                  Tensor<1, dim> value;
                  for (unsigned int q = 0; q < dim + 1; ++q)
                    value += lambda[q] * u[q];
                  for (unsigned int q = 0; q < dim + 1; ++q)
                    {
                      const double w = lambda[q] * particles.mass[p];
                      mu[q] += w * value;
                      if (first)
                        mass[q] += w;
                    }
                }
              for (unsigned int q = 0; q < dim + 1; ++q)
                {
                  xpic.next[grid.cell_nodes[c][q]] += mu[q];
                  if (first)
                    xpic.point_mass[grid.cell_nodes[c][q]] += mass[q];
                }
            });
          // The term C(m, k) A^(k-1) v^n from the previous one by
          // (m - k + 1) / k; the mass at a node that is not the points'
          // (the membrane's) is lumped: A is the identity for it.
          const double scale = (order - k + 1.) / k;
          for_each_node(active, [&](const unsigned int i) {
            const double m = nodes.mass[i];
            if (m <= 0)
              return;
            const double rest = std::max(m - xpic.point_mass[i], 0.);
            xpic.next[i]
              = (scale / m) * (xpic.next[i] + rest * xpic.previous[i]);
          });
          // MPI: the rim nodes' terms as their owners have them.
          if (synchronise)
            synchronise(xpic.next);
          for_each_node(active, [&](const unsigned int i) {
            xpic.correction[i] += sign * xpic.next[i];
            std::swap(xpic.previous[i], xpic.next[i]);
          });
        }
      for_each_node(active, [&](const unsigned int i) {
        constraints.project_out(i, xpic.correction[i]);
      });
    }

    template void
    xpic_correction<2>(
      const BackgroundGrid<2> &,
      const ParticleStore<2> &,
      const NodalConstraints<2> &,
      const NodalFields<2> &,
      const unsigned int,
      XpicFields<2> &,
      const std::function<void(std::vector<Tensor<1, 2>> &)> &);
    template void
    xpic_correction<3>(
      const BackgroundGrid<3> &,
      const ParticleStore<3> &,
      const NodalConstraints<3> &,
      const NodalFields<3> &,
      const unsigned int,
      XpicFields<3> &,
      const std::function<void(std::vector<Tensor<1, 3>> &)> &);
  } // namespace Stages
} // namespace fsgmpm
