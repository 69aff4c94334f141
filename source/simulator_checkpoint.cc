/**
 * Checkpoint and restart of a Simulator (doc/checkpoint_and_hdf5.md): the whole
 * state in one HDF5 file per checkpoint, written atomically, the last two
 * kept; a restarted run continues bit for bit as the uninterrupted one.
 */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <fsgmpm/base/version.h>
#include <fsgmpm/io/checkpoint_file.h>
#include <fsgmpm/io/monitor_file.h>
#include <fsgmpm/io/state_checkpoint.h>
#include <fsgmpm/parallel/distributed_points.h>
#include <fsgmpm/simulator.h>
#include <fsgmpm/step/stages.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace fsgmpm
{
  namespace
  {
    namespace fs = std::filesystem;

    /// Parameters a restart may change: where and what it writes, how far
    /// it runs, on how many threads and processes, and a body's smoothing
    /// stabilisation (which keeps the stress power equal to the nodal
    /// forces' power at every step, whatever its value: water that has come
    /// to rest, a geocontainer's after the landing, may be run on with it).
    /// Everything else is the physics of the checkpointed run.
    bool
    may_change_on_restart(const std::string &path)
    {
      const std::string stabilisation = "/Smoothing stabilisation";
      return path.rfind("Output/", 0) == 0 || path == "Simulation/End time"
             || path == "Simulation/Maximum number of steps"
             || path == "Simulation/Termination"
             || path == "Simulation/Number of threads"
             || path == "Simulation/Repartition imbalance"
             || (path.rfind("Bodies/Body ", 0) == 0
                 && path.size() > stabilisation.size()
                 && path.compare(path.size() - stabilisation.size(),
                                 stabilisation.size(),
                                 stabilisation)
                      == 0);
    }

    std::string
    listing_text(const std::vector<std::pair<std::string, std::string>> &list)
    {
      std::string text;
      for (const auto &[path, value] : list)
        if (!may_change_on_restart(path))
          text += path + " = " + value + "\n";
      return text;
    }

    /// The checkpoints in @p directory, newest first (the names carry the
    /// step, zero-padded).
    std::vector<fs::path>
    checkpoint_files(const fs::path &directory)
    {
      std::vector<fs::path> files;
      if (fs::is_directory(directory))
        for (const auto &entry : fs::directory_iterator(directory))
          if (entry.path().extension() == ".h5"
              && entry.path().filename().string().rfind("checkpoint_", 0) == 0)
            files.push_back(entry.path());
      std::sort(files.rbegin(), files.rend());
      return files;
    }

    std::string
    message_of(const ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      return Utilities::trim(info.str());
    }
  } // namespace



  template <int dim>
  void
  Simulator<dim>::write_checkpoint(const double wall_seconds)
  {
    const auto start = std::chrono::steady_clock::now();
    // MPI: one file for all processes, written collectively; each process
    // writes its own points, process 0 everything else (the same
    // everywhere) and the partition.
    const MPI_Comm communicator
      = partition ? partition->get_communicator() : MPI_COMM_SELF;
    const fs::path directory
      = fs::path(params.output_directory) / "checkpoints";
    if (root)
      fs::create_directories(directory);
    if (partition) // every process opens the file in it
      MPI_Barrier(communicator);
    char name[40];
    std::snprintf(name, sizeof(name), "checkpoint_%010u", step);
    std::string file_name;
    {
      CheckpointWriter out((directory / name).string(), communicator);
      out.put("fsgmpm/version", version_string());
      out.put("fsgmpm/dim", double(dim));
      out.put("fsgmpm/parameters", listing_text(parameter_listing));

      out.put("run/time", time);
      out.put("run/dt", time_step_control.state());
      out.put("run/step", std::vector<unsigned int>{step});
      const auto m = monitors.values();
      out.put("run/monitors", std::vector<double>(m.begin(), m.end()));
      // Dynamic relaxation, the rest and convergence counters and the
      // stability guard's energy history.
      out.put("run/energies", relaxation.energy_state());
      out.put("run/counters", relaxation.counter_state());
      out.put("run/stability_guard", stability_guard.state());
      out.put("run/stability_guard_largest", stability_guard.largest_state());

      // Process 0 writes monitors.csv (the others have no monitor file).
      out.put("output/monitor_bytes", root ? double(monitor_file->size()) : 0.);
      out.put("output/next_output_time", output_schedule.next_time());
      out.put("output/last_output_step",
              std::vector<unsigned int>{output_schedule.last_step()});
      out.put("output/next_checkpoint_time",
              checkpoint_schedule.next_time_after(time));
      const auto series = output->state();
      out.put("output/particle_series", series.series_times[0]);
      out.put("output/grid_series", series.series_times[1]);
      out.put("output/membrane_series", series.series_times[2]);
      out.put("output/particle_xdmf", series.xdmf_records[0]);
      out.put("output/membrane_xdmf", series.xdmf_records[1]);
      out.put("cost/wall_seconds", previous_wall_seconds + wall_seconds);
      out.put("cost/stage_seconds", get_stage_seconds());
      out.put("cost/particle_updates", double(particle_updates));
      out.put("cost/checkpoint_seconds", checkpoint_seconds);

      StateCheckpoint::save(out, particles, *grid);
      if (partition)
        {
          out.put("mpi/ranks", std::vector<unsigned int>{partition->n_ranks()});
          out.put("mpi/cell_owner", partition->owners());
          out.put("mpi/repartitions",
                  std::vector<unsigned int>{n_repartitions});
        }
      if (membrane)
        {
          StateCheckpoint::save(out, *membrane);
          StateCheckpoint::save(out, *mpm_step->get_membrane_coupling());
        }
      file_name = out.commit();
    }
    // Read it back before older ones go: HDF5 may report a failed write
    // (a full disk) only as a file that does not read back. With MPI each
    // process reads back what it wrote.
    std::string error;
    try
      {
        CheckpointReader verify(file_name, communicator);
      }
    catch (const ExceptionBase &e)
      {
        error = message_of(e);
      }
    if (!error.empty())
      {
        if (root)
          fs::remove(file_name);
        AssertThrow(false,
                    ExcMessage("Writing the checkpoint <" + file_name
                               + "> failed: it does not read back (" + error
                               + "). Is the disk full? The previous "
                                 "checkpoints are kept."));
      }
    // Keep the newest two.
    if (root)
      {
        const auto files = checkpoint_files(directory);
        for (unsigned int k = 2; k < files.size(); ++k)
          fs::remove(files[k]);
      }
    const double seconds
      = std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    checkpoint_seconds += seconds;
    if (!params.quiet && root)
      std::cout << "  checkpoint " << file_name << ": " << std::setprecision(3)
                << fs::file_size(file_name) / 1e6 << " MB in " << seconds
                << " s" << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::check_checkpoint_parameters(const CheckpointReader &in) const
  {
    AssertThrow(in.scalar("fsgmpm/dim") == dim,
                ExcMessage("The checkpoint is of a "
                           + std::to_string(int(in.scalar("fsgmpm/dim")))
                           + "D run; this scene is " + std::to_string(dim)
                           + "D."));
    // "path = value" by path, without the parameters a restart may change
    // (also those that a checkpoint of an older version stored).
    const auto physics = [](const std::string &text) {
      std::map<std::string, std::string> values;
      std::istringstream                 lines(text);
      for (std::string line; std::getline(lines, line);)
        {
          const auto        equals = line.find(" = ");
          const std::string path   = line.substr(0, equals);
          if (!may_change_on_restart(path))
            values[path] = equals == std::string::npos
                             ? std::string()
                             : line.substr(equals + 3);
        }
      return values;
    };
    const auto file = physics(in.text("fsgmpm/parameters"));
    const auto here = physics(listing_text(parameter_listing));
    if (file == here)
      return;
    // Name the parameters that differ.
    std::set<std::string> paths;
    for (const auto &m : {file, here})
      for (const auto &entry : m)
        paths.insert(entry.first);
    std::string  differences;
    unsigned int n = 0;
    for (const auto &path : paths)
      {
        const auto a = file.find(path), b = here.find(path);
        if (a != file.end() && b != here.end() && a->second == b->second)
          continue;
        if (++n <= 5)
          differences += "\n  " + path + ": checkpoint "
                         + (a == file.end() ? "(none)" : "<" + a->second + ">")
                         + ", this run "
                         + (b == here.end() ? "(none)" : "<" + b->second + ">");
      }
    AssertThrow(false,
                ExcMessage(
                  "The scene's parameters differ from those of the "
                  "checkpointed run ("
                  + std::to_string(n) + " parameter(s)):" + differences
                  + "\nA restart may change only Output/*, Simulation/End "
                    "time, Maximum number of steps, Termination, Number "
                    "of threads, Repartition imbalance and a body's "
                    "Smoothing stabilisation; run the checkpointed scene's "
                    "prm with --restart."));
  }



  template <int dim>
  void
  Simulator<dim>::load_checkpoint(const CheckpointReader &in)
  {
    AssertThrow(in.has("membrane/position") == bool(membrane),
                ExcMessage("The checkpoint's scene and this one differ in "
                           "having a membrane."));
    time = in.scalar("run/time");
    time_step_control.set_state(in.doubles("run/dt"));
    step          = in.uints("run/step").at(0);
    const auto &m = in.doubles("run/monitors");
    AssertThrow(m.size() == Monitors::n_values,
                ExcMessage("The checkpoint holds " + std::to_string(m.size())
                           + " monitor values where this version of fsgmpm "
                             "keeps "
                           + std::to_string(Monitors::n_values)
                           + ": it was written by another version (or is "
                             "damaged); restart it with the version that "
                             "wrote it, or start the run anew."));
    std::array<double, Monitors::n_values> values;
    std::copy(m.begin(), m.end(), values.begin());
    monitors.set_values(values);
    relaxation.set_state(in.doubles("run/energies"), in.uints("run/counters"));
    stability_guard.set_state(in.doubles("run/stability_guard"));
    // (A checkpoint of an older version did not keep the largest creation:
    // it is then counted from the restart.)
    if (in.has("run/stability_guard_largest"))
      stability_guard.set_largest_state(
        in.doubles("run/stability_guard_largest"));

    resume_monitor_bytes = in.scalar("output/monitor_bytes");
    output_schedule.set_state(in.scalar("output/next_output_time"),
                              in.uints("output/last_output_step").at(0));
    checkpoint_schedule.set_state(in.scalar("output/next_checkpoint_time"), 0);
    resume_output         = {{{in.doubles("output/particle_series"),
                               in.doubles("output/grid_series"),
                               in.doubles("output/membrane_series")}},
                             {{in.doubles("output/particle_xdmf"),
                               in.doubles("output/membrane_xdmf")}}};
    previous_wall_seconds = in.scalar("cost/wall_seconds");
    // A checkpoint of another version may time other stages: then the
    // cost before the restart is left out of the stage times.
    restored_stage_seconds = in.doubles("cost/stage_seconds");
    particle_updates
      = static_cast<unsigned long long>(in.scalar("cost/particle_updates"));
    checkpoint_seconds = in.scalar("cost/checkpoint_seconds");

    // The points' cells are numbers in the whole grid (a process may hold
    // a window of it) until adopt_owners() below.
    StateCheckpoint::load(in, particles, grid->n_global_cells());
    if (membrane)
      {
        StateCheckpoint::load(in, *membrane);
        StateCheckpoint::load(in, *mpm_step->get_membrane_coupling());
      }
    if (partition)
      {
        // With as many processes as the checkpointed run, its partition
        // (the same cells, so the same sums, as the uninterrupted run), and
        // each process read its own points; otherwise a new partition, and
        // each process read an even share of the points (or, from a
        // checkpoint of an older version, all of them) and sends them to
        // their owners.
        const MPI_Comm     communicator = partition->get_communicator();
        const unsigned int ranks
          = in.has("mpi/ranks") ? in.uints("mpi/ranks").at(0) : 1;
        std::vector<unsigned int> owners;
        if (ranks == partition->n_ranks())
          {
            owners         = in.uints("mpi/cell_owner");
            n_repartitions = in.uints("mpi/repartitions").at(0);
          }
        else
          {
            // (From a checkpoint of an older version every process read
            // all points: process 0's count.)
            const ParticleStore<dim>        none;
            const std::vector<unsigned int> points_per_cell
              = DistributedPoints::points_per_cell_on_root(
                *grid,
                in.rows_split() || root ? particles : none,
                true,
                communicator);
            owners
              = DomainPartition<dim>::split(whole_grid ? *whole_grid : *grid,
                                            points_per_cell,
                                            communicator);
          }
        if (in.rows_split())
          particles.next_id
            = Utilities::MPI::max(particles.next_id, communicator);
        else
          {
            // Every process read all points: it keeps those of its cells.
            DomainPartition<dim>::check_owners(*grid,
                                               owners,
                                               partition->n_ranks());
            std::vector<std::uint8_t> flag(particles.size());
            for (unsigned int p = 0; p < particles.size(); ++p)
              flag[p] = owners[particles.cell[p]] != partition->rank();
            particles.remove_flagged(flag);
          }
        adopt_owners(owners);
        DistributedPoints::add_ghosts(*partition, particles);
      }
    // The nodal fields of the first step after the restart are rebuilt
    // from the points, as every step rebuilds them.
    rebuild_nodal_fields();
    if (partition)
      DistributedPoints::drop_ghosts(particles);
  }



  template <int dim>
  void
  Simulator<dim>::restart(const std::string &directory)
  {
    const fs::path dir = fs::path(directory) / "checkpoints";
    // MPI: process 0's list of the checkpoints counts; every process then
    // opens the file (CheckpointReader, collectively).
    std::vector<fs::path> files;
    {
      std::vector<std::string> names;
      for (const auto &file : checkpoint_files(dir))
        names.push_back(file.string());
      if (partition)
        names = Utilities::MPI::broadcast(partition->get_communicator(), names);
      files.assign(names.begin(), names.end());
    }
    AssertThrow(!files.empty(),
                ExcMessage("--restart " + directory + ": no checkpoint in <"
                           + dir.string()
                           + "> (a run writes them with Output/Checkpoint "
                             "interval > 0)."));
    std::string damaged;
    for (const auto &file : files)
      {
        std::unique_ptr<CheckpointReader> in;
        try
          {
            in = std::make_unique<CheckpointReader>(
              file.string(),
              partition ? partition->get_communicator() : MPI_COMM_SELF);
          }
        catch (const ExceptionBase &e)
          {
            damaged += "\n  " + message_of(e);
            if (root)
              std::cerr << "fsgmpm: warning: " << message_of(e)
                        << " Trying the one before it." << std::endl;
            continue;
          }
        check_checkpoint_parameters(*in);
        load_checkpoint(*in);
        AssertThrow(!time_step_control.reached_end(time, step),
                    ExcMessage(
                      "The checkpoint <" + file.string()
                      + "> is at t = " + std::to_string(time) + " s, step "
                      + std::to_string(step) + ", already at "
                      + (time_step_control.reached_end_time(time)
                           ? "Simulation/End time = "
                               + std::to_string(params.time_step.end_time)
                               + " s; raise it to continue."
                           : "Simulation/Maximum number of steps = "
                               + std::to_string(params.time_step.max_steps)
                               + "; raise it (or set 0, no limit) to "
                                 "continue.")));
        params.output_directory = directory;
        resumed                 = true;
        if (!params.quiet && root)
          std::cout << "fsgmpm: restarting from " << file.string()
                    << " (t = " << time << " s, step " << step << ")"
                    << std::endl;
        return;
      }
    AssertThrow(false,
                ExcMessage("--restart " + directory
                           + ": no checkpoint reads back intact:" + damaged));
  }



  // The members defined here (the class is instantiated in simulator.cc).
#define FSGMPM_INSTANTIATE(dim)                                            \
  template void Simulator<dim>::write_checkpoint(const double);            \
  template void Simulator<dim>::check_checkpoint_parameters(               \
    const CheckpointReader &) const;                                       \
  template void Simulator<dim>::load_checkpoint(const CheckpointReader &); \
  template void Simulator<dim>::restart(const std::string &);
  FSGMPM_INSTANTIATE(2)
  FSGMPM_INSTANTIATE(3)
#undef FSGMPM_INSTANTIATE
} // namespace fsgmpm
