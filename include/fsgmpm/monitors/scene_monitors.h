#ifndef fsgmpm_monitors_scene_monitors_h
#define fsgmpm_monitors_scene_monitors_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/monitors/scene_monitor.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * The scene monitors a scene selects in Monitors/Scene monitors, and the
   * columns they add to monitors.csv. Each name of the list is a monitor's
   * (all its columns) or a quantity a monitor registered (its columns, e.g.
   * front_position of dam_break); the columns keep the order of the list.
   * Each selected monitor is built once and evaluated once per row.
   */
  template <int dim>
  class SceneMonitors
  {
  public:
    /// Scene monitors, the references monitors share (Container body, Wall
    /// position, Base position) and every registered monitor's entries.
    static void
    declare_parameters(ParameterHandler &prm);

    /// @p lower, @p cell_size: mesh corner and cell size per direction,
    /// used where the parameters say "auto"; @p n_bodies for the per-body
    /// columns; @p has_membrane: monitors that need one are refused without.
    SceneMonitors(ParameterHandler  &prm,
                  const Point<dim>  &lower,
                  const Point<dim>  &cell_size,
                  const unsigned int n_bodies     = 1,
                  const bool         has_membrane = false);

    /// The selected columns, in order.
    const std::vector<std::string> &
    names() const
    {
      return columns;
    }

    /// The selected columns' units (SceneMonitor::column_units()), in the
    /// order of names().
    const std::vector<std::string> &
    units() const
    {
      return column_units;
    }

    /// The columns' values (the membrane is nullptr if there is none).
    /// MPI: @p communicator holds the processes that share the points;
    /// the monitors that combine_over_processes() return global values,
    /// the maxima are the caller's to combine.
    std::vector<double>
    evaluate(const ParticleStore<dim> &particles,
             const Membrane<dim>      *membrane     = nullptr,
             const MPI_Comm            communicator = MPI_COMM_SELF) const;

    /// True if a selected monitor needs a membrane.
    bool
    needs_membrane() const;

    /// The selected monitors that can not run on more than one MPI process
    /// (neither maxima nor combining over the processes themselves), comma
    /// separated; empty if none.
    std::string
    not_distributed() const;

    /// The selected monitor registered as @p name; throws, naming the
    /// selected ones, if the scene did not select it.
    const SceneMonitor<dim> &
    get(const std::string &name) const;

  private:
    /// The selected monitors and their registered names.
    std::vector<std::pair<std::string, std::unique_ptr<SceneMonitor<dim>>>>
      monitors;
    /// Their numbers of columns, to check what evaluate() returns.
    std::vector<unsigned int> n_columns;
    std::vector<std::string>  columns;
    std::vector<std::string>  column_units;
    /// Column k is value source[k].second of monitor source[k].first.
    std::vector<std::pair<unsigned int, unsigned int>> source;
  };
} // namespace fsgmpm

#endif
