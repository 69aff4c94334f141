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
  std::vector<double>
  BodiesMonitor<dim>::evaluate(const MonitorContext<dim> &context) const
  {
    const ParticleStore<dim> &particles = context.particles;
    // Masses first, then kinetic energies: the order of column_names().
    std::vector<double> values(2 * n_bodies, 0.);
    for (unsigned int p = 0; p < particles.size(); ++p)
      if (particles.body_id[p] < n_bodies)
        {
          values[particles.body_id[p]] += particles.mass[p];
          values[n_bodies + particles.body_id[p]]
            += 0.5 * particles.mass[p] * particles.velocity[p].norm_square();
        }
    const std::vector<double> local = values;
    Utilities::MPI::sum(make_array_view(local),
                        context.communicator,
                        make_array_view(values));
    return values;
  }

  template class BodiesMonitor<2>;
  template class BodiesMonitor<3>;

  FSGMPM_REGISTER_MONITOR(BodiesMonitor,
                          "bodies",
                          "mass and kinetic energy of each body")
} // namespace fsgmpm
