#ifndef fsgmpm_monitors_dam_break_monitor_h
#define fsgmpm_monitors_dam_break_monitor_h

#include <fsgmpm/monitors/scene_monitor.h>

namespace fsgmpm
{
  /**
   * Scene monitor "dam_break", both from the non-flagged points:
   * - front_position: largest x - x_wall of the points in the bottom cell
   *   row, plus half a point spacing (V_p^(1/dim));
   * - column_height: largest y - y_base of the points within one cell of the
   *   wall, plus half a point spacing.
   * The wall and base are Monitors/Wall position and Base position.
   */
  template <int dim>
  class DamBreakMonitor : public SceneMonitor<dim>
  {
  public:
    /// Row height and Column width (subsection Monitors).
    static void
    declare_parameters(ParameterHandler &prm);

    static std::vector<std::string>
    quantities()
    {
      return {"front_position", "column_height"};
    }

    DamBreakMonitor(ParameterHandler &prm, const MonitorSetup<dim> &setup);

    std::vector<std::string>
    column_names() const override
    {
      return quantities();
    }

    std::vector<std::string>
    column_units() const override
    {
      return {"m", "m"};
    }

    std::vector<double>
    evaluate(const MonitorContext<dim> &context) const override;

    bool
    values_are_maxima() const override
    {
      return true;
    }

  private:
    double wall_x, base_y, row_height, column_width;
  };
} // namespace fsgmpm

#endif
