#ifndef fsgmpm_monitors_scene_monitor_h
#define fsgmpm_monitors_scene_monitor_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/particles/particle_store.h>

#include <cmath>
#include <string>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * What a scene monitor learns of the scene when it is built: the mesh and
   * the bodies, and the references that several monitors share (entries of
   * subsection Monitors that SceneMonitors reads, "auto" already resolved).
   */
  template <int dim>
  struct MonitorSetup
  {
    Point<dim>   lower_corner; ///< the mesh's lower corner
    Point<dim>   cell_size;    ///< per direction (Grid/Cell size)
    unsigned int n_bodies = 1;
    /// Monitors/Container body: the body the membrane holds (the fill).
    unsigned int container_body = 0;
    double       wall_x         = 0; ///< Monitors/Wall position
    double       base_y         = 0; ///< Monitors/Base position
    bool         has_membrane   = false;
  };

  /// Half the spacing V^(1/dim) of a point of volume @p volume: what a
  /// point adds to a front or a height beyond its centre (dam_break,
  /// deposit).
  template <int dim>
  inline double
  half_point_spacing(const double volume)
  {
    return 0.5 * (dim == 2 ? std::sqrt(volume) : std::cbrt(volume));
  }

  /// What a scene monitor sees each time it is evaluated.
  template <int dim>
  struct MonitorContext
  {
    const ParticleStore<dim> &particles;
    /// The scene's membrane, or nullptr if it has none.
    const Membrane<dim> *membrane;
    /// The processes that share the points (MPI; each holds its own points
    /// and the whole membrane); MPI_COMM_SELF in a serial run.
    MPI_Comm communicator = MPI_COMM_SELF;
  };

  /**
   * One named monitor: a few columns of monitors.csv computed from the
   * state, as ASPECT's postprocessors are. A monitor is a class template
   * (template <int dim>) derived from this class, with
   * - a constructor (ParameterHandler &, const MonitorSetup<dim> &): the
   *   ParameterHandler is in subsection Monitors, where the monitor reads
   *   the entries it declared;
   * - optionally the static functions declare_parameters(ParameterHandler
   *   &), which declares its entries in subsection Monitors (best in a
   *   subsection of its own: entries are shared by all monitors), and
   *   quantities(), the names besides its own under which parts of its
   *   columns may be selected (columns_of());
   * registered by name with FSGMPM_REGISTER_MONITOR
   * (monitors/monitor_factory.h) and selected in Monitors/Scene monitors.
   */
  template <int dim>
  class SceneMonitor
  {
  public:
    virtual ~SceneMonitor() = default;

    /// No entries of its own (a monitor that has some hides this one).
    static void
    declare_parameters(ParameterHandler &)
    {}

    /// No names but the monitor's own (a monitor that offers a part of its
    /// columns by name hides this one).
    static std::vector<std::string>
    quantities()
    {
      return {};
    }

    /// Its columns, in the order evaluate() returns their values.
    virtual std::vector<std::string>
    column_names() const = 0;

    /// The SI units of column_names(), in their order, as monitors.csv's
    /// header and summary.json write them ("front_position[m]"): per metre
    /// of thickness in 2D (J/m, kg/m, m^2), of the whole body in 3D; empty
    /// for counts and ratios. By default none.
    virtual std::vector<std::string>
    column_units() const
    {
      return std::vector<std::string>(column_names().size());
    }

    /// The columns selected by @p quantity, one of quantities(): by default
    /// the column of that name; per-body quantities give one each.
    virtual std::vector<std::string>
    columns_of(const std::string &quantity) const
    {
      return {quantity};
    }

    /// The values of column_names() for the current state.
    virtual std::vector<double>
    evaluate(const MonitorContext<dim> &context) const = 0;

    /// True if evaluate() needs a membrane; the scene refuses the monitor
    /// without one (Membrane/Enabled).
    virtual bool
    needs_membrane() const
    {
      return false;
    }

    /// True if every value is a maximum over the points that is zero or
    /// more (a front, a height), so that the value over all MPI processes
    /// is the maximum of theirs. Monitors that are not cannot run on more
    /// than one process yet.
    virtual bool
    values_are_maxima() const
    {
      return false;
    }

    /// True if evaluate() combines its sums over the points over
    /// MonitorContext::communicator itself, so that every process returns
    /// the global values. A monitor that neither does this nor has
    /// values_are_maxima() cannot run on more than one process yet.
    virtual bool
    combines_over_processes() const
    {
      return false;
    }
  };
} // namespace fsgmpm

#endif
