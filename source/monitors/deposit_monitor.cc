#include <fsgmpm/base/parallel_reductions.h>
#include <fsgmpm/monitors/deposit_monitor.h>
#include <fsgmpm/monitors/monitor_factory.h>

#include <algorithm>

namespace fsgmpm
{
  template <int dim>
  DepositMonitor<dim>::DepositMonitor(ParameterHandler &,
                                      const MonitorSetup<dim> &setup)
    : wall_x(setup.wall_x)
    , base_y(setup.base_y)
  {}



  template <int dim>
  std::vector<double>
  DepositMonitor<dim>::evaluate(const MonitorContext<dim> &context) const
  {
    const ParticleStore<dim> &particles = context.particles;
    // In parallel: a maximum is exact, the same for any number of threads.
    const auto maxima = Reductions::parallel_maxima<2>(
      particles.size(), {{0., 0.}}, [&](const unsigned int p, auto &m) {
        const double half_spacing
          = half_point_spacing<dim>(particles.volume[p]);
        const double x = particles.position[p][0] - wall_x;
        const double y = particles.position[p][1] - base_y;
        // A point resting on the base makes the deposit one spacing thick.
        if (y + half_spacing >= 2 * half_spacing * (1 - 1e-3))
          m[0] = std::max(m[0], x + half_spacing);
        m[1] = std::max(m[1], y + half_spacing);
      });
    return {maxima[0], maxima[1]}; // run-out, top
  }

  template class DepositMonitor<2>;
  template class DepositMonitor<3>;

  FSGMPM_REGISTER_MONITOR(DepositMonitor,
                          "deposit",
                          "run-out from the wall where the deposit is a "
                          "point spacing thick, and its height (m)")
} // namespace fsgmpm
