#ifndef fsgmpm_grid_moving_wall_h
#define fsgmpm_grid_moving_wall_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/moving_wall_parameters.h>

#include <array>
#include <string>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * A rigid, frictionless plane wall moving in its own plane with a
   * prescribed, piecewise-linear velocity history (a lifted gate). It acts
   * like a slip wall of NodalConstraints on the grid nodes that lie in its
   * plane and inside its current extent: the velocity relative to the wall
   * may not point into it (unilateral), the tangential one is free. Because
   * the wall moves only in its own plane and is frictionless, its force
   * does no work, so the energy bookkeeping needs no wall term.
   *
   * The wall is one-sided: it holds the material on its material side. The
   * plane must pass through grid nodes (a grid line of a box mesh), which
   * the constructor checks.
   */
  template <int dim>
  class MovingWall
  {
  public:
    /// Throws if the wall's plane holds no grid node inside its extent, or
    /// cuts a cell there (the material would pass between its nodes).
    MovingWall(const MovingWallParameters &wall_parameters,
               const BackgroundGrid<dim>  &background_grid);

    /// Prescribed velocity at time @p t.
    Tensor<1, dim>
    velocity(const double t) const;

    /// Displacement from t = 0 to @p t (the exact integral of velocity()).
    Tensor<1, dim>
    displacement(const double t) const;

    /// Move the wall to time @p t: update its velocity and which nodes of
    /// its plane lie inside its extent.
    void
    set_time(const double t);

    bool
    is_active(const unsigned int node) const
    {
      AssertIndexRange(node, active.size());
      return active[node] != 0;
    }

    /// Unit normal from the material into the wall.
    const Tensor<1, dim> &
    outward_normal() const
    {
      return normal;
    }

    const Tensor<1, dim> &
    current_velocity() const
    {
      return wall_velocity;
    }

    /// The grid nodes in the wall's plane (whether inside its extent or
    /// not).
    const std::vector<unsigned int> &
    nodes_in_plane() const
    {
      return plane_nodes;
    }

    /// Number of grid nodes the wall acts on at the current time.
    unsigned int
    n_active_nodes() const
    {
      return n_active;
    }

  private:
    MovingWallParameters       parameters;
    const BackgroundGrid<dim> &grid;
    Tensor<1, dim>             normal;
    Tensor<1, dim>             wall_velocity;
    /// Tolerance of "on the plane" and "inside the extent" (m): 1e-6 of
    /// the mesh's shortest edge.
    double tolerance;
    /// Grid nodes in the wall's plane (any extent).
    std::vector<unsigned int>  plane_nodes;
    std::vector<unsigned char> active;
    unsigned int               n_active = 0;
  };
} // namespace fsgmpm

#endif
