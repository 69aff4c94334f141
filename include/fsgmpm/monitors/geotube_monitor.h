#ifndef fsgmpm_monitors_geotube_monitor_h
#define fsgmpm_monitors_geotube_monitor_h

#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/monitors/scene_monitor.h>
#include <fsgmpm/particles/particle_store.h>

#include <map>
#include <string>
#include <vector>

namespace fsgmpm
{
  /**
   * Geotube monitors: height and width (max - min of the
   * membrane nodes), contact_width (extent of the nodes within
   * @p contact_tolerance of the lowest node), max_tension and mean_tension
   * (length-weighted), top_pressure and bottom_pressure (a least-squares line
   * of particle pressure against y over the central strip |x - x_c| <=
   * strip_width/2, evaluated at the membrane's top and bottom),
   * membrane_length, enclosed_area (2D), fluid_volume (sum of particle
   * volumes; per metre in 2D) and particles_outside, the last three over
   * the points of body @p fill_body only (the pressure strip too). MPI:
   * the sums over the points are taken over @p communicator (each process
   * holds its own points and the whole membrane).
   */
  template <int dim>
  std::map<std::string, double>
  membrane_monitors(const Membrane<dim>      &membrane,
                    const ParticleStore<dim> &particles,
                    const double              contact_tolerance,
                    const double              strip_width,
                    const unsigned int        fill_body    = 0,
                    const MPI_Comm            communicator = MPI_COMM_SELF);

  /// Names of the columns membrane_monitors() provides.
  const std::vector<std::string> &
  membrane_monitor_names();

  /**
   * Scene monitor "geotube": the columns of membrane_monitors() in the order
   * of membrane_monitor_names(), over the points of Monitors/Container body;
   * needs a membrane. Its entries: Contact tolerance and Pressure strip
   * width (subsection Monitors).
   */
  template <int dim>
  class GeotubeMonitor : public SceneMonitor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    static std::vector<std::string>
    quantities()
    {
      return membrane_monitor_names();
    }

    GeotubeMonitor(ParameterHandler &prm, const MonitorSetup<dim> &setup);

    std::vector<std::string>
    column_names() const override
    {
      return membrane_monitor_names();
    }

    /// Lengths, tensions (N/m in 2D and 3D), pressures; the section's
    /// area and the fluid's (per unit length of an extruded 3D tube).
    std::vector<std::string>
    column_units() const override
    {
      return {"m", "m", "m", "N/m", "N/m", "Pa", "Pa", "m", "m^2", "m^2", ""};
    }

    std::vector<double>
    evaluate(const MonitorContext<dim> &context) const override;

    bool
    needs_membrane() const override
    {
      return true;
    }

    bool
    combines_over_processes() const override
    {
      return true;
    }

  private:
    double       contact_tolerance, strip_width;
    unsigned int fill_body;
  };
} // namespace fsgmpm

#endif
