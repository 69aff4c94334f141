#ifndef fsgmpm_simulator_h
#define fsgmpm_simulator_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/base/compensated_sum.h>
#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/boundary_conditions.h>
#include <fsgmpm/grid/nodal_fields.h>
#include <fsgmpm/io/run_output.h>
#include <fsgmpm/materials/material.h>
#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/monitors/scene_monitors.h>
#include <fsgmpm/parallel/domain_partition.h>
#include <fsgmpm/parallel/process_count.h>
#include <fsgmpm/particles/particle_store.h>
#include <fsgmpm/run/dynamic_relaxation.h>
#include <fsgmpm/run/monitors.h>
#include <fsgmpm/run/output_schedule.h>
#include <fsgmpm/run/stability_guard.h>
#include <fsgmpm/run/termination.h>
#include <fsgmpm/run/time_step_control.h>
#include <fsgmpm/scene/body.h>
#include <fsgmpm/scene/parameters.h>
#include <fsgmpm/step/material_options.h>
#include <fsgmpm/step/mpm_step.h>
#include <fsgmpm/step/smoothing_fields.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace fsgmpm
{
  class MonitorFile;
  class CheckpointWriter;
  class CheckpointReader;

  /**
   * A scene and its run: owns the grid, the points, the materials, the
   * membrane (the state), the explicit step that advances them (MpmStep)
   * and the run control around it, each a piece of its own that a program
   * can also use alone: TimeStepControl (the step), StabilityGuard,
   * EnergyBalance and DynamicRelaxation (the energy bookkeeping, Eq. 30,
   * kinetic damping, rest), OutputSchedule and RunOutput (when and what is
   * written), the scene monitors. The constructor reads and validates the
   * whole scene and builds everything, but writes nothing; run() creates
   * the output directory and writes as it goes.
   */
  template <int dim>
  class Simulator
  {
  public:
    explicit Simulator(ParameterHandler &prm);
    ~Simulator();

    /// Run to the end (time, steps, convergence or instability) and write
    /// output. Returns the termination reason.
    Termination
    run();

    /**
     * Continue the run whose output is in @p directory from the newest of
     * its checkpoints (@p directory/checkpoints, Output/Checkpoint
     * interval) that reads back intact; a damaged one is reported and the
     * one before it is used. Call before run(), which then appends to the
     * run's monitors.csv (cut back to the checkpoint's step) and output
     * series in @p directory. The scene's parameters must be those of the
     * checkpointed run, except those under Output, Simulation/End time, Maximum
     * number of steps, Termination and Number of threads.
     */
    void
    restart(const std::string &directory);

    /// Advance one time step without any file output. Returns false and
    /// sets the termination reason when the run must stop.
    bool
    advance();

    /// Call after changing particle data directly (e.g. prescribing an
    /// initial velocity field): recomputes the monitors and restarts the
    /// energy history of the stability guard.
    void
    reinitialize_state();

    // --- state access (tests, postprocessing) ---------------------------
    const ParticleStore<dim> &
    get_particles() const
    {
      return particles;
    }
    ParticleStore<dim> &
    get_particles()
    {
      return particles;
    }
    /// The grid the step runs on: the whole grid, or in an MPI run this
    /// process's window of it.
    const BackgroundGrid<dim> &
    get_grid() const
    {
      return *grid;
    }
    const NodalFields<dim> &
    get_nodes() const
    {
      return nodes;
    }
    const Monitors &
    get_monitors() const
    {
      return monitors;
    }

    /// The energy balance's guard (its residual and scale).
    const StabilityGuard &
    get_stability_guard() const
    {
      return stability_guard;
    }
    const std::vector<MaterialOptions> &
    get_material_options() const
    {
      return material_options;
    }
    /// Values of the scene monitors (names in get_scene_monitor_names()).
    std::vector<double>
    get_scene_monitors() const
    {
      return scene_monitors->evaluate(particles, membrane.get());
    }
    /// The membrane, or nullptr if the scene has none.
    const Membrane<dim> *
    get_membrane() const
    {
      return membrane.get();
    }
    const std::vector<std::string> &
    get_scene_monitor_names() const
    {
      return scene_monitors->names();
    }
    /// The scene monitor registered as @p name (monitors/monitor_factory.h)
    /// if Monitors/Scene monitors selects it; throws otherwise.
    const SceneMonitor<dim> &
    get_scene_monitor(const std::string &name) const
    {
      return scene_monitors->get(name);
    }
    /// The current value of the scene monitors' column @p column (e.g.
    /// front_position); throws, naming the columns, if there is none.
    double
    get_scene_monitor_value(const std::string &column) const;
    const std::vector<std::unique_ptr<Material>> &
    get_materials() const
    {
      return materials;
    }
    double
    get_time() const
    {
      return time;
    }
    unsigned int
    get_step() const
    {
      return step;
    }
    double
    get_dt() const
    {
      return time_step_control.dt();
    }
    Termination
    get_termination() const
    {
      return termination;
    }
    /// The signal (SIGTERM or SIGINT) that interrupted the run (termination
    /// interrupted), or 0.
    int
    get_interrupt_signal() const
    {
      return interrupt_signal;
    }
    /// Diagnosis when the termination is unstable or error, what stopped
    /// the run when it was interrupted.
    const std::string &
    get_diagnosis() const
    {
      return diagnosis;
    }
    /// Steps for which both Eq. (30) ratios have been below tolerance.
    unsigned int
    get_converged_steps() const
    {
      return relaxation.converged_steps();
    }
    /// MPI: how often the cells were split again (Simulation/Repartition
    /// imbalance).
    unsigned int
    get_n_repartitions() const
    {
      return n_repartitions;
    }
    const Parameters<dim> &
    get_parameters() const
    {
      return params;
    }

    /// Bytes of the grid (its arrays, deal.II mesh and DoF handler), the
    /// nodal fields and the smoothing fields, divided by the number of
    /// points (the points' own: ParticleStore::bytes_per_particle()).
    double
    get_grid_memory_per_particle() const;

    /// Names of the timed stages: MpmStep's in step order, then the run
    /// control's (monitors, kinetic damping, output).
    static const std::vector<std::string> &
    stage_names();
    /// Wall seconds per stage so far, in stage_names() order.
    std::vector<double>
    get_stage_seconds() const;

    /// The explicit step this run drives.
    MpmStep<dim> &
    get_mpm_step()
    {
      return *mpm_step;
    }
    /// The run control's pieces.
    const TimeStepControl &
    get_time_step_control() const
    {
      return time_step_control;
    }
    const DynamicRelaxation &
    get_dynamic_relaxation() const
    {
      return relaxation;
    }

  private:
    /// The nodal fields rebuilt from the points (with the ghost points
    /// present, MPI), as the first stage of a step builds them: Stages::p2g
    /// with the projection's halo updates, then the membrane's share.
    void
    rebuild_nodal_fields();
    /// The membrane, its cells located on the whole grid; the mesh's cell
    /// size and z range given (a window may not have the grid yet).
    void
    setup_membrane(ParameterHandler               &prm,
                   const Point<dim>               &cell_size,
                   const std::pair<double, double> z_range);
    /// Fill the bodies; with MPI, partition the cells by the points of
    /// each and keep this process's points.
    void
    setup_bodies();
    /// Fill every body in order (fill_body(): @p keep_cell, one flag per
    /// base cell, and @p points_per_cell, per cell of every velocity field),
    /// with their initial stresses.
    /// @p first_ids (one per body and base cell of the whole grid, body by
    /// body): with @p points_per_cell, the id of the first point of each
    /// body in each cell, computed; without, a window's fill takes them.
    void
    fill_bodies(const std::vector<std::uint8_t> *keep_cell,
                std::vector<unsigned int>       *points_per_cell,
                std::vector<unsigned int>       *first_ids = nullptr);
    /// The energies of monitors.csv (at the start of a run).
    void
    compute_monitors();
    /// After a step: this process's energies and the grid's kinetic energy
    /// of Eq. (30) (EnergyBalance::local_energies()), to be summed over the
    /// processes.
    std::vector<CompensatedSum>
    local_energies() const;
    /// (flagged, detecting) points from Stages::detect_free_surface.
    void
    set_free_surface_fraction(const std::pair<unsigned int, unsigned int> &n)
    {
      monitors.free_surface_fraction
        = n.second > 0 ? double(n.first) / n.second : 0.;
    }
    bool
    check_stability(const double displacement_ratio);
    void
    write_summary(const double wall_seconds) const;
    /// Write the whole state to Output/Directory/checkpoints (keeps two).
    void
    write_checkpoint(const double wall_seconds);
    /// Refuse a checkpoint written with other (physical) parameters.
    void
    check_checkpoint_parameters(const CheckpointReader &in) const;
    void
    load_checkpoint(const CheckpointReader &in);
    Tensor<1, dim>
    current_gravity() const;
    /// MPI: refuses what is not distributed yet (setup_bodies() split the
    /// cells over the processes).
    void
    setup_partition();
    /// (flagged, detecting) free-surface points of this process's own
    /// points.
    std::pair<unsigned int, unsigned int>
    local_free_surface_counts() const;
    /// (flagged, detecting) free-surface points over all processes, counted
    /// on the points each process owns.
    std::pair<unsigned int, unsigned int>
    count_free_surface() const;
    /// The number of points over all processes.
    unsigned int
    n_global_particles() const;
    /// MPI: split the cells again if the points are out of balance
    /// (Simulation/Repartition imbalance) and move the points to their new
    /// owners. At the start of a step (no ghosts held; the output between
    /// steps needs the partition the nodal values were computed with).
    /// @p point_counts: the points per process (sum and maximum).
    void
    rebalance(const Utilities::MPI::MinMaxAvg &point_counts);
    /**
     * MPI: take @p owners (of the cells of the whole grid) as the
     * partition, and move the points, whose cells are numbered in the
     * whole grid on entry, to their owners. A process then holds only its
     * window of the grid (DomainPartition::window_cells()), which process
     * 0 cuts from the whole grid and sends; process 0 keeps the whole grid
     * (whole_grid) for METIS and the grid's output. Every process holds
     * the whole membrane (MembraneCoupling).
     */
    void
    adopt_owners(const std::vector<unsigned int> &owners);

    Parameters<dim>                   params;
    std::vector<BodyDescription<dim>> bodies;
    /// The grid the step runs on: the whole grid, or with MPI this
    /// process's window of it (adopt_owners()).
    std::unique_ptr<BackgroundGrid<dim>> grid;
    /// Process 0 of an MPI run on windows: the whole grid.
    std::unique_ptr<BackgroundGrid<dim>>   whole_grid;
    std::unique_ptr<NodalConstraints<dim>> constraints;
    NodalFields<dim>                       nodes;
    ParticleStore<dim>                     particles;
    std::vector<std::unique_ptr<Material>> materials;
    std::vector<MaterialOptions>           material_options;
    SmoothingFields<dim>                   smoothing;
    std::unique_ptr<SceneMonitors<dim>>    scene_monitors;
    /// The geomembrane (FEM-MPM coupling), if the scene has one; cables
    /// longer than membrane_split_length are split.
    std::unique_ptr<Membrane<dim>> membrane;
    double                         membrane_split_length = 0;
    /// Membrane/Impermeable to points.
    bool membrane_impermeable = true;
    /// The outline the bodies with Shape = membrane fill (x-y, z range).
    std::vector<Point<2>>     membrane_outline;
    std::pair<double, double> membrane_z_range;

    double            time = 0;
    unsigned int      step = 0;
    TimeStepControl   time_step_control;
    Monitors          monitors;
    DynamicRelaxation relaxation;
    Termination       termination = Termination::running;
    std::string       diagnosis;
    /// Interruption::received_signal() as the processes agreed on it in
    /// the last step (MPI: the strongest of their signals, SIGTERM over
    /// SIGINT), or 0.
    int            interrupt_signal = 0;
    StabilityGuard stability_guard;

    std::unique_ptr<MpmStep<dim>> mpm_step;
    /// MPI runs with more than one process: who owns which cell (null in
    /// serial). Rank 0 writes the files.
    std::unique_ptr<DomainPartition<dim>> partition;
    bool                                  root = true;
    /// MPI (more than one process): each process holds its window of the
    /// grid, process 0 the whole grid besides (adopt_owners()).
    static bool
    on_windows()
    {
      return Parallel::n_processes(MPI_COMM_WORLD) > 1;
    }
    /// MPI statistics for summary.json: repartitions so far, the ghost
    /// points of the last step (this process's ratio to its owned points;
    /// write_summary() takes the largest) and the last max/mean points per
    /// process.
    unsigned int n_repartitions = 0;
    double       halo_fraction = 0, imbalance = 1;
    /// Wall seconds of the run-control stages, and of all stages before a
    /// restart (from the checkpoint).
    std::vector<double>          run_stage_seconds, restored_stage_seconds;
    std::unique_ptr<MonitorFile> monitor_file;
    /// The columns of monitors.csv (without their units) and the last row
    /// written, for summary.json.
    std::vector<std::string>        monitor_columns;
    std::vector<std::string>        monitor_units;
    std::vector<double>             last_monitor_row;
    std::unique_ptr<RunOutput<dim>> output;
    OutputSchedule                  output_schedule, checkpoint_schedule;
    unsigned long long              particle_updates = 0;
    /// Points this process put back on their side of the membrane.
    unsigned long long membrane_crossings = 0;

    /// Every parameter ("Section/Name", value), for the checkpoint.
    std::vector<std::pair<std::string, std::string>> parameter_listing;
    /// Wall seconds spent writing checkpoints (summary.json).
    double checkpoint_seconds = 0;
    /// Set by restart(): the state came from a checkpoint, with these
    /// bytes of monitors.csv, wall seconds and output series before it.
    bool                           resumed               = false;
    double                         resume_monitor_bytes  = 0;
    double                         previous_wall_seconds = 0;
    typename RunOutput<dim>::State resume_output;
  };
} // namespace fsgmpm

#endif
