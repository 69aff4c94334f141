#include <fsgmpm/base/parallel_reductions.h>
#include <fsgmpm/base/parameter_parsing.h>
#include <fsgmpm/monitors/dam_break_monitor.h>
#include <fsgmpm/monitors/monitor_factory.h>

#include <algorithm>

namespace fsgmpm
{
  template <int dim>
  void
  DamBreakMonitor<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Row height",
                      "auto",
                      Patterns::Anything(),
                      "Height of the bottom cell row (m); auto: the cell size "
                      "in y.");
    prm.declare_entry("Column width",
                      "auto",
                      Patterns::Anything(),
                      "Width of the strip at the wall for column_height (m); "
                      "auto: the cell size in x.");
  }



  template <int dim>
  DamBreakMonitor<dim>::DamBreakMonitor(ParameterHandler        &prm,
                                        const MonitorSetup<dim> &setup)
    : wall_x(setup.wall_x)
    , base_y(setup.base_y)
    , row_height(parse_auto_or_double(prm.get("Row height"),
                                      setup.cell_size[1],
                                      "Monitors/Row height"))
    , column_width(parse_auto_or_double(prm.get("Column width"),
                                        setup.cell_size[0],
                                        "Monitors/Column width"))
  {}



  template <int dim>
  std::vector<double>
  DamBreakMonitor<dim>::evaluate(const MonitorContext<dim> &context) const
  {
    const ParticleStore<dim> &particles = context.particles;
    // In parallel (a maximum is exact: the same for any number of threads),
    // and a point's spacing (a root per point, a cube root in 3D) only for
    // the points in the bottom row or the wall's column.
    const auto maxima = Reductions::parallel_maxima<2>(
      particles.size(), {{0., 0.}}, [&](const unsigned int p, auto &m) {
        if (particles.free_surface[p])
          return;
        const double x = particles.position[p][0] - wall_x;
        const double y = particles.position[p][1] - base_y;
        if (y >= row_height && x >= column_width)
          return;
        const double half_spacing
          = half_point_spacing<dim>(particles.volume[p]);
        if (y < row_height)
          m[0] = std::max(m[0], x + half_spacing);
        if (x < column_width)
          m[1] = std::max(m[1], y + half_spacing);
      });
    return {maxima[0], maxima[1]}; // front, height
  }

  template class DamBreakMonitor<2>;
  template class DamBreakMonitor<3>;

  FSGMPM_REGISTER_MONITOR(DamBreakMonitor,
                          "dam_break",
                          "surge front from the wall in the bottom cell row "
                          "and column height at the wall (m)")
} // namespace fsgmpm
