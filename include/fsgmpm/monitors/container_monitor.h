#ifndef fsgmpm_monitors_container_monitor_h
#define fsgmpm_monitors_container_monitor_h

#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/monitors/scene_monitor.h>
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
   * Without a membrane the last two are zero. With several processes
   * each passes its own points and the same membrane; the sums, counts and
   * extremes are combined over @p communicator.
   */
  template <int dim>
  std::map<std::string, double>
  container_monitors(const ParticleStore<dim> &particles,
                     const Membrane<dim>      *membrane,
                     const unsigned int        container,
                     const MPI_Comm            communicator = MPI_COMM_SELF);

  /// Names of the columns container_monitors() provides.
  const std::vector<std::string> &
  container_monitor_names();

  /**
   * Scene monitor "container": the columns of container_monitors() in the
   * order of container_monitor_names(), for the body of Monitors/Container
   * body. A membrane is optional (without one the inside counts are zero).
   */
  template <int dim>
  class ContainerMonitor : public SceneMonitor<dim>
  {
  public:
    static std::vector<std::string>
    quantities()
    {
      return container_monitor_names();
    }

    ContainerMonitor(ParameterHandler &prm, const MonitorSetup<dim> &setup);

    std::vector<std::string>
    column_names() const override
    {
      return container_monitor_names();
    }

    /// The soil's area is a volume in 3D.
    std::vector<std::string>
    column_units() const override
    {
      return {
        "m", "m", "m/s", "deg", dim == 2 ? "m^2" : "m^3", "", "", "m", "m"};
    }

    std::vector<double>
    evaluate(const MonitorContext<dim> &context) const override;

    bool
    combines_over_processes() const override
    {
      return true;
    }

  private:
    unsigned int container;
  };
} // namespace fsgmpm

#endif
