#ifndef fsgmpm_io_container_monitors_h
#define fsgmpm_io_container_monitors_h

#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/particles/particle_store.h>

#include <map>
#include <string>
#include <vector>

namespace fsgmpm
{
  /**
   * Monitors of a body held by a membrane among other bodies (the
   * geocontainer of paper Section 5), all in the x-y plane (3D: per unit
   * thickness, the membrane's first ring):
   * - container_centre_x, container_centre_y, container_velocity_y: the
   *   mass-weighted centre and vertical velocity of the @p container body's
   *   points;
   * - container_tilt: angle (degrees, -90 to 90) of the major principal
   *   axis of their second moment of area from the x axis;
   * - soil_area: the container body's point volumes (m^2; per metre in 3D);
   * - soil_points_outside: its points outside the closed membrane;
   * - water_points_inside: points of the other bodies inside it;
   * - water_inside_depth, soil_outside_distance: the largest distance from
   *   the membrane of those points (how far they crossed it).
   * Without a membrane the last two are zero.
   */
  template <int dim>
  std::map<std::string, double>
  container_monitors(const ParticleStore<dim> &particles,
                     const Membrane<dim>      *membrane,
                     const unsigned int        container);

  /// Per body b: body_mass_b (kg; per metre in 2D) and
  /// body_kinetic_energy_b (J).
  template <int dim>
  std::map<std::string, double>
  body_monitors(const ParticleStore<dim> &particles,
                const unsigned int        n_bodies);

  /// Names of the columns container_monitors() provides.
  const std::vector<std::string> &
  container_monitor_names();
} // namespace fsgmpm

#endif
