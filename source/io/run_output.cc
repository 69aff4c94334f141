#include <deal.II/base/mpi.h>

#include <fsgmpm/io/atomic_file.h>
#include <fsgmpm/io/grid_output.h>
#include <fsgmpm/io/membrane_fe_output.h>
#include <fsgmpm/io/membrane_output.h>
#include <fsgmpm/io/run_output.h>
#include <fsgmpm/parallel/process_count.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <regex>

namespace fsgmpm
{
  template <int dim>
  RunOutput<dim>::RunOutput(const Settings &settings)
    : settings(settings)
    , parallel(Parallel::n_processes(settings.communicator) > 1)
    , root(!parallel
           || Utilities::MPI::this_mpi_process(settings.communicator) == 0)
    , particle_series(settings.directory,
                      "particles",
                      parallel ? ".pvtu" : ".vtu")
    , grid_series(settings.directory, "grid")
    , membrane_series(settings.directory, "membrane")
    , particle_xdmf(settings.directory, "particles", settings.communicator)
    , membrane_xdmf(settings.directory, "membrane")
  {}



  template <int dim>
  void
  RunOutput<dim>::remove_previous_output() const
  {
    namespace fs = std::filesystem;
    for (const auto &entry : fs::directory_iterator(settings.directory))
      for (const char *stale : {".vtu", ".pvtu", ".pvd", ".h5", ".xdmf"})
        if (entry.path().extension() == stale)
          fs::remove(entry.path());
  }



  template <int dim>
  void
  RunOutput<dim>::write(const double               time,
                        const ParticleStore<dim>  &particles,
                        const BackgroundGrid<dim> &grid,
                        const NodalFields<dim>    &nodes,
                        const Membrane<dim>       *membrane,
                        const NodalFields<dim>    *grid_nodes,
                        const BackgroundGrid<dim> *whole_grid)
  {
    const std::string &dir = settings.directory;
    if (settings.write_particles)
      {
        particle_output.build_patches(particles, &grid, &nodes);
        if (settings.hdf5)
          particle_output.write_xdmf(particle_xdmf, time);
        else if (!parallel)
          {
            const std::string name = particle_series.next_file(time);
            write_file_atomically(dir + "/" + name, [&](std::ostream &out) {
              particle_output.write_vtu(out);
            });
            particle_series.write_pvd();
          }
        else
          write_pieces(particle_series.next_file(time), particles.size());
      }
    if (!root)
      return;
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
        write_grid_vtu(whole_grid != nullptr ? *whole_grid : grid,
                       grid_nodes != nullptr ? *grid_nodes : nodes,
                       dir + "/" + name);
        grid_series.write_pvd();
      }
  }



  template <int dim>
  void
  RunOutput<dim>::write_pieces(const std::string &record,
                               const unsigned int n_local)
  {
    // BASE_NNNNN.pvtu names the pieces BASE_NNNNN.R.vtu of the processes
    // that own points (an empty piece makes VTK readers complain), or
    // process 0's alone if none does.
    const std::string  stem = record.substr(0, record.size() - 5);
    const unsigned int rank
      = Utilities::MPI::this_mpi_process(settings.communicator);
    const std::vector<unsigned int> counts
      = Utilities::MPI::all_gather(settings.communicator, n_local);
    const bool               none = std::all_of(counts.begin(),
                                  counts.end(),
                                  [](const unsigned int c) { return c == 0; });
    std::vector<std::string> pieces;
    for (unsigned int r = 0; r < counts.size(); ++r)
      if (counts[r] > 0 || (none && r == 0))
        pieces.push_back(stem + "." + std::to_string(r) + ".vtu");
    // A failure on one process is everyone's (no process may wait for
    // pieces that never come), and the record is written once every piece
    // is complete.
    std::string error;
    try
      {
        if (n_local > 0 || (none && rank == 0))
          write_file_atomically(settings.directory + "/" + stem + "."
                                  + std::to_string(rank) + ".vtu",
                                [&](std::ostream &out) {
                                  particle_output.write_vtu(out);
                                });
      }
    catch (const std::exception &e)
      {
        error = e.what();
      }
    const bool ok
      = Utilities::MPI::min(int(error.empty()), settings.communicator) == 1;
    AssertThrow(ok,
                ExcMessage(error.empty()
                             ? "Writing <" + settings.directory + "/" + record
                                 + ">: another process failed to write its "
                                   "piece (see its message)."
                             : error));
    if (!root)
      return;
    write_file_atomically(settings.directory + "/" + record,
                          [&](std::ostream &out) {
                            particle_output.write_pvtu_record(out, pieces);
                          });
    particle_series.write_pvd();
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
        series[k]->restore(state.series_times[k]);
        if (!state.series_times[k].empty() && root)
          series[k]->write_pvd();
      }
    particle_xdmf.restore(state.xdmf_records[0]);
    membrane_xdmf.restore(state.xdmf_records[1]);
    if (root)
      remove_files_after(state);
  }



  template <int dim>
  void
  RunOutput<dim>::remove_files_after(const State &state) const
  {
    // The interrupted run's files after the checkpoint are written again,
    // but not always under the same names: continued on another number of
    // processes, a serial run's particles_N.vtu would stay beside the new
    // particles_N.pvtu (and a reader of the directory would see the step
    // twice), and the pieces particles_N.R.vtu of processes that are gone
    // would stay. So every numbered file past the restored series goes.
    namespace fs = std::filesystem;
    const std::regex numbered(
      R"((particles|grid|membrane)_(\d+)(\.\d+)?\.(vtu|pvtu|h5))");
    const auto written = [&](const std::string &base, const bool h5) {
      const unsigned int k = base == "particles" ? 0 : (base == "grid" ? 1 : 2);
      if (!h5)
        return state.series_times[k].size();
      // XdmfSeries::records(): (time, nodes, cells) per step; the grid has
      // no HDF5 series.
      return k == 1 ? std::numeric_limits<std::size_t>::max()
                    : state.xdmf_records[k == 0 ? 0 : 1].size() / 3;
    };
    for (const auto &entry : fs::directory_iterator(settings.directory))
      {
        std::smatch       match;
        const std::string name = entry.path().filename().string();
        if (std::regex_match(name, match, numbered)
            && std::stoul(match[2].str())
                 >= written(match[1].str(), match[4].str() == "h5"))
          fs::remove(entry.path());
      }
  }

  template class RunOutput<2>;
  template class RunOutput<3>;
} // namespace fsgmpm
