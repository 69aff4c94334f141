#ifndef fsgmpm_particles_body_filler_h
#define fsgmpm_particles_body_filler_h

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/particles/body_shape.h>
#include <fsgmpm/particles/particle_store.h>

#include <array>
#include <vector>

namespace fsgmpm
{
  /**
   * Barycentric coordinates of the material points placed in one simplex:
   * the centroids of the children of L levels of regular (Bey) refinement,
   * so (2^dim)^L points of exactly equal volume share. Throws if
   * @p particles_per_cell is not 1, 4, 16, 64 (2D) or 1, 8, 64, 512 (3D).
   */
  template <int dim>
  std::vector<std::array<double, dim + 1>>
  reference_particle_points(const unsigned int particles_per_cell);

  /**
   * Fill @p shape with material points: every sub-cell centroid of every
   * background cell that lies inside the shape becomes a point with volume
   * (cell volume / particles per cell) and mass density * volume, unless
   * it lies inside one of the shapes in @p taken (the regions of bodies
   * filled before: bodies fill in order, so a water tank around a bag does
   * not put a second mass where the bag is). Throws if the shape reaches
   * outside the mesh or holds no point. Returns the number of points of
   * the body.
   *
   * With MPI a process stores only the points of its own cells: with
   * @p keep_cell (one flag per base cell), the points of the other cells
   * are not stored, but take their ids (particles.next_id advances), so
   * that every point has the id of a serial run's fill. With
   * @p points_per_base_cell the body's points of each base cell are added
   * to it, stored or not.
   *
   * On a process's window of the grid (BackgroundGrid::window()) the
   * cells before a cell may be missing, so @p first_id gives the id of
   * the body's first point in each base cell (as the whole grid's fill
   * numbers them), and the checks on the whole body (inside the mesh, not
   * empty) are left to the process that fills the whole grid.
   */
  template <int dim>
  unsigned int
  fill_body(const BackgroundGrid<dim>                 &grid,
            const BodyShape<dim>                      &shape,
            const unsigned int                         particles_per_cell,
            const double                               density,
            const Tensor<1, dim>                      &initial_velocity,
            const std::uint16_t                        material_id,
            const std::uint16_t                        body_id,
            ParticleStore<dim>                        &particles,
            const std::vector<const BodyShape<dim> *> &taken      = {},
            const std::vector<std::uint8_t>           *keep_cell  = nullptr,
            std::vector<unsigned int>       *points_per_base_cell = nullptr,
            const std::vector<unsigned int> *first_id             = nullptr);

  /**
   * Height of the surface of @p shape above the inside point @p x: the
   * first y above x (same x, z) where the vertical line leaves the shape,
   * at most @p y_top (the shape's highest point), to @p tolerance
   * (bisection after steps of @p step). The depth of a point below its
   * body's own top, for the geostatic stress under a sloped or curved
   * surface.
   */
  template <int dim>
  double
  surface_height_above(const BodyShape<dim> &shape,
                       const Point<dim>     &x,
                       const double          y_top,
                       const double          step,
                       const double          tolerance);
} // namespace fsgmpm

#endif
