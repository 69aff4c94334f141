#ifndef fsgmpm_monitors_deposit_monitor_h
#define fsgmpm_monitors_deposit_monitor_h

#include <fsgmpm/monitors/scene_monitor.h>

namespace fsgmpm
{
  /**
   * Scene monitor "deposit", the shape of a collapsed granular column, from
   * all points:
   * - runout: largest x - x_wall where the deposit is at least one point
   *   spacing (V_p^(1/dim)) thick, plus half a spacing;
   * - final_height: the highest point above the base plus half a spacing.
   * The wall and base are Monitors/Wall position and Base position.
   */
  template <int dim>
  class DepositMonitor : public SceneMonitor<dim>
  {
  public:
    static std::vector<std::string>
    quantities()
    {
      return {"runout", "final_height"};
    }

    DepositMonitor(ParameterHandler &prm, const MonitorSetup<dim> &setup);

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
    double wall_x, base_y;
  };
} // namespace fsgmpm

#endif
