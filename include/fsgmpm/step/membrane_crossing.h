#ifndef fsgmpm_step_membrane_crossing_h
#define fsgmpm_step_membrane_crossing_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <fsgmpm/grid/nodal_fields.h>
#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/particles/particle_store.h>

#include <array>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * The membrane as a wall for the material points themselves. The
   * coupling through the shared grid nodes (paper Section 2.1.2) keeps the
   * fill and the water apart only as far as the grid's linear velocity
   * field can: a point near the membrane moves with the velocity
   * interpolated in its cell, the membrane nodes with that of theirs, and
   * where the two differ (a cell cut by the membrane holds points of both
   * sides) a point can pass through an element within a step. This stage
   * finds those passes on the points' own paths and undoes them.
   *
   * Over a step every point and every membrane node moves on a straight
   * line (x + t dx, t in [0, 1]). A point crosses an element (a segment in
   * 2D, a triangle in 3D, Membrane::elements) if its signed distance to the
   * element's line or plane changes sign over the step and, at the time it
   * is zero, the point lies on the element (continuous collision detection;
   * the zero is found by bisection of the exact distance). A crossed point
   * is put back on its side of the element at the end of the step, a
   * hundredth of the element's size from it, and its velocity relative to
   * the element loses the normal part that carried it across (an inelastic
   * contact; the kinetic energy it takes is booked as numerical
   * dissipation).
   *
   * Usage, inside the step: remember_start() before the points and the
   * membrane nodes move, keep_points_on_their_side() after both moved and
   * before the points are relocated to their cells (the point indices must
   * not change in between). Only the points that can reach the membrane
   * within the step are followed: those within 2 dt max|v_i| (the largest
   * relative displacement of a point and a membrane node, v_i the grid
   * velocities both move with) of the membrane's bounding box. MPI: every
   * process holds the whole membrane and follows its own points.
   */
  template <int dim>
  class MembraneCrossing
  {
  public:
    explicit MembraneCrossing(const Membrane<dim> &membrane);

    /// Remembers the membrane nodes' positions and the points that may
    /// reach the membrane before the position update with the grid
    /// velocities of @p nodes over @p dt.
    void
    remember_start(const NodalFields<dim>   &nodes,
                   const ParticleStore<dim> &particles,
                   const double              dt);

    struct Outcome
    {
      /// Points put back on their side of the membrane.
      unsigned int corrected = 0;
      /// Kinetic energy their velocity corrections removed (J, J/m in 2D).
      double kinetic_energy_removed = 0;
    };

    /// Finds the points that crossed an element since remember_start() and
    /// puts them back (see the class comment).
    Outcome
    keep_points_on_their_side(const double dt, ParticleStore<dim> &particles);

  private:
    const Membrane<dim> &membrane;
    /// The membrane nodes at the start of the step.
    std::vector<Point<dim>> start_node;
    /// The followed points and their start positions.
    std::vector<unsigned int> followed;
    std::vector<Point<dim>>   start_point;
  };
} // namespace fsgmpm

#endif
