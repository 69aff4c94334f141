#include <fsgmpm/base/compensated_sum.h>
#include <fsgmpm/monitors/bodies_monitor.h>
#include <fsgmpm/monitors/monitor_factory.h>


namespace fsgmpm
{
  template <int dim>
  BodiesMonitor<dim>::BodiesMonitor(ParameterHandler &,
                                    const MonitorSetup<dim> &setup)
    : n_bodies(setup.n_bodies)
  {}



  template <int dim>
  std::vector<std::string>
  BodiesMonitor<dim>::columns_of(const std::string &quantity) const
  {
    std::vector<std::string> columns;
    for (unsigned int b = 0; b < n_bodies; ++b)
      columns.push_back(quantity + "_" + std::to_string(b));
    return columns;
  }



  template <int dim>
  std::vector<std::string>
  BodiesMonitor<dim>::column_names() const
  {
    std::vector<std::string> columns;
    for (const auto &quantity : quantities())
      for (const auto &column : columns_of(quantity))
        columns.push_back(column);
    return columns;
  }



  template <int dim>
  std::vector<std::string>
  BodiesMonitor<dim>::column_units() const
  {
    std::vector<std::string> units;
    for (const std::string unit :
         {dim == 2 ? "kg/m" : "kg", dim == 2 ? "J/m" : "J"})
      units.resize(units.size() + n_bodies, unit);
    return units;
  }



  template <int dim>
  std::vector<double>
  BodiesMonitor<dim>::evaluate(const MonitorContext<dim> &context) const
  {
    const ParticleStore<dim> &particles = context.particles;
    // Masses first, then kinetic energies: the order of column_names().
    // Compensated sums: the values do not depend on the order of the
    // points nor on how they are split over the processes.
    std::vector<CompensatedSum> sums(2 * n_bodies);
    for (unsigned int p = 0; p < particles.size(); ++p)
      if (particles.body_id[p] < n_bodies)
        {
          sums[particles.body_id[p]].add(particles.mass[p]);
          sums[n_bodies + particles.body_id[p]].add(
            0.5 * particles.mass[p] * particles.velocity[p].norm_square());
        }
    return sum_over_processes(sums, context.communicator);
  }

  template class BodiesMonitor<2>;
  template class BodiesMonitor<3>;

  FSGMPM_REGISTER_MONITOR(BodiesMonitor,
                          "bodies",
                          "mass and kinetic energy of each body")
} // namespace fsgmpm
