#ifndef fsgmpm_particles_point_locator_h
#define fsgmpm_particles_point_locator_h

#include <fsgmpm/grid/background_grid.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <utility>

namespace fsgmpm
{
  /**
   * Point location on the simplex background grid: the exact barycentric
   * test of the per-cell affine inverse, starting from a guess cell and
   * walking across the face with the most negative barycentric coordinate.
   * If the walk leaves the mesh or does not settle, all cells are tested
   * (needed for non-convex domains), so the answer is always exact: the
   * returned cell contains the point up to @p tolerance in every barycentric
   * coordinate, or BackgroundGrid::invalid if no cell does.
   */
  template <int dim>
  class PointLocator
  {
  public:
    static constexpr double default_tolerance = 1e-12;

    explicit PointLocator(const BackgroundGrid<dim> &grid,
                          const double tolerance = default_tolerance)
      : grid(grid)
      , tolerance(tolerance)
    {}

    unsigned int
    locate(const Point<dim> &x, const unsigned int guess) const
    {
      return locate(x, guess, grid.geometry(guess));
    }

    /// The same, with the geometry of the guess cell known (points of one
    /// cell in a row compute it once).
    unsigned int
    locate(const Point<dim>        &x,
           const unsigned int       guess,
           const CellGeometry<dim> &guess_geometry) const
    {
      const unsigned int c = walk(x, guess, guess_geometry, true);
      return c != BackgroundGrid<dim>::invalid
               ? c
               : search(x, guess, BackgroundGrid<dim>::invalid);
    }

    /// locate(x, guess)'s answer, found faster where the walk from @p guess
    /// does not settle: instead of testing all cells, the search starts
    /// from the cell a walk from @p hint (a cell near x) reaches and tests
    /// the cells around it that hold x (BackgroundGrid::best_cell_around():
    /// the same cell as find_cell_brute_force()). The membrane's nodes,
    /// located from cell 0 at the start, take the previous node's cell as
    /// the hint (the geotube at 1 cm, 422 400 cells: 6 s less set-up).
    unsigned int
    locate(const Point<dim>  &x,
           const unsigned int guess,
           const unsigned int hint) const
    {
      const unsigned int c = walk(x, guess, grid.geometry(guess), true);
      return c != BackgroundGrid<dim>::invalid
               ? c
               : search(x, guess, walk(x, hint));
    }

    /// The walk of locate() alone: the cell it settles in, or invalid if
    /// it leaves the cells this grid holds or does not settle (no search).
    /// On a window, the membrane's location (MembraneCoupling::relocate())
    /// combines the walks and searches of all processes.
    /// A longer walk (@p max_steps) answers "is x in the mesh?" for a
    /// point far from @p guess in a convex mesh.
    unsigned int
    walk(const Point<dim>  &x,
         const unsigned int guess,
         const unsigned int max_steps = max_walk_steps) const
    {
      return walk(x, guess, grid.geometry(guess), false, max_steps);
    }

    static constexpr unsigned int max_walk_steps = 64;

  private:
    const BackgroundGrid<dim> &grid;
    const double               tolerance;

    /// locate()'s search after a walk from @p guess that did not settle:
    /// of all cells, or (if @p near, a cell that holds x, is valid) of the
    /// cells around @p near, which gives the same cell. The walk stays in
    /// the guess's velocity field; so does the search.
    unsigned int
    search(const Point<dim>  &x,
           const unsigned int guess,
           const unsigned int near) const
    {
      const unsigned int found
        = near == BackgroundGrid<dim>::invalid
            ? grid.find_cell_brute_force(x, tolerance)
            : grid.best_cell_around(x, tolerance, grid.cell_in_field(near, 0));
      return found == BackgroundGrid<dim>::invalid
               ? found
               : grid.cell_in_field(found, grid.field_of_cell(guess));
    }

    /// The walk from @p guess across the face with the most negative
    /// barycentric coordinate. If @p stop_beyond_window, a walk out through
    /// a window's edge stops the run (check_not_beyond_window()).
    unsigned int
    walk(const Point<dim>        &x,
         const unsigned int       guess,
         const CellGeometry<dim> &guess_geometry,
         const bool               stop_beyond_window,
         const unsigned int       max_steps = max_walk_steps) const
    {
      unsigned int c = guess;
      for (unsigned int step = 0; step < max_steps; ++step)
        {
          const auto   lambda = step == 0 ? guess_geometry.barycentric(x)
                                          : grid.barycentric(c, x);
          unsigned int kmin   = 0;
          for (unsigned int k = 1; k < dim + 1; ++k)
            if (lambda[k] < lambda[kmin])
              kmin = k;
          if (lambda[kmin] >= -tolerance)
            return c;
          const unsigned int next = grid.cell_neighbors[c][kmin];
          if (next == BackgroundGrid<dim>::invalid)
            {
              if (stop_beyond_window)
                check_not_beyond_window(x, c, kmin);
              break;
            }
          c = next;
        }
      return BackgroundGrid<dim>::invalid;
    }

    /// MPI: in a process's window of the grid a face without a neighbour
    /// is either the mesh's boundary or the edge of the window. A point
    /// that walks out through the edge has left the cells the process
    /// holds (a step moves a point less than its cell's smallest altitude,
    /// so this takes a sliver cell beside it): the whole grid would find
    /// it, the window cannot. Stop rather than count it as lost.
    void
    check_not_beyond_window(const Point<dim>  &x,
                            const unsigned int c,
                            const unsigned int face) const
    {
      if (!grid.is_window())
        return;
      // boundary_faces are sorted by cell, then face.
      const auto key = std::make_pair(c % grid.n_base_cells(), face);
      const auto it
        = std::lower_bound(grid.boundary_faces.begin(),
                           grid.boundary_faces.end(),
                           key,
                           [](const auto                                  &f,
                              const std::pair<unsigned int, unsigned int> &k) {
                             return std::make_pair(f.cell, f.vertex) < k;
                           });
      if (it != grid.boundary_faces.end() && it->cell == key.first
          && it->vertex == face)
        return;
      std::ostringstream where;
      where << x;
      AssertThrow(false,
                  ExcMessage("A point at (" + where.str()
                             + ") moved beyond its MPI process's ghost layer "
                               "of the grid in one step (from cell "
                             + std::to_string(grid.global_cell(c))
                             + " of the mesh). Lower Simulation/Courant "
                               "number, or mend the sliver cells of the "
                               "mesh there."));
    }
  };
} // namespace fsgmpm

#endif
