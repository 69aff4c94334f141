#ifndef fsgmpm_grid_cell_geometry_h
#define fsgmpm_grid_cell_geometry_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>
#include <limits>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * The affine data of one simplex (triangle or tetrahedron) with vertices
   * x_0..x_dim, computed from its vertices when a loop reaches the cell:
   * the grid stores only node positions and connectivity (a stored inverse
   * and volume cost 40 B per triangle, 80 B per tetrahedron, and made up
   * most of the grid's memory).
   *
   * For linear simplices the shape function of vertex k at x is its
   * barycentric coordinate lambda_k(x) and its gradient is constant: the
   * rows of the inverse A of the edge matrix E = [x_1 - x_0, ...] are the
   * gradients of lambda_1..lambda_dim (lambda_k = grad lambda_k . (x - x_0)),
   * and lambda_0 = 1 - sum, whose gradient is minus theirs. So point
   * location and all particle-grid transfers use these gradients, never a
   * mapping's Newton iteration. Negatively oriented cells (Gmsh tets) need
   * no special care: A inverts E whatever the sign of its determinant.
   */
  template <int dim>
  struct CellGeometry
  {
    /// Zero (room in an array, e.g. ParticleStore's cache, filled later).
    CellGeometry() = default;

    /// From the vertices; the same arithmetic wherever a cell's geometry is
    /// needed, so every loop sees the same bits.
    CellGeometry(const std::array<Point<dim>, dim + 1> &x)
      : x0(x[0])
    {
      const Tensor<2, dim> edges = edge_matrix(x);
      volume                     = volume_of(edges);
      inverse_edges              = invert(edges);
    }

    /// The edge matrix E, columns x_k - x_0.
    static Tensor<2, dim>
    edge_matrix(const std::array<Point<dim>, dim + 1> &x)
    {
      Tensor<2, dim> edges;
      for (unsigned int k = 0; k < dim; ++k)
        for (unsigned int d = 0; d < dim; ++d)
          edges[d][k] = x[k + 1][d] - x[0][d];
      return edges;
    }

    /// The simplex's volume |det E| / dim!.
    static double
    volume_of(const Tensor<2, dim> &edges)
    {
      double factorial = 1;
      for (unsigned int d = 2; d <= dim; ++d)
        factorial *= d;
      return std::abs(determinant(edges)) / factorial;
    }

    /// Barycentric coordinates of @p x (the shape function values).
    std::array<double, dim + 1>
    barycentric(const Point<dim> &x) const
    {
      std::array<double, dim + 1> lambda;
      const Tensor<1, dim>        d   = x - x0;
      double                      sum = 0;
      for (unsigned int k = 0; k < dim; ++k)
        {
          lambda[k + 1] = inverse_edges[k] * d;
          sum += lambda[k + 1];
        }
      lambda[0] = 1. - sum;
      return lambda;
    }

    /// Gradients of the dim + 1 shape functions (constant over the cell).
    std::array<Tensor<1, dim>, dim + 1>
    shape_gradients() const
    {
      std::array<Tensor<1, dim>, dim + 1> g;
      for (unsigned int k = 0; k < dim; ++k)
        {
          g[k + 1] = inverse_edges[k];
          g[0] -= inverse_edges[k];
        }
      return g;
    }

    /// max_k |grad lambda_k|^2, the inverse square of the smallest
    /// altitude: a bound on a length squared relative to the cell without
    /// a root or a division (the position update's guard).
    double
    inverse_square_min_altitude() const
    {
      double     largest = 0;
      const auto g       = shape_gradients();
      for (unsigned int k = 0; k < dim + 1; ++k)
        largest = std::max(largest, g[k].norm_square());
      return largest;
    }

    /// Smallest altitude, min_k 1/|grad lambda_k| (time step, guards),
    /// as 1/sqrt(max_k |grad lambda_k|^2): one root and one division, the
    /// same bits (rounded sqrt and division are monotone).
    double
    min_altitude() const
    {
      return std::min(std::numeric_limits<double>::max(),
                      1. / std::sqrt(inverse_square_min_altitude()));
    }

    Point<dim>     x0;
    Tensor<2, dim> inverse_edges;
    double         volume = 0;
  };
} // namespace fsgmpm

#endif
