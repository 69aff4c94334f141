#include <fsgmpm/particles/point_locator.h>
#include <fsgmpm/step/stages.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsgmpm
{
  namespace Stages
  {
    // The membrane is small (10^2-10^4 nodes against 10^5 points), so its
    // transfers run serially; they only need the shape values N_i(x_a), never
    // gradients (FEM-MPM coupling through the shared grid nodes).

    template <int dim>
    void
    membrane_p2g(const BackgroundGrid<dim> &grid,
                 Membrane<dim>             &membrane,
                 NodalFields<dim>          &nodes)
    {
      // The shape values at the node (start of step) are the transfer
      // weights of every membrane stage of this step.
      membrane.weights.resize(membrane.n_nodes());
      for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
        {
          const auto l
            = grid.barycentric(membrane.cell[a], membrane.position[a]);
          std::copy(l.begin(), l.end(), membrane.weights[a].begin());
        }

      for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
        {
          const unsigned int c = membrane.cell[a];
          nodes.activate(grid.cell_nodes[c]);
          const auto  &lambda = membrane.weights[a];
          const double m      = membrane.mass[a];
          for (unsigned int k = 0; k < dim + 1; ++k)
            {
              const unsigned int i = grid.cell_nodes[c][k];
              nodes.mass[i] += lambda[k] * m;
              nodes.momentum[i] += (lambda[k] * m) * membrane.velocity[a];
              // The element force acts on the node: M a = F_ext - F_int.
              nodes.internal_force[i] -= lambda[k] * membrane.force[a];
            }
        }
    }



    template <int dim>
    double
    membrane_time_step(const BackgroundGrid<dim>       &grid,
                       const Membrane<dim>             &membrane,
                       const std::vector<double>       &cell_stiffness,
                       const std::vector<unsigned int> &occupied_cells,
                       NodalFields<dim>                &nodes,
                       const double                     dt_floor)
    {
      // Block Gershgorin bound on the membrane stiffness projected to the
      // grid: element blocks k [A -A; -A A] <= 2 k diag(A, A) and convex
      // transfer weights give K <= diag_i(D_i) with the directional
      // D_i = c0 sum_a N_i(x_a) K_a (Membrane::nodal_stiffness; c0 = 2.5
      // leaves a margin over the exact 2). The explicit update is stable if
      // m_i I + added_i >= dt^2 (D_i + k_p,i I) / 4: dt <= 2 sqrt((m_i +
      // added)/lambda) over the eigenpairs of D_i + k_p,i I, with the full
      // nodal mass (fluid included) and the points' stiffness k_p,i (the
      // same row-sum bound for V_p M_p grad N_i . grad N_j, M_p the P-wave
      // modulus). The accumulation uses added_mass as scratch.
      const double c0
        = (dim == 2)
            ? 2.5
            : 2.5 / (1. - std::pow(membrane.properties.poisson_ratio, 2));
      const std::vector<SymmetricTensor<2, dim>> k_node
        = membrane.nodal_stiffness();
      std::vector<unsigned int> touched;
      touched.reserve(membrane.n_nodes() * (dim + 1));
      for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
        {
          const unsigned int c      = membrane.cell[a];
          const auto        &lambda = membrane.weights[a];
          for (unsigned int k = 0; k < dim + 1; ++k)
            {
              const unsigned int i = grid.cell_nodes[c][k];
              nodes.added_mass[i] += (c0 * std::max(lambda[k], 0.)) * k_node[a];
              touched.push_back(i);
            }
        }
      std::sort(touched.begin(), touched.end());
      touched.erase(std::unique(touched.begin(), touched.end()), touched.end());

      // The points' row sums on the touched nodes.
      std::vector<double> k_points(touched.size(), 0.);
      if (!cell_stiffness.empty())
        for (const unsigned int c : occupied_cells)
          {
            const auto  &grad = grid.shape_gradients[c];
            const double S    = cell_stiffness[c];
            if (!(S > 0))
              continue;
            double row = 0;
            for (unsigned int k = 0; k < dim + 1; ++k)
              row += grad[k].norm();
            for (unsigned int k = 0; k < dim + 1; ++k)
              {
                const auto it = std::lower_bound(touched.begin(),
                                                 touched.end(),
                                                 grid.cell_nodes[c][k]);
                if (it != touched.end() && *it == grid.cell_nodes[c][k])
                  k_points[it - touched.begin()] += S * grad[k].norm() * row;
              }
          }

      double dt = std::numeric_limits<double>::max();
      for (unsigned int t = 0; t < touched.size(); ++t)
        {
          const unsigned int            i = touched[t];
          const SymmetricTensor<2, dim> D
            = nodes.added_mass[i] + k_points[t] * unit_symmetric_tensor<dim>();
          nodes.added_mass[i] = SymmetricTensor<2, dim>();
          const double m      = nodes.mass[i];
          if (m <= 0)
            continue;
          for (const auto &[k, e] : eigenvectors(D))
            if (k > 0)
              {
                // Fictitious inertia only in the directions that need it.
                const double added
                  = std::max(0.25 * k * dt_floor * dt_floor - m, 0.);
                if (added > 0)
                  nodes.added_mass[i]
                    += added * symmetrize(outer_product(e, e));
                dt = std::min(dt, 2. * std::sqrt((m + added) / k));
              }
        }
      return dt;
    }



    template <int dim>
    void
    membrane_g2p(const BackgroundGrid<dim> &grid,
                 const NodalFields<dim>    &nodes,
                 Membrane<dim>             &membrane)
    {
      // PIC: the node takes the grid velocity v^{n+1}. Its mass is
      // negligible, and PIC keeps its velocity free of noise.
      for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
        {
          const unsigned int c      = membrane.cell[a];
          const auto        &lambda = membrane.weights[a];
          Tensor<1, dim>     v;
          for (unsigned int k = 0; k < dim + 1; ++k)
            v += lambda[k] * nodes.velocity[grid.cell_nodes[c][k]];
          membrane.velocity[a] = v;
        }
    }



    template <int dim>
    void
    membrane_remap(const BackgroundGrid<dim> &grid,
                   const Membrane<dim>       &membrane,
                   NodalFields<dim>          &nodes)
    {
      for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
        {
          const unsigned int c      = membrane.cell[a];
          const auto        &lambda = membrane.weights[a];
          for (unsigned int k = 0; k < dim + 1; ++k)
            nodes.momentum[grid.cell_nodes[c][k]]
              += (lambda[k] * membrane.mass[a]) * membrane.velocity[a];
        }
    }



    template <int dim>
    double
    membrane_positions(const BackgroundGrid<dim> &grid,
                       const NodalFields<dim>    &nodes,
                       const double               dt,
                       Membrane<dim>             &membrane)
    {
      double ratio = 0;
      for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
        {
          const unsigned int c      = membrane.cell[a];
          const auto        &lambda = membrane.weights[a];
          Tensor<1, dim>     dx;
          for (unsigned int k = 0; k < dim + 1; ++k)
            dx += lambda[k] * nodes.velocity[grid.cell_nodes[c][k]];
          dx *= dt;
          membrane.position[a] += dx;
          ratio = std::max(ratio, dx.norm() / grid.cell_min_altitude[c]);
        }
      return ratio;
    }



    template <int dim>
    unsigned int
    membrane_relocate(const BackgroundGrid<dim> &grid,
                      const double               max_length,
                      Membrane<dim>             &membrane)
    {
      const unsigned int unknown = BackgroundGrid<dim>::invalid;
      if (membrane.tangential_slip)
        membrane.equalize_stretch();
      membrane.split_long_elements(max_length, unknown);
      const PointLocator<dim> locator(grid);
      unsigned int            outside = 0;
      for (unsigned int a = 0; a < membrane.n_nodes(); ++a)
        {
          // New nodes start the walk from cell 0 (rare: only after a split).
          const unsigned int guess
            = membrane.cell[a] == unknown ? 0 : membrane.cell[a];
          const unsigned int c = locator.locate(membrane.position[a], guess);
          if (c == unknown)
            ++outside;
          else
            membrane.cell[a] = c;
        }
      membrane.compute_forces();
      return outside;
    }

#define FSGMPM_INSTANTIATE(dim)                                                    \
  template void         membrane_p2g<dim>(const BackgroundGrid<dim> &,             \
                                  Membrane<dim> &,                         \
                                  NodalFields<dim> &);                     \
  template double       membrane_time_step<dim>(const BackgroundGrid<dim> &,       \
                                          const Membrane<dim> &,             \
                                          const std::vector<double> &,       \
                                          const std::vector<unsigned int> &, \
                                          NodalFields<dim> &,                \
                                          const double);                     \
  template void         membrane_g2p<dim>(const BackgroundGrid<dim> &,             \
                                  const NodalFields<dim> &,                \
                                  Membrane<dim> &);                        \
  template void         membrane_remap<dim>(const BackgroundGrid<dim> &,           \
                                    const Membrane<dim> &,                 \
                                    NodalFields<dim> &);                   \
  template double       membrane_positions<dim>(const BackgroundGrid<dim> &,       \
                                          const NodalFields<dim> &,          \
                                          const double,                      \
                                          Membrane<dim> &);                  \
  template unsigned int membrane_relocate<dim>(const BackgroundGrid<dim> &,        \
                                               const double,                       \
                                               Membrane<dim> &);
    FSGMPM_INSTANTIATE(2)
    FSGMPM_INSTANTIATE(3)
#undef FSGMPM_INSTANTIATE
  } // namespace Stages
} // namespace fsgmpm
