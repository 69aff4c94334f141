#ifndef fsgmpm_monitors_bodies_monitor_h
#define fsgmpm_monitors_bodies_monitor_h

#include <fsgmpm/monitors/scene_monitor.h>

namespace fsgmpm
{
  /**
   * Scene monitor "bodies": per body b, body_mass_b (kg; per metre in 2D)
   * and body_kinetic_energy_b (J). The quantities body_mass and
   * body_kinetic_energy select one column per body each.
   */
  template <int dim>
  class BodiesMonitor : public SceneMonitor<dim>
  {
  public:
    static std::vector<std::string>
    quantities()
    {
      return {"body_mass", "body_kinetic_energy"};
    }

    BodiesMonitor(ParameterHandler &prm, const MonitorSetup<dim> &setup);

    /// body_mass_0, ..., body_kinetic_energy_0, ...
    std::vector<std::string>
    column_names() const override;

    /// quantity_0, quantity_1, ...: one column per body.
    std::vector<std::string>
    columns_of(const std::string &quantity) const override;

    /// kg/m and J/m in 2D, kg and J in 3D.
    std::vector<std::string>
    column_units() const override;

    std::vector<double>
    evaluate(const MonitorContext<dim> &context) const override;

    bool
    combines_over_processes() const override
    {
      return true;
    }

  private:
    unsigned int n_bodies;
  };
} // namespace fsgmpm

#endif
