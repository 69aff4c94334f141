#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/mapping_fe.h>

#include <fsgmpm/membrane/membrane_fe.h>
#include <fsgmpm/membrane/membrane_mechanics.h>

#include <cmath>
#include <map>

namespace fsgmpm
{
  namespace
  {
    unsigned int
    checked_degree(const unsigned int degree)
    {
      AssertThrow(degree == 1 || degree == 2,
                  ExcMessage("Membrane/Element degree must be 1 or 2; got "
                             + std::to_string(degree) + "."));
      return degree;
    }

    // The deformed tangents g_a = F t_a = sum_i x_i dN_i/dt_a at one
    // quadrature point, from its shape derivatives @p dN (dN[i][a] = grad
    // N_i . t_a on the rest surface) and the cell's support points @p dofs.
    template <int dim>
    std::array<Tensor<1, dim>, dim - 1>
    deformed_tangents(const double                  *dN,
                      const types::global_dof_index *dofs,
                      const unsigned int             n_dofs,
                      const std::vector<Point<dim>> &x)
    {
      std::array<Tensor<1, dim>, dim - 1> g;
      for (unsigned int i = 0; i < n_dofs; ++i)
        for (unsigned int a = 0; a < dim - 1; ++a)
          g[a] += dN[i * (dim - 1) + a] * x[dofs[i]];
      return g;
    }
  } // namespace



  template <int dim>
  MembraneFE<dim>::MembraneFE(const Triangulation<dim - 1, dim> &rest,
                              const unsigned int                 degree,
                              const double                       EA,
                              const double                       nu)
    : fe(checked_degree(degree))
    // Degree 1 has a constant strain per cell: its one-point rule is exact
    // for the forces, and HRZ lumping gives the exact mass L/2 or A/3 per
    // vertex by symmetry with any symmetric rule. Degree 2 keeps
    // QGaussSimplex(3), exact for the quartic N_i N_j on straight cells.
    , quadrature(QGaussSimplex<dim - 1>(degree == 1 ? 1 : degree + 1))
    , EA(EA)
    , nu(nu)
  {
    AssertThrow(std::isfinite(EA) && EA > 0,
                ExcMessage("Membrane: the stiffness EA must be positive and "
                           "finite."));
    AssertThrow(dim == 2 || (nu > -1 && nu < 1),
                ExcMessage("Membrane: the Poisson ratio must lie in (-1, 1) "
                           "(plane stress)."));
    triangulation.copy_triangulation(rest);
    dof_handler.reinit(triangulation);
    dof_handler.distribute_dofs(fe);
    // The rest geometry is the triangulation's (straight-sided cells); the
    // support points of degree 2 are the edge midpoints.
    rest_points.resize(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(MappingFE<dim - 1, dim>(
                                           FE_SimplexP<dim - 1, dim>(1)),
                                         dof_handler,
                                         rest_points);

    n_q_points = quadrature.size();
    cell_dofs.resize(triangulation.n_active_cells() * fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        std::copy(dofs.begin(),
                  dofs.end(),
                  cell_dofs.begin()
                    + cell->active_cell_index() * fe.n_dofs_per_cell());
      }
    set_rest_support_points(rest_points);
  }



  template <int dim>
  void
  MembraneFE<dim>::set_rest_support_points(const std::vector<Point<dim>> &X)
  {
    AssertThrow(X.size() == n_support_points(),
                ExcMessage("MembraneFE: one rest position per support point "
                           "is needed."));
    rest_points = X;
    // The isoparametric map of the rest cell, X(xi) = sum_i X_i N_i(xi),
    // at each quadrature point: its Jacobian J (dim x dim-1), the area
    // element sqrt(det J^T J), an orthonormal tangent frame t_a (Gram-Schmidt
    // on J's columns) and the surface gradients grad N_i = J (J^T J)^-1
    // grad_xi N_i, stored as dN_i/dt_a.
    const unsigned int n_dofs  = fe.n_dofs_per_cell();
    const unsigned int n_cells = triangulation.n_active_cells();
    JxW.assign(n_cells * n_q_points, 0.);
    tangent_derivative.assign(n_cells * n_q_points * n_dofs * (dim - 1), 0.);
    shape_value.resize(n_q_points * n_dofs);
    std::vector<Tensor<1, dim - 1>> grad_xi(n_q_points * n_dofs);
    for (unsigned int q = 0; q < n_q_points; ++q)
      for (unsigned int i = 0; i < n_dofs; ++i)
        {
          shape_value[q * n_dofs + i] = fe.shape_value(i, quadrature.point(q));
          grad_xi[q * n_dofs + i]     = fe.shape_grad(i, quadrature.point(q));
        }
    for (unsigned int c = 0; c < n_cells; ++c)
      for (unsigned int q = 0; q < n_q_points; ++q)
        {
          const unsigned int cq = c * n_q_points + q;
          Tensor<2, dim>     J; // columns 0 .. dim-2 used
          for (unsigned int i = 0; i < n_dofs; ++i)
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int a = 0; a < dim - 1; ++a)
                J[d][a] += X[cell_dofs[c * n_dofs + i]][d]
                           * grad_xi[q * n_dofs + i][a];
          // Metric G = J^T J and its inverse.
          Tensor<2, dim - 1> G;
          for (unsigned int a = 0; a < dim - 1; ++a)
            for (unsigned int b = 0; b < dim - 1; ++b)
              for (unsigned int d = 0; d < dim; ++d)
                G[a][b] += J[d][a] * J[d][b];
          const double det_G = determinant(G);
          AssertThrow(det_G > 0,
                      ExcMessage("Membrane: a cell of the rest membrane is "
                                 "degenerate (zero length or area)."));
          const Tensor<2, dim - 1> G_inverse = invert(G);
          JxW[cq] = quadrature.weight(q) * std::sqrt(det_G);
          std::array<Tensor<1, dim>, dim - 1> t;
          for (unsigned int a = 0; a < dim - 1; ++a)
            {
              for (unsigned int d = 0; d < dim; ++d)
                t[a][d] = J[d][a];
              for (unsigned int b = 0; b < a; ++b)
                t[a] -= (t[a] * t[b]) * t[b];
              t[a] /= t[a].norm();
            }
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              // grad N_i = J G^-1 grad_xi N_i.
              const Tensor<1, dim - 1> h = G_inverse * grad_xi[q * n_dofs + i];
              Tensor<1, dim>           grad;
              for (unsigned int d = 0; d < dim; ++d)
                for (unsigned int a = 0; a < dim - 1; ++a)
                  grad[d] += J[d][a] * h[a];
              for (unsigned int a = 0; a < dim - 1; ++a)
                tangent_derivative[(cq * n_dofs + i) * (dim - 1) + a]
                  = grad * t[a];
            }
        }
  }



  template <int dim>
  std::vector<Tensor<1, dim>>
  MembraneFE<dim>::internal_forces(const std::vector<Point<dim>> &x) const
  {
    std::vector<Tensor<1, dim>> force;
    internal_forces(x, force, nullptr);
    return force;
  }



  template <int dim>
  void
  MembraneFE<dim>::internal_forces(
    const std::vector<Point<dim>>        &x,
    std::vector<Tensor<1, dim>>          &force,
    std::vector<std::array<double, 2>>   *cell_stress,
    std::vector<SymmetricTensor<2, dim>> *cell_tension_tensor) const
  {
    AssertThrow(x.size() == n_support_points(),
                ExcMessage("MembraneFE: one position per support point "
                           "is needed."));
    force.assign(n_support_points(), Tensor<1, dim>());
    const unsigned int n_dofs  = fe.n_dofs_per_cell();
    const unsigned int n_cells = triangulation.n_active_cells();
    if (cell_stress)
      cell_stress->assign(n_cells, {{0., 0.}});
    if (cell_tension_tensor)
      cell_tension_tensor->assign(n_cells, SymmetricTensor<2, dim>());
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        const types::global_dof_index *dofs = &cell_dofs[c * n_dofs];
        double                         area = 0;
        std::array<double, 2>          stress{{0., 0.}};
        SymmetricTensor<2, dim>        sigma_sum;
        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            const unsigned int cq = c * n_q_points + q;
            // dN[i][a] = grad N_i . t_a on the rest surface.
            const double *dN = &tangent_derivative[cq * n_dofs * (dim - 1)];
            const std::array<Tensor<1, dim>, dim - 1> g
              = deformed_tangents(dN, dofs, n_dofs, x);
            // P t_b: the first Piola-Kirchhoff stress against the rest
            // tangents, f_i = -int sum_b (P t_b) dN_i/dt_b dA.
            std::array<Tensor<1, dim>, dim - 1> P;
            std::array<double, 2>               principal{{0., 0.}};
            if constexpr (dim == 2)
              {
                const double stretch = g[0].norm();
                const double T       = EA * std::max(0., stretch - 1.);
                if (stretch > 0)
                  P[0] = (T / stretch) * g[0];
                principal[0] = T;
                if (cell_tension_tensor && stretch > 0)
                  sigma_sum += (JxW[cq] * T / (stretch * stretch))
                               * symmetrize(outer_product(g[0], g[0]));
              }
            else
              {
                const MembraneMechanics::PlaneStress S
                  = MembraneMechanics::cut_off_svk_stress(g[0], g[1], EA, nu);
                P[0] = S[0] * g[0] + S[2] * g[1];
                P[1] = S[2] * g[0] + S[1] * g[1];
                if (cell_stress)
                  {
                    // sigma = G S G^T / J (G = [g0 g1]) has the nonzero
                    // eigenvalues of S C / J, C = G^T G (similar to the
                    // symmetric C^1/2 S C^1/2): from its trace and
                    // determinant.
                    const double C00 = g[0] * g[0], C11 = g[1] * g[1],
                                 C01   = g[0] * g[1];
                    const double det_C = C00 * C11 - C01 * C01;
                    if (det_C > 1e-24 * (C00 + C11) * (C00 + C11))
                      {
                        const double J = std::sqrt(det_C);
                        const double tr
                          = (S[0] * C00 + 2 * S[2] * C01 + S[1] * C11) / J;
                        const double det
                          = (S[0] * S[1] - S[2] * S[2]) * det_C / (J * J);
                        const double root
                          = std::sqrt(std::max(0., 0.25 * tr * tr - det));
                        principal = {{0.5 * tr + root, 0.5 * tr - root}};
                      }
                  }
                if (cell_tension_tensor)
                  {
                    // sigma = G S G^T / J, J the area ratio.
                    const double J = cross_product_3d(g[0], g[1]).norm();
                    if (J > 0)
                      sigma_sum
                        += (JxW[cq] / J)
                           * (S[0] * symmetrize(outer_product(g[0], g[0]))
                              + S[1] * symmetrize(outer_product(g[1], g[1]))
                              + S[2]
                                  * (2.
                                     * symmetrize(outer_product(g[0], g[1]))));
                  }
              }
            const double w = JxW[cq];
            for (unsigned int i = 0; i < n_dofs; ++i)
              for (unsigned int b = 0; b < dim - 1; ++b)
                force[dofs[i]] -= (w * dN[i * (dim - 1) + b]) * P[b];
            area += w;
            stress[0] += w * principal[0];
            stress[1] += w * principal[1];
          }
        if (cell_stress)
          (*cell_stress)[c] = {{stress[0] / area, stress[1] / area}};
        if (cell_tension_tensor)
          (*cell_tension_tensor)[c] = sigma_sum / area;
      }
  }



  template <int dim>
  double
  MembraneFE<dim>::strain_energy(const std::vector<Point<dim>> &x) const
  {
    AssertThrow(x.size() == n_support_points(),
                ExcMessage("MembraneFE: one position per support point "
                           "is needed."));
    const unsigned int n_dofs = fe.n_dofs_per_cell();
    double             energy = 0;
    for (unsigned int c = 0; c < triangulation.n_active_cells(); ++c)
      for (unsigned int q = 0; q < n_q_points; ++q)
        {
          const unsigned int                        cq = c * n_q_points + q;
          const std::array<Tensor<1, dim>, dim - 1> g
            = deformed_tangents(&tangent_derivative[cq * n_dofs * (dim - 1)],
                                &cell_dofs[c * n_dofs],
                                n_dofs,
                                x);
          if constexpr (dim == 2)
            {
              const double strain = std::max(0., g[0].norm() - 1.);
              energy += 0.5 * EA * strain * strain * JxW[cq];
            }
          else
            {
              // S : E / 2 with the Green strain E_ab = (g_a . g_b - d_ab)/2:
              // the Saint Venant-Kirchhoff energy where the membrane is taut
              // (internal_forces() is then its negative gradient); with the
              // cut-off, the energy of the stress that is kept.
              const MembraneMechanics::PlaneStress S
                = MembraneMechanics::cut_off_svk_stress(g[0], g[1], EA, nu);
              const double E00 = 0.5 * (g[0] * g[0] - 1.),
                           E11 = 0.5 * (g[1] * g[1] - 1.),
                           E01 = 0.5 * g[0] * g[1];
              energy
                += 0.5 * (S[0] * E00 + S[1] * E11 + 2. * S[2] * E01) * JxW[cq];
            }
        }
    return energy;
  }



  template <int dim>
  std::vector<double>
  MembraneFE<dim>::lumped_masses(const double mu) const
  {
    // HRZ: the diagonal of the consistent mass matrix (at degree 2 by a
    // quadrature exact for N_i N_j on straight cells; at degree 1 the
    // one-point rule gives equal diagonals, hence the exact equal shares),
    // scaled to the cell's mass.
    std::vector<double> mass(n_support_points(), 0.);
    const unsigned int  n_dofs = fe.n_dofs_per_cell();
    std::vector<double> diagonal(n_dofs);
    for (unsigned int c = 0; c < triangulation.n_active_cells(); ++c)
      {
        double cell_mass = 0, diagonal_sum = 0;
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            diagonal[i] = 0;
            for (unsigned int q = 0; q < n_q_points; ++q)
              diagonal[i] += mu * shape_value[q * n_dofs + i]
                             * shape_value[q * n_dofs + i]
                             * JxW[c * n_q_points + q];
            diagonal_sum += diagonal[i];
          }
        for (unsigned int q = 0; q < n_q_points; ++q)
          cell_mass += mu * JxW[c * n_q_points + q];
        for (unsigned int i = 0; i < n_dofs; ++i)
          mass[cell_dofs[c * n_dofs + i]]
            += diagonal[i] * cell_mass / diagonal_sum;
      }
    return mass;
  }



  template class MembraneFE<2>;
  template class MembraneFE<3>;
} // namespace fsgmpm
