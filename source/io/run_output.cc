#include <fsgmpm/io/atomic_file.h>
#include <fsgmpm/io/grid_output.h>
#include <fsgmpm/io/membrane_fe_output.h>
#include <fsgmpm/io/membrane_output.h>
#include <fsgmpm/io/run_output.h>

#include <filesystem>

namespace fsgmpm
{
  template <int dim>
  RunOutput<dim>::RunOutput(const Settings &settings)
    : settings(settings)
    , particle_series(settings.directory, "particles")
    , grid_series(settings.directory, "grid")
    , membrane_series(settings.directory, "membrane")
    , particle_xdmf(settings.directory, "particles")
    , membrane_xdmf(settings.directory, "membrane")
  {}



  template <int dim>
  void
  RunOutput<dim>::remove_previous_output() const
  {
    namespace fs = std::filesystem;
    for (const auto &entry : fs::directory_iterator(settings.directory))
      for (const char *stale : {".vtu", ".pvd", ".h5", ".xdmf"})
        if (entry.path().extension() == stale)
          fs::remove(entry.path());
  }



  template <int dim>
  void
  RunOutput<dim>::write(const double                         time,
                        const ParticleStore<dim>            &particles,
                        const BackgroundGrid<dim>           &grid,
                        const NodalFields<dim>              &nodes,
                        const Membrane<dim>                 *membrane,
                        const std::vector<NodalPointFields> *nodal_fields)
  {
    const std::string &dir = settings.directory;
    if (settings.write_particles)
      {
        particle_output.build_patches(particles, &grid, &nodes, nodal_fields);
        if (settings.hdf5)
          particle_output.write_xdmf(particle_xdmf, time);
        else
          {
            const std::string name = particle_series.next_file(time);
            write_file_atomically(dir + "/" + name, [&](std::ostream &out) {
              particle_output.write_vtu(out);
            });
            particle_series.write_pvd();
          }
      }
    if (membrane && settings.hdf5)
      write_membrane_xdmf(*membrane, membrane_xdmf, time);
    else if (membrane)
      {
        const std::string name = membrane_series.next_file(time);
        if (settings.membrane_finite_elements)
          write_membrane_fe_vtu(*membrane, dir + "/" + name);
        else
          write_membrane_vtu(*membrane, dir + "/" + name);
        membrane_series.write_pvd();
      }
    if (settings.write_grid)
      {
        const std::string name = grid_series.next_file(time);
        write_grid_vtu(grid, nodes, dir + "/" + name);
        grid_series.write_pvd();
      }
  }



  template <int dim>
  typename RunOutput<dim>::State
  RunOutput<dim>::state() const
  {
    return {
      {{particle_series.times(), grid_series.times(), membrane_series.times()}},
      {{particle_xdmf.records(), membrane_xdmf.records()}}};
  }



  template <int dim>
  void
  RunOutput<dim>::restore(const State &state)
  {
    PvdSeries *series[3] = {&particle_series, &grid_series, &membrane_series};
    for (unsigned int k = 0; k < 3; ++k)
      {
        for (const double t : state.series_times[k])
          series[k]->next_file(t);
        if (!state.series_times[k].empty())
          series[k]->write_pvd();
      }
    particle_xdmf.restore(state.xdmf_records[0]);
    membrane_xdmf.restore(state.xdmf_records[1]);
  }

  template class RunOutput<2>;
  template class RunOutput<3>;
} // namespace fsgmpm
