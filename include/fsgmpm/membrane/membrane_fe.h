#ifndef fsgmpm_membrane_membrane_fe_h
#define fsgmpm_membrane_membrane_fe_h

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_simplex_p.h>

#include <deal.II/grid/tria.h>

#include <array>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * The membrane's internal forces on deal.II's finite-element machinery:
   * FE_SimplexP of
   * degree 1 or 2 on the membrane's codim-1 triangulation (cables: lines in
   * 2D; surfaces: triangles in 3D), total Lagrangian on the rest geometry,
   * forces by FEValues quadrature. The node values are the current
   * positions of the support points (one scalar DoF per support point,
   * dim components stored per point), so the element is the vector-valued
   * P_k of the membrane.
   *
   * Material law, as MembraneMechanics (the hand-written elements, the
   * reference this reproduces at degree 1):
   * - 2D cables: T = EA max(0, lambda - 1) with the stretch lambda = |F t|
   *   (engineering strain, tension only);
   * - 3D: Green-Lagrange E = (F^T F - I)/2 in an orthonormal frame of the
   *   rest surface, plane-stress Saint Venant-Kirchhoff S, the compression
   *   cut-off of Eqs. (9)-(10) on S, and f_i = -int S_ab (F t_a)
   *   (grad N_i . t_b) dA.
   * The forces are those ON the support points (-dW/dx).
   *
   * Total Lagrangian on a fixed rest geometry, the isoparametric cells
   * through the rest support points: the shape-function derivatives along
   * the rest tangents and the JxW values never change, so they are computed
   * once (set_rest_support_points()) and the forces are then pure
   * arithmetic on the current positions.
   */
  template <int dim>
  class MembraneFE
  {
  public:
    /// @p rest: the membrane at rest (copied); EA = E thickness (N/m);
    /// @p nu the Poisson ratio (3D only). Throws on degree other than 1
    /// or 2, or on EA or nu out of range.
    MembraneFE(const Triangulation<dim - 1, dim> &rest,
               const unsigned int                 degree,
               const double                       EA,
               const double                       nu);

    unsigned int
    n_support_points() const
    {
      return rest_points.size();
    }

    /// Rest positions of the support points, in DoF order.
    const std::vector<Point<dim>> &
    rest_support_points() const
    {
      return rest_points;
    }

    /// Makes @p X (one point per support point, DoF order) the rest
    /// geometry: the rest cells become the isoparametric cells through
    /// them, curved at degree 2. The constructor uses the triangulation's
    /// straight cells (the edge midpoints at degree 2).
    void
    set_rest_support_points(const std::vector<Point<dim>> &X);

    /// Forces on the support points for the current positions @p x (same
    /// order as rest_support_points()).
    std::vector<Tensor<1, dim>>
    internal_forces(const std::vector<Point<dim>> &x) const;

    /// As above, into @p force (resized). If @p cell_stress is given, it
    /// receives per active cell (active_cell_index order) the principal
    /// Cauchy membrane stresses {major, minor} (N/m) averaged over the
    /// cell's quadrature points with their weights: the cable tension
    /// EA max(0, lambda - 1) in 2D (minor 0); in 3D the eigenvalues of
    /// sigma = F S F^T / J in the current tangent plane, after the
    /// cut-off. If @p cell_tension_tensor is given, it receives per active
    /// cell the same average of sigma itself (N/m, in x-y-z: T t t^T for a
    /// cable of direction t), from which any component can be taken, e.g.
    /// the hoop tension of a tube.
    void
    internal_forces(const std::vector<Point<dim>>        &x,
                    std::vector<Tensor<1, dim>>          &force,
                    std::vector<std::array<double, 2>>   *cell_stress,
                    std::vector<SymmetricTensor<2, dim>> *cell_tension_tensor
                    = nullptr) const;

    /// Strain energy for the positions @p x: 2D cables, the quadrature of
    /// EA/2 max(0, lambda - 1)^2 over the rest length; 3D, of S : E / 2
    /// (the Saint Venant-Kirchhoff energy where the membrane is taut; with
    /// the compression cut-off, that of the stress kept). internal_forces()
    /// is its negative gradient wherever no cut-off acts. The slip at degree
    /// 2 accepts a move only if it lowers this (MembraneSlip).
    double
    strain_energy(const std::vector<Point<dim>> &x) const;

    /// Lumped mass of each support point for the areal mass @p mu (kg/m^2,
    /// kg/m for cables): the diagonal of the consistent mass matrix scaled
    /// to the element's mass (HRZ lumping: positive at every node, also at
    /// the vertices of quadratic triangles where row sums are zero).
    std::vector<double>
    lumped_masses(const double mu) const;

    const DoFHandler<dim - 1, dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    unsigned int
    get_degree() const
    {
      return fe.degree;
    }

  private:
    Triangulation<dim - 1, dim> triangulation;
    FE_SimplexP<dim - 1, dim>   fe;
    Quadrature<dim - 1>         quadrature;
    DoFHandler<dim - 1, dim>    dof_handler;
    std::vector<Point<dim>>     rest_points;
    double                      EA, nu;

    // Precomputed on the rest geometry, per active cell c and quadrature
    // point q (n_q per cell): the cell's DoFs, JxW and, per DoF i and rest
    // tangent a, dN_i/dt_a at [((c n_q + q) n_dofs + i) (dim - 1) + a].
    unsigned int                         n_q_points;
    std::vector<types::global_dof_index> cell_dofs;
    std::vector<double>                  JxW;
    std::vector<double>                  tangent_derivative;
    /// N_i at the quadrature points of the reference cell, [q n_dofs + i].
    std::vector<double> shape_value;
  };
} // namespace fsgmpm

#endif
