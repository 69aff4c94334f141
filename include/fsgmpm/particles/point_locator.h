#ifndef fsgmpm_particles_point_locator_h
#define fsgmpm_particles_point_locator_h

#include <fsgmpm/grid/background_grid.h>

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
    explicit PointLocator(const BackgroundGrid<dim> &grid,
                          const double               tolerance = 1e-12)
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
      unsigned int c = guess;
      for (unsigned int step = 0; step < max_walk_steps; ++step)
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
            break;
          c = next;
        }
      // The walk stays in the guess's velocity field; so does the search.
      const unsigned int found = grid.find_cell_brute_force(x, tolerance);
      return found == BackgroundGrid<dim>::invalid
               ? found
               : grid.cell_in_field(found, grid.field_of_cell(guess));
    }

    static constexpr unsigned int max_walk_steps = 64;

  private:
    const BackgroundGrid<dim> &grid;
    const double               tolerance;
  };
} // namespace fsgmpm

#endif
