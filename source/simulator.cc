#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/base/broadcast_vector.h>
#include <fsgmpm/base/compensated_sum.h>
#include <fsgmpm/base/format.h>
#include <fsgmpm/base/version.h>
#include <fsgmpm/grid/mesh_generation.h>
#include <fsgmpm/io/membrane_output.h>
#include <fsgmpm/io/monitor_file.h>
#include <fsgmpm/membrane/membrane_geometry.h>
#include <fsgmpm/parallel/distributed_points.h>
#include <fsgmpm/parallel/process_count.h>
#include <fsgmpm/particles/body_filler.h>
#include <fsgmpm/particles/point_locator.h>
#include <fsgmpm/run/energy_balance.h>
#include <fsgmpm/run/interruption.h>
#include <fsgmpm/scene/parameter_path.h>
#include <fsgmpm/simulator.h>
#include <fsgmpm/step/cell_loops.h>
#include <fsgmpm/step/stages.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>
#include <utility>

#ifdef __GLIBC__
#  include <malloc.h>
#endif

namespace fsgmpm
{
  namespace
  {
    /// The run-control stages timed besides MpmStep's.
    const std::vector<std::string> run_stage_names
      = {"monitors", "kinetic_damping", "output", "mpi_points"};
    enum RunStage : unsigned int
    {
      monitor_stage,
      kinetic_damping_stage,
      output_stage,
      /// MPI: sending ghost copies, migrating and rebalancing points.
      mpi_points_stage
    };

    template <int dim>
    typename MpmStep<dim>::Settings
    step_settings(const Parameters<dim> &params)
    {
      typename MpmStep<dim>::Settings settings;
      settings.stress_integration         = params.stress_integration;
      settings.use_musl                   = params.use_musl;
      settings.apic_affine_remap          = params.apic_affine_remap;
      settings.flip_noise_relaxation_time = params.flip_noise_relaxation_time;
      settings.xpic_order                 = params.xpic_order;
      settings.local_damping              = params.local_damping;
      settings.courant                    = params.time_step.courant;
      settings.mass_scaling               = params.mass_scaling;
      settings.contact_friction           = params.contact_friction;
      settings.contact_volume_fraction    = params.contact_volume_fraction;
      return settings;
    }
  } // namespace



  template <int dim>
  const std::vector<std::string> &
  Simulator<dim>::stage_names()
  {
    static const std::vector<std::string> names = [] {
      std::vector<std::string> n = MpmStep<dim>::stage_names();
      n.insert(n.end(), run_stage_names.begin(), run_stage_names.end());
      return n;
    }();
    return names;
  }



  template <int dim>
  std::vector<double>
  Simulator<dim>::get_stage_seconds() const
  {
    std::vector<double> seconds = mpm_step->stage_seconds();
    for (const double s : run_stage_seconds)
      seconds.push_back(s);
    // Plus what the run spent before its restart.
    if (restored_stage_seconds.size() == seconds.size())
      for (unsigned int s = 0; s < seconds.size(); ++s)
        seconds[s] += restored_stage_seconds[s];
    return seconds;
  }



  template <int dim>
  Simulator<dim>::Simulator(ParameterHandler &prm)
    : params(prm)
    , time_step_control(params.time_step)
    , relaxation(params.relaxation)
    , stability_guard(params.stability)
    , run_stage_seconds(run_stage_names.size(), 0.)
    , output_schedule(params.output_interval, params.output_every_steps)
    , checkpoint_schedule(params.checkpoint_interval)
    , parameter_listing(parameter_values(prm))
  {
    if (params.n_threads > 0)
      MultithreadInfo::set_thread_limit(params.n_threads);

    bodies = BodyDescription<dim>::parse_bodies(prm);

    // MPI: process 0 builds the grid (a Gmsh file's from deal.II's mesh),
    // which no other process ever holds whole. The run is on windows of the
    // grid: process 0 alone holds the whole grid and sends each process its
    // window once the cells are split (setup_bodies()). An error on process 0
    // stops every process (main()).
    root
      = !on_windows() || Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    if (root && params.grid_type == "box")
      // A box's grid straight from its vertices and cells: creating
      // deal.II's Triangulation of it was the peak of the run's memory
      // (doc/performance.md, "A box's grid without deal.II's mesh").
      grid
        = std::make_unique<BackgroundGrid<dim>>(MeshGeneration::box_simplices(
          params.lower_corner, params.upper_corner, params.subdivisions));
    else if (root && params.grid_type == "extruded box")
      {
        if constexpr (dim == 3)
          grid = std::make_unique<BackgroundGrid<dim>>(
            MeshGeneration::extrude_simplices(
              MeshGeneration::box_simplices(
                Point<2>(params.lower_corner[0], params.lower_corner[1]),
                Point<2>(params.upper_corner[0], params.upper_corner[1]),
                params.subdivisions),
              params.extrusion_thickness));
      }
    else if (root)
      {
        Triangulation<dim> triangulation;
        MeshGeneration::read_gmsh(params.mesh_file, triangulation);
        grid = std::make_unique<BackgroundGrid<dim>>(std::move(triangulation));
#ifdef __GLIBC__
        // The mesh's many small blocks are free now; give their pages back
        // (glibc keeps a freed heap resident otherwise).
        malloc_trim(0);
#endif
      }
    else
      grid = std::make_unique<BackgroundGrid<dim>>();
    // What follows needs the whole grid: with windows, process 0 does it
    // (a window gets the velocity fields and nodal volumes from it).
    if (root)
      {
        unsigned int n_fields = 1;
        for (const auto &body : bodies)
          n_fields = std::max(n_fields, body.velocity_field + 1);
        if (n_fields > 1)
          grid->set_velocity_fields(n_fields);
        // The nodal volumes: read only by the contact and APIC's affine
        // remap.
        if (n_fields > 1 || params.apic_affine_remap)
          grid->compute_node_volumes();

        // Every boundary id named in the wall conditions must exist.
        std::set<types::boundary_id> mesh_ids;
        for (const auto &face : grid->boundary_faces)
          mesh_ids.insert(face.boundary_id);
        for (const auto &[id, wall] : params.walls)
          AssertThrow(mesh_ids.count(id) == 1,
                      ExcMessage("Grid/Boundary conditions names boundary id "
                                 + std::to_string(id)
                                 + ", but the mesh has no boundary face with "
                                   "that id."));

        constraints
          = std::make_unique<NodalConstraints<dim>>(*grid,
                                                    params.walls,
                                                    params.moving_wall);
      }
    // On windows the nodal fields are sized for the window (adopt_owners()):
    // process 0's whole grid never gets them.
    if (!on_windows())
      nodes.resize(grid->n_nodes());

    const auto cell_size = [this]() {
      Point<dim> h;
      for (unsigned int d = 0; d < dim; ++d)
        h[d] = (params.grid_type != "gmsh")
                 ? (params.upper_corner[d] - params.lower_corner[d])
                     / params.subdivisions[std::min<unsigned int>(
                       d, params.subdivisions.size() - 1)]
                 : grid->max_altitude_global;
      return h;
    };
    // The membrane's mesh and fill need the cell size and the mesh's z
    // range. With windows a process's grid is empty until setup_bodies()
    // gives it its window: process 0 sends them.
    std::pair<Point<dim>, std::pair<double, double>> h_and_z;
    if (root)
      h_and_z = {cell_size(),
                 {grid->lower_corner[dim - 1], grid->upper_corner[dim - 1]}};
    if (on_windows())
      h_and_z = Utilities::MPI::broadcast(MPI_COMM_WORLD, h_and_z, 0);
    setup_membrane(prm, h_and_z.first, h_and_z.second);
    setup_bodies();
    scene_monitors = std::make_unique<SceneMonitors<dim>>(
      prm, grid->lower_corner, cell_size(), bodies.size(), membrane != nullptr);
    setup_partition();
    smoothing.resize(materials.size(), grid->n_nodes());
    mpm_step = std::make_unique<MpmStep<dim>>(*grid,
                                              *constraints,
                                              materials,
                                              material_options,
                                              step_settings(params),
                                              particles,
                                              nodes,
                                              smoothing);
    if (membrane)
      mpm_step->attach_membrane(*membrane,
                                membrane_split_length,
                                membrane_impermeable);
    if (partition)
      mpm_step->attach_partition(*partition);

    reinitialize_state();
  }



  template <int dim>
  void
  Simulator<dim>::setup_partition()
  {
    if (Parallel::n_processes(MPI_COMM_WORLD) == 1)
      return;
    const std::string n_ranks
      = std::to_string(Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
    auto refuse = [&](const bool ok, const std::string &what) {
      AssertThrow(ok,
                  ExcMessage(what
                             + " does not run on more than one MPI "
                               "process yet (this run has "
                             + n_ranks + "); run it with one process."));
    };
    const std::string others = scene_monitors->not_distributed();
    refuse(others.empty(), "The scene monitor(s) " + others);

    // setup_bodies() partitioned the cells and filled this process's.
    Assert(partition, ExcInternalError());
  }



  template <int dim>
  std::pair<unsigned int, unsigned int>
  Simulator<dim>::local_free_surface_counts() const
  {
    // Between steps: no ghost copies are held.
    Assert(particles.ghost.empty(), ExcInternalError());
    std::pair<unsigned int, unsigned int> n = {0, 0};
    for (unsigned int p = 0; p < particles.size(); ++p)
      if (material_options[particles.material_id[p]].detect_free_surface)
        {
          n.first += particles.free_surface[p];
          ++n.second;
        }
    return n;
  }



  template <int dim>
  std::pair<unsigned int, unsigned int>
  Simulator<dim>::count_free_surface() const
  {
    const auto      n    = local_free_surface_counts();
    const MPI_Comm &comm = partition->get_communicator();
    return {Utilities::MPI::sum(n.first, comm),
            Utilities::MPI::sum(n.second, comm)};
  }



  template <int dim>
  unsigned int
  Simulator<dim>::n_global_particles() const
  {
    return partition ? DistributedPoints::global_size(*partition, particles)
                     : particles.size();
  }



  template <int dim>
  void
  Simulator<dim>::rebalance(const Utilities::MPI::MinMaxAvg &point_counts)
  {
    const MPI_Comm &comm   = partition->get_communicator();
    const double    n_mean = point_counts.sum / partition->n_ranks();
    imbalance              = n_mean > 0 ? point_counts.max / n_mean : 1.;
    if (params.repartition_imbalance == 0
        || imbalance <= params.repartition_imbalance)
      return;
    // The points of every cell of the whole grid, for METIS on process 0.
    const std::vector<unsigned int> points_per_cell
      = DistributedPoints::points_per_cell_on_root(*grid,
                                                   particles,
                                                   false,
                                                   comm);
    const std::vector<unsigned int> owners
      = DomainPartition<dim>::split(whole_grid ? *whole_grid : *grid,
                                    points_per_cell,
                                    comm);
    for (unsigned int &c : particles.cell)
      c = grid->global_cell(c);
    adopt_owners(owners);
    ++n_repartitions;
  }



  template <int dim>
  void
  Simulator<dim>::rebuild_nodal_fields()
  {
    Stages::p2g(
      *grid,
      particles,
      nodes,
      params.stress_integration,
      [this](const unsigned int pass) {
        mpm_step->synchronise_projection(pass);
      },
      mpm_step->projection_stabilisation());
    if (membrane)
      mpm_step->get_membrane_coupling()->p2g(nodes);
  }



  template <int dim>
  void
  Simulator<dim>::reinitialize_state()
  {
    particles.sort_by_cell(grid->n_cells());
    if (partition)
      DistributedPoints::add_ghosts(*partition, particles);
    rebuild_nodal_fields();
    // A fixed time step above the explicit limit is refused now, before
    // the run writes anything, with the message its first step would give
    // (the same state, nodal masses and bound).
    if (params.time_step.fixed_dt > 0)
      {
        double dt_stable = mpm_step->stable_time_step();
        if (partition)
          dt_stable
            = Utilities::MPI::min(dt_stable, partition->get_communicator());
        const std::string problem
          = time_step_control.check_fixed(dt_stable, step + 1);
        AssertThrow(problem.empty(), ExcMessage(problem));
      }
    set_free_surface_fraction(Stages::detect_free_surface(
      *grid, nodes, material_options, smoothing, particles, [this]() {
        mpm_step->synchronise_free_surface();
      }));
    if (partition)
      {
        DistributedPoints::drop_ghosts(particles);
        set_free_surface_fraction(count_free_surface());
      }
    compute_monitors();
    double potential
      = EnergyBalance::potential_energy_above(particles,
                                              params.gravity,
                                              grid->lower_corner);
    if (partition)
      potential = Utilities::MPI::sum(potential, partition->get_communicator());
    relaxation.reset(monitors, potential);
    stability_guard.reset(monitors, potential);
  }



  template <int dim>
  Simulator<dim>::~Simulator() = default;



  template <int dim>
  void
  Simulator<dim>::setup_membrane(ParameterHandler               &prm,
                                 const Point<dim>               &cell_size,
                                 const std::pair<double, double> z_range)
  {
    const MembraneDescription<dim> description(prm);
    if (!description.enabled)
      {
        for (const auto &body : bodies)
          AssertThrow(!body.fills_membrane,
                      ExcMessage(body.path
                                 + "/Shape = membrane needs a membrane "
                                   "(Membrane/Enabled = true)."));
        return;
      }
    const double h   = cell_size[0];
    membrane_z_range = z_range;
    if (description.shape != "gmsh")
      membrane_outline = description.outline(h);

    Triangulation<dim - 1, dim>                                 mesh;
    std::map<std::pair<unsigned int, unsigned int>, Point<dim>> middle_points;
    description.make_mesh(h, membrane_z_range, mesh, &middle_points);
    membrane = std::make_unique<Membrane<dim>>(mesh,
                                               description.properties,
                                               middle_points);
    // A Gmsh surface extruded along z (a closed ring of nodes at each z
    // level) can be filled like an ellipse or polygon: its cross-section is
    // the lowest ring, counter-clockwise.
    if (description.shape == "gmsh" && !membrane->rings.empty())
      {
        for (const unsigned int a : membrane->rings.front())
          membrane_outline.emplace_back(membrane->position[a][0],
                                        membrane->position[a][1]);
        if (MembraneGeometry::signed_area(membrane_outline) < 0)
          std::reverse(membrane_outline.begin(), membrane_outline.end());
        // The fill spans the grid's z range (the slab's walls close the
        // ends); a shorter surface would leave fill outside it.
        double z_low = std::numeric_limits<double>::max(), z_high = -z_low;
        for (const auto &x : membrane->position)
          {
            z_low  = std::min(z_low, x[dim - 1]);
            z_high = std::max(z_high, x[dim - 1]);
          }
        const double tolerance
          = 1e-6 * (membrane_z_range.second - membrane_z_range.first);
        for (const auto &body : bodies)
          AssertThrow(!body.fills_membrane
                        || (z_low <= membrane_z_range.first + tolerance
                            && z_high >= membrane_z_range.second - tolerance),
                      ExcMessage(
                        body.path
                        + "/Shape = membrane fills the Gmsh surface over the "
                          "grid's z range ["
                        + format(membrane_z_range.first) + ", "
                        + format(membrane_z_range.second)
                        + "], but the surface spans only z in [" + format(z_low)
                        + ", " + format(z_high)
                        + "]: extrude it over the whole grid, or fit the grid "
                          "to it."));
      }
    for (const auto &body : bodies)
      AssertThrow(!body.fills_membrane || !membrane_outline.empty(),
                  ExcMessage(body.path
                             + "/Shape = membrane needs a membrane given as "
                               "an ellipse or polygon, or a Gmsh surface "
                               "extruded along z (a closed ring of nodes at "
                               "each z level)."));
    membrane->tangential_slip = description.tangential_slip;
    AssertThrow(!membrane->tangential_slip || dim == 2
                  || !membrane->rings.empty(),
                ExcMessage("Membrane/Tangential coupling = slip: the 3D "
                           "membrane is not an extrusion along z (no closed "
                           "ring of nodes at each z level)."));
    if (std::isfinite(description.ground_level))
      {
        membrane->ground.level     = description.ground_level;
        membrane->ground.stiffness = description.ground_stiffness;
        membrane->compute_forces();
      }
    AssertThrow(dim == 3 || membrane->is_closed_loop(),
                ExcMessage("The membrane must be one closed loop."));
    membrane_split_length = description.split_fraction * h;
    membrane_impermeable  = description.impermeable_to_points;

    // The nodes' cells, by whole-grid numbers: with windows process 0
    // (which alone holds the whole grid) finds them for all.
    if (root)
      {
        const PointLocator<dim> locator(*grid);
        for (unsigned int a = 0; a < membrane->n_nodes(); ++a)
          {
            // As a walk from cell 0, else the search of all cells; the
            // search starts near the previous node.
            membrane->cell[a]
              = locator.locate(membrane->position[a],
                               0,
                               a > 0 ? membrane->cell[a - 1] : 0);
            AssertThrow(membrane->cell[a] != BackgroundGrid<dim>::invalid,
                        ExcMessage("Membrane node " + std::to_string(a) + " at "
                                   + "(" + format(membrane->position[a]) + ")"
                                   + " lies outside the mesh; move or shrink "
                                     "the membrane (Membrane/Lowest point, "
                                     "Circumference and Enclosed area, or "
                                     "Polygon vertices) or enlarge the grid."));
          }
      }
    if (on_windows())
      Parallel::broadcast_vector(membrane->cell, MPI_COMM_WORLD, 0);
    AssertThrow(membrane->max_element_length()
                    <= membrane_split_length * (1 + 1e-9)
                  || dim == 2,
                ExcMessage("Membrane elements are longer than Membrane/"
                           "Split length grid cells; use a finer membrane "
                           "mesh (Membrane/Mesh file or Element size)."));
  }



  template <int dim>
  void
  Simulator<dim>::setup_bodies()
  {
    for (auto &body : bodies)
      if (body.fills_membrane)
        body.shape
          = std::make_unique<CrossSectionShape<dim>>(membrane_outline,
                                                     membrane_z_range.first,
                                                     membrane_z_range.second);
    // The bodies are filled twice: first counting the points of each cell
    // (storing none), then storing the points kept, in arrays of the exact
    // size (filled by push_back they kept up to half their room unused: 33
    // B of 329 B per point in the 2D dam break). MPI: no process holds all
    // points; the partition weighs the counts and a process stores the
    // points of its own cells, each with the id, and so the place, it has
    // in a serial run. With windows, process 0 alone counts (it alone
    // holds the whole grid), and hands every process its window and the
    // ids of the first points of each body in each cell.
    std::vector<unsigned int> points_per_cell, first_ids;
    if (root)
      {
        points_per_cell.assign(grid->n_cells(), 0);
        const std::vector<std::uint8_t> store_none(grid->n_base_cells(), 0);
        fill_bodies(&store_none,
                    &points_per_cell,
                    on_windows() ? &first_ids : nullptr);
      }
    const unsigned int        n_points = particles.next_id;
    std::vector<std::uint8_t> mine; // empty: keep every point (serial)
    std::vector<unsigned int> owners;
    unsigned int              n_kept = 0;
    if (Parallel::n_processes(MPI_COMM_WORLD) > 1)
      {
        const MPI_Comm comm = MPI_COMM_WORLD;
        owners = DomainPartition<dim>::split(*grid, points_per_cell, comm);
        const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
        // The points each process keeps, for the exact room.
        std::vector<unsigned int> kept(Utilities::MPI::n_mpi_processes(comm),
                                       0);
        for (unsigned int c = 0; c < points_per_cell.size(); ++c)
          kept[owners[c]] += points_per_cell[c];
        const int ierr = MPI_Scatter(
          kept.data(), 1, MPI_UNSIGNED, &n_kept, 1, MPI_UNSIGNED, 0, comm);
        AssertThrowMPI(ierr);
        Parallel::broadcast_vector(first_ids, comm, 0);
        adopt_owners(owners);
        mine.resize(grid->n_base_cells());
        for (unsigned int c = 0; c < grid->n_base_cells(); ++c)
          mine[c] = owners[grid->global_cell(c)] == rank;
      }
    else
      for (const unsigned int n : points_per_cell)
        n_kept += n;
    particles = ParticleStore<dim>();
    particles.reserve(n_kept);
    fill_bodies(mine.empty() ? nullptr : &mine,
                nullptr,
                on_windows() ? &first_ids : nullptr);
    // On a window the fill ends at the last cell it holds: the next point
    // added (none yet) gets the id after the serial fill's last.
    if (!owners.empty())
      particles.next_id = Utilities::MPI::max(n_points, MPI_COMM_WORLD);
    for (auto &body : bodies)
      {
        material_options.push_back(body.options);
        materials.push_back(std::move(body.material));
      }
    if (params.use_apic)
      particles.enable_affine_velocity();
    // The displacement in the output, where a body is a solid.
    if (std::any_of(materials.begin(), materials.end(), [](const auto &m) {
          return !m->is_fluid();
        }))
      particles.enable_initial_position();
    // The plastic strain and yield flag in the output, where a material
    // yields.
    if (std::any_of(materials.begin(), materials.end(), [](const auto &m) {
          return m->yields();
        }))
      particles.enable_plasticity();
    particles.sort_by_cell(grid->n_cells());
  }



  template <int dim>
  void
  Simulator<dim>::adopt_owners(const std::vector<unsigned int> &owners)
  {
    const MPI_Comm     comm    = MPI_COMM_WORLD;
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    // Every process checks the owners before any of them waits for a
    // window, so that bad ones (a checkpoint's) stop all alike. (At the
    // start a process other than 0 has no grid yet, and the owners are
    // METIS's.)
    if (grid->n_cells() > 0)
      DomainPartition<dim>::check_owners(*grid, owners, n_ranks);
    Assert(on_windows(), ExcInternalError());
    if (root && !whole_grid)
      whole_grid = std::make_unique<BackgroundGrid<dim>>(std::move(*grid));
    // In place: the step and the constraints refer to *grid.
    if (root)
      {
        std::vector<std::vector<unsigned int>> cells
          = DomainPartition<dim>::all_window_cells(*whole_grid,
                                                   owners,
                                                   n_ranks);
        for (unsigned int q = 1; q < n_ranks; ++q)
          {
            whole_grid->send_window(cells[q], q, comm);
            cells[q] = std::vector<unsigned int>();
          }
        *grid = whole_grid->window(cells[0]);
      }
    else
      *grid = BackgroundGrid<dim>::receive_window(0, comm);
    // In place too (the step refers to it); none yet at the start.
    NodalConstraints<dim> window_constraints(*grid,
                                             params.walls,
                                             params.moving_wall);
    if (constraints)
      *constraints = std::move(window_constraints);
    else
      constraints = std::make_unique<NodalConstraints<dim>>(
        std::move(window_constraints));
    constraints->set_time(time);
    nodes.resize(grid->n_nodes());
    smoothing.resize(materials.size(), grid->n_nodes());
    partition = std::make_unique<DomainPartition<dim>>(comm, *grid);
    partition->set_owners(owners);
    DistributedPoints::move_to_owners(*partition, particles);
    if (mpm_step)
      mpm_step->attach_partition(*partition);
  }



  template <int dim>
  void
  Simulator<dim>::fill_bodies(const std::vector<std::uint8_t> *keep_cell,
                              std::vector<unsigned int>       *points_per_cell,
                              std::vector<unsigned int>       *first_ids)
  {
    // Bodies fill in order: a body leaves out the regions of those before
    // it, so a water tank listed after a bag surrounds it without a second
    // mass inside.
    std::vector<const BodyShape<dim> *> taken;
    std::vector<unsigned int>           per_base_cell;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        BodyDescription<dim> &body     = bodies[b];
        const unsigned int    first    = particles.size();
        const unsigned int    first_id = particles.next_id;
        if (points_per_cell)
          per_base_cell.assign(grid->n_base_cells(), 0);
        // A window's cells: the ids of their first points in the whole
        // grid's fill.
        std::vector<unsigned int> cell_first_id;
        if (first_ids && !points_per_cell)
          {
            const unsigned int n_whole
              = grid->n_global_cells() / grid->n_velocity_fields();
            cell_first_id.resize(grid->n_base_cells());
            for (unsigned int c = 0; c < grid->n_base_cells(); ++c)
              cell_first_id[c]
                = (*first_ids)[b * n_whole + grid->global_cell(c)];
          }
        fill_body(*grid,
                  *body.shape,
                  body.particles_per_cell,
                  body.density,
                  body.initial_velocity,
                  b,
                  b,
                  particles,
                  taken,
                  keep_cell,
                  points_per_cell ? &per_base_cell : nullptr,
                  cell_first_id.empty() ? nullptr : &cell_first_id);
        if (points_per_cell)
          for (unsigned int c = 0; c < grid->n_base_cells(); ++c)
            (*points_per_cell)[grid->cell_in_field(c, body.velocity_field)]
              += per_base_cell[c];
        if (points_per_cell)
          {
            // A body a few cells across moves and deforms as a few points:
            // say so (once, on the counting pass) rather than let a
            // coarse grid pass for a result.
            unsigned int n_cells = 0, n_points = 0;
            for (const unsigned int n : per_base_cell)
              {
                n_cells += (n > 0);
                n_points += n;
              }
            // 8 squares (16 triangles) in 2D, 8 cubes (48 tetrahedra) in 3D.
            const unsigned int few_cells = dim == 2 ? 16 : 48;
            if (n_points > 0 && n_cells < few_cells)
              std::cerr << "fsgmpm: warning: Bodies/Body " << b
                        << " is resolved by only " << n_points << " points in "
                        << n_cells << " cells (fewer than " << few_cells
                        << "): it will move and deform as a few points. "
                           "Refine Grid/Cell size (or Grid/Subdivisions) "
                           "for a body of this size."
                        << std::endl;
          }
        if (points_per_cell && first_ids)
          {
            // Ids run body by body, cell by cell (fill_body()).
            unsigned int id = first_id;
            for (unsigned int c = 0; c < grid->n_base_cells(); ++c)
              {
                first_ids->push_back(id);
                id += per_base_cell[c];
              }
          }
        for (unsigned int p = first; p < particles.size(); ++p)
          particles.cell[p]
            = grid->cell_in_field(particles.cell[p], body.velocity_field);
        taken.push_back(body.shape.get());
        using InitialStress = typename BodyDescription<dim>::InitialStress;
        if (body.initial_stress != InitialStress::none)
          {
            // sigma_yy = rho g_y (y_top - y): compression below the top. A
            // fluid at rest has one level (the highest point of the body);
            // soil is loaded by what lies above each point, so its depth is
            // taken below its own surface there (a sloped or curved top).
            double y_top = -std::numeric_limits<double>::max();
            for (const auto &p : body.shape->outline_points())
              y_top = std::max(y_top, p[1]);
            const bool geostatic
              = body.initial_stress == InitialStress::geostatic;
            const double k    = geostatic ? body.k0 : 1.;
            const double step = 0.25 * grid->max_altitude_global;
            for (unsigned int p = first; p < particles.size(); ++p)
              {
                const double top
                  = geostatic ? surface_height_above(*body.shape,
                                                     particles.position[p],
                                                     y_top,
                                                     step,
                                                     1e-6 * step)
                              : y_top;
                const double syy = body.density * params.gravity[1]
                                   * (top - particles.position[p][1]);
                SymmetricTensor<2, 3> s;
                s[0][0] = s[2][2]   = k * syy;
                s[1][1]             = syy;
                particles.stress[p] = s;
                // A fluid carries this pressure at a compressed volume.
                particles.volume[p]
                  = particles.reference_volume[p]
                    * body.material->volume_ratio_for_pressure(-syy);
              }
          }
      }
  }



  template <int dim>
  Tensor<1, dim>
  Simulator<dim>::current_gravity() const
  {
    if (params.gravity_ramp_time > 0 && time < params.gravity_ramp_time)
      return params.gravity * (time / params.gravity_ramp_time);
    return params.gravity;
  }



  template <int dim>
  void
  Simulator<dim>::compute_monitors()
  {
    // MPI: every process holds the whole membrane; process 0 adds it.
    // The potential energy is that of the gravity acting now (ramped, as
    // in the external work), so that -d(potential) equals gravity's work
    // whenever the field is steady.
    EnergyBalance::compute_energies(particles,
                                    materials,
                                    root ? membrane.get() : nullptr,
                                    current_gravity(),
                                    monitors,
                                    partition ? partition->get_communicator()
                                              : MPI_COMM_SELF);
  }



  template <int dim>
  std::vector<CompensatedSum>
  Simulator<dim>::local_energies() const
  {
    return EnergyBalance::local_energies(particles,
                                         materials,
                                         root ? membrane.get() : nullptr,
                                         current_gravity(),
                                         &nodes,
                                         partition ? &partition->counted_nodes()
                                                   : nullptr);
  }



  template <int dim>
  bool
  Simulator<dim>::check_stability(const double displacement_ratio)
  {
    auto fail = [&](const std::string &what) {
      termination = Termination::unstable;
      // Locate the fastest (or a non-finite) point for the diagnosis.
      unsigned int worst = 0;
      double       vmax  = -1;
      for (unsigned int p = 0; p < particles.size(); ++p)
        {
          const double v = particles.velocity[p].norm();
          if (!std::isfinite(v) || v > vmax)
            {
              worst = p;
              vmax  = std::isfinite(v) ? v
                                       : std::numeric_limits<double>::infinity();
              if (!std::isfinite(v))
                break;
            }
        }
      std::ostringstream s;
      s << "unstable at step " << step << ", t = " << time
        << " s, dt = " << time_step_control.dt() << " s: " << what;
      if (particles.size() > 0)
        s << "; fastest material point (body " << particles.body_id[worst]
          << ") at "
          << "(" + format(particles.position[worst]) + ")"
          << " with speed " << vmax << " m/s";
      s << ". Reduce Simulation/Courant number or Simulation/Fixed time step, "
           "or check the material parameters.";
      diagnosis = s.str();
      return false;
    };

    const std::string what
      = stability_guard.check(monitors, displacement_ratio);
    if (!what.empty())
      return fail(what);
    return true;
  }



  template <int dim>
  bool
  Simulator<dim>::advance()
  {
    using Clock = std::chrono::steady_clock;
    auto timed  = [&](const RunStage s, const auto &f) {
      const auto t0 = Clock::now();
      f();
      run_stage_seconds[s]
        += std::chrono::duration<double>(Clock::now() - t0).count();
    };

    // MPI: the points over all processes and the most any process holds,
    // in one collective (deal.II's min_max_avg; exact for counts).
    Utilities::MPI::MinMaxAvg point_counts;
    if (partition)
      point_counts = Utilities::MPI::min_max_avg(double(particles.size()),
                                                 partition->get_communicator());
    const unsigned int n_before
      = partition ? static_cast<unsigned int>(point_counts.sum)
                  : particles.size();
    if (n_before == 0)
      {
        termination = Termination::error;
        diagnosis   = "no material point is left in the mesh (all "
                    + std::to_string(monitors.lost_particles)
                    + " left through its boundary) at step "
                    + std::to_string(step) + ".";
        return false;
      }

    // MPI: rebalance at the start of a step, so that between steps (output)
    // every process still has exact nodal values around its points.
    if (partition)
      timed(mpi_points_stage, [&] {
        rebalance(point_counts);
        const unsigned int n_owned = particles.size();
        DistributedPoints::add_ghosts(*partition, particles);
        // This process's; write_summary() takes the largest.
        halo_fraction
          = n_owned > 0 ? double(particles.size() - n_owned) / n_owned : 0.;
      });
    // P2G first: the membrane's nodal time-step bound needs the nodal
    // masses (p2g does not depend on dt).
    mpm_step->transfer_to_grid();
    double dt_stable = mpm_step->stable_time_step();
    if (partition)
      dt_stable = Utilities::MPI::min(dt_stable, partition->get_communicator());
    const std::string problem = time_step_control.choose(dt_stable, time, step);
    if (!problem.empty())
      {
        termination = Termination::unstable;
        diagnosis   = problem;
        return false;
      }
    const double dt = time_step_control.dt();

    typename MpmStep<dim>::Result result
      = mpm_step->advance(dt, time + dt, current_gravity());
    if (partition)
      {
        // The largest displacement ratio over the processes (infinite if
        // some process's is not finite) comes with the migration.
        timed(mpi_points_stage, [&] {
          result.displacement_ratio = DistributedPoints::migrate(
            *partition,
            particles,
            std::isfinite(result.displacement_ratio)
              ? result.displacement_ratio
              : std::numeric_limits<double>::infinity());
        });
        const MPI_Comm &comm = partition->get_communicator();
        // Each process's node sums and their rounding corrections, added
        // over the processes separately (sum_over_processes()), and in the
        // same collective the point counts (exact: integers in doubles)
        // and the energies (the membrane's from process 0).
        std::vector<CompensatedSum> energies;
        timed(monitor_stage, [&] { energies = local_energies(); });
        Stages::GridUpdateResult   &g    = result.grid;
        const auto                  free = local_free_surface_counts();
        std::vector<CompensatedSum> sums = {g.external_work_increment,
                                            g.damping_work_increment,
                                            g.unbalanced_norm_sq,
                                            g.external_norm_sq,
                                            CompensatedSum(particles.size()),
                                            CompensatedSum(free.first),
                                            CompensatedSum(free.second),
                                            result.material_dissipation,
                                            result.numerical_dissipation,
                                            result.outflow_energy};
        sums.insert(sums.end(), energies.begin(), energies.end());
        // A signal on any process stops them all after this step: the
        // processes' signals ride along in the same collective (SIGTERM
        // counted 2^20, SIGINT 1, so the sum says which came).
        const int signal = Interruption::received_signal();
        sums.emplace_back(signal == SIGTERM ? double(1 << 20)
                                            : (signal != 0 ? 1. : 0.));
        const std::vector<double> total = sum_over_processes(sums, comm);
        interrupt_signal                = total.back() >= double(1 << 20)
                                            ? SIGTERM
                                            : (total.back() > 0 ? SIGINT : 0);
        EnergyBalance::set_energies(make_array_view(total.cbegin() + 10,
                                                    total.cend() - 1),
                                    monitors);
        g.external_work_increment = CompensatedSum(total[0]);
        g.damping_work_increment  = CompensatedSum(total[1]);
        g.unbalanced_norm_sq      = CompensatedSum(total[2]);
        g.external_norm_sq        = CompensatedSum(total[3]);
        result.lost_particles = n_before - static_cast<unsigned int>(total[4]);
        result.free_surface   = {static_cast<unsigned int>(total[5]),
                                 static_cast<unsigned int>(total[6])};
        result.material_dissipation  = CompensatedSum(total[7]);
        result.numerical_dissipation = CompensatedSum(total[8]);
        result.outflow_energy        = CompensatedSum(total[9]);
      }
    set_free_surface_fraction(result.free_surface);
    if (result.membrane_nodes_outside > 0)
      {
        termination = Termination::error;
        diagnosis   = std::to_string(result.membrane_nodes_outside)
                    + " membrane node(s) left the mesh at step "
                    + std::to_string(step)
                    + "; enlarge the grid or check the walls.";
        return false;
      }

    particle_updates
      += partition ? n_before - result.lost_particles : particles.size();
    membrane_crossings += result.membrane_crossings;
    time += dt;
    ++step;
    time_step_control.record_step(step);

    bool ok = true;
    timed(monitor_stage, [&] {
      if (!partition)
        {
          std::vector<double> totals;
          for (const CompensatedSum &e : local_energies())
            totals.push_back(e.value());
          EnergyBalance::set_energies(make_array_view(std::as_const(totals)),
                                      monitors);
        }
      EnergyBalance::add_step(result.grid,
                              {result.material_dissipation.value(),
                               result.numerical_dissipation.value(),
                               result.outflow_energy.value()},
                              result.lost_particles,
                              monitors);
    });
    timed(kinetic_damping_stage, [&] {
      relaxation.apply_kinetic_damping(monitors, particles, membrane.get());
    });
    Termination relaxed = Termination::running;
    timed(monitor_stage, [&] {
      ok      = check_stability(result.displacement_ratio);
      relaxed = relaxation.update(monitors, time);
    });
    if (!ok)
      return false;
    if (relaxed != Termination::running)
      {
        termination = relaxed;
        return false;
      }
    if (time_step_control.reached_end(time, step))
      {
        // The step limit is reported as such: a run it cut short did not
        // reach its end time.
        termination = time_step_control.reached_end_time(time)
                        ? Termination::end_time
                        : Termination::max_steps;
        return false;
      }
    return true;
  }



  template <int dim>
  Termination
  Simulator<dim>::run()
  {
    namespace fs      = std::filesystem;
    using Clock       = std::chrono::steady_clock;
    const auto  start = Clock::now();
    const auto &dir   = params.output_directory;
    // With MPI, rank 0 writes every file but the points' (each process
    // writes its own: RunOutput).
    if (root)
      {
        fs::create_directories(dir);
        // A rerun into the directory of an earlier run replaces its
        // results: say so (on standard error, even when quiet).
        if (!resumed
            && (fs::exists(fs::path(dir) / "monitors.csv")
                || fs::exists(fs::path(dir) / "summary.json")))
          std::cerr << "fsgmpm: note: " << dir
                    << " holds the results of an earlier run; this run "
                       "replaces its monitors.csv, summary.json, checkpoints "
                       "and output files.\n";
        fs::remove(fs::path(dir) / "summary.json");
        if (!resumed)
          {
            fs::remove(fs::path(dir) / "monitors.csv");
            fs::remove_all(fs::path(dir) / "checkpoints");
          }
      }

    output = std::make_unique<RunOutput<dim>>(typename RunOutput<dim>::Settings{
      dir,
      params.output_format == "hdf5",
      params.membrane_output == "finite elements",
      params.write_particles,
      params.write_grid,
      partition ? partition->get_communicator() : MPI_COMM_SELF});
    if (!resumed && root)
      output->remove_previous_output();
    if (root)
      fs::remove(fs::path(dir) / "membrane_shape.csv");
    // MPI: the directory exists and is cleared before any process writes
    // its points there.
    if (partition)
      MPI_Barrier(partition->get_communicator());
    // Common columns, the free-surface fraction where a body
    // detects free surfaces, then the scene's own columns.
    bool detecting = false;
    for (const auto &o : material_options)
      detecting = detecting || o.detect_free_surface;
    std::vector<std::string> columns      = {"time", "step", "dt"};
    std::vector<std::string> units        = {"s", "", "s"};
    const auto               base_columns = Monitors::names();
    const auto               base_units   = Monitors::units(dim);
    for (unsigned int k = 0; k < Monitors::n_values; ++k)
      if (base_columns[k] != "free_surface_fraction" || detecting)
        {
          columns.push_back(base_columns[k]);
          units.push_back(base_units[k]);
        }
    for (unsigned int k = 0; k < scene_monitors->names().size(); ++k)
      {
        columns.push_back(scene_monitors->names()[k]);
        units.push_back(scene_monitors->units()[k]);
      }
    monitor_columns = columns;
    monitor_units   = units;
    // The header carries each column's unit: "kinetic_energy[J/m]".
    std::vector<std::string> headers;
    for (unsigned int k = 0; k < columns.size(); ++k)
      headers.push_back(monitor_column_header(columns[k], units[k]));
    if (root)
      monitor_file
        = resumed
            ? std::make_unique<MonitorFile>(dir + "/monitors.csv",
                                            headers,
                                            resume_monitor_bytes)
            : std::make_unique<MonitorFile>(dir + "/monitors.csv", headers);
    auto write_monitor_row = [&] {
      // The common columns; the free-surface fraction (the last value)
      // only where a body detects free surfaces.
      const auto          values = monitors.values();
      std::vector<double> row    = {time, double(step), time_step_control.dt()};
      row.insert(row.end(), values.begin(), values.end() - (detecting ? 0 : 1));
      std::vector<double> scene
        = scene_monitors->evaluate(particles,
                                   membrane.get(),
                                   partition ? partition->get_communicator()
                                             : MPI_COMM_SELF);
      if (partition)
        {
          const std::vector<double> local = scene;
          Utilities::MPI::max(make_array_view(local),
                              partition->get_communicator(),
                              make_array_view(scene));
        }
      row.insert(row.end(), scene.begin(), scene.end());
      if (root)
        monitor_file->write_row(row);
      last_monitor_row = row;
    };
    const bool any_output
      = (params.write_particles || params.write_grid || membrane)
        && output_schedule.active();
    NodalFields<dim> all_nodes;
    auto             write_output = [&] {
      // MPI: every process writes its own points (their vorticity and
      // projected pressure need the nodal values around them, exact at
      // their owner); the grid's nodal mass and velocity (all that grid
      // output reads) come to process 0, each node as the process that
      // counts it has it.
      if (partition && params.write_grid)
        {
          all_nodes.mass = partition->counted_values(nodes.mass);
          all_nodes.velocity = partition->counted_values(nodes.velocity);
        }
      output->write(time,
                    particles,
                    *grid,
                    nodes,
                    membrane.get(),
                    partition && params.write_grid ? &all_nodes : nullptr,
                    whole_grid.get());
    };
    if (resumed)
      output->restore(resume_output);
    else
      {
        write_monitor_row();
        if (any_output)
          write_output();
      }
    const double start_time = time;

    const bool verbose = !params.quiet && root;
    {
      const unsigned int n_points = n_global_particles();
      if (verbose)
        std::cout << "fsgmpm: " << dim << "D, " << n_points
                  << " material points, " << grid->n_global_cells()
                  << " cells, " << MultithreadInfo::n_threads() << " threads"
                  << (partition ? " x " + std::to_string(partition->n_ranks())
                                    + " MPI processes"
                                : std::string())
                  << ", " << (params.use_musl ? "MUSL" : "USL") << std::endl;
    }

    auto last_progress = Clock::now();
    bool running       = true;
    while (running)
      {
        running = advance();
        if (termination == Termination::unstable
            || termination == Termination::error)
          break;
        // SIGTERM or SIGINT: stop after this complete step (with MPI
        // advance() agreed on the signal).
        if (!partition)
          interrupt_signal = Interruption::received_signal();
        const bool stopping         = running && interrupt_signal != 0;
        auto       write_due_output = [&](const bool last_step) {
          if (any_output && output_schedule.due(time, step, last_step))
            {
              const auto t0 = Clock::now();
              write_output();
              run_stage_seconds[output_stage]
                += std::chrono::duration<double>(Clock::now() - t0).count();
              output_schedule.written(time, step);
            }
        };
        const bool row_due = step % params.monitor_every_steps == 0;
        if (row_due || !running)
          write_monitor_row();
        write_due_output(!running);
        if (stopping)
          {
            // The checkpoint holds the state as the run would have gone on
            // from it, before the stop's own row and output: a restart
            // drops those and continues as the uninterrupted run.
            if (params.checkpoint_interval > 0)
              {
                write_checkpoint(
                  std::chrono::duration<double>(Clock::now() - start).count());
                checkpoint_schedule.written(time, step);
              }
            running     = false;
            termination = Termination::interrupted;
            diagnosis   = std::string("interrupted by ")
                        + (interrupt_signal == SIGTERM ? "SIGTERM" : "SIGINT")
                        + " at step " + std::to_string(step)
                        + ", t = " + format(time) + " s"
                        + (params.checkpoint_interval > 0
                             ? "; continue with --restart " + dir
                             : "; Output/Checkpoint interval > 0 would have "
                               "written a checkpoint to continue from")
                        + ".";
            if (!row_due)
              write_monitor_row();
            write_due_output(true);
          }
        else if (checkpoint_schedule.active() && running
                 && checkpoint_schedule.due(time, step))
          {
            write_checkpoint(
              std::chrono::duration<double>(Clock::now() - start).count());
            checkpoint_schedule.written(time, step);
          }
        if (verbose
            && std::chrono::duration<double>(Clock::now() - last_progress)
                   .count()
                 > 2.)
          {
            last_progress = Clock::now();
            const double elapsed
              = std::chrono::duration<double>(last_progress - start).count();
            const double eta = elapsed * (params.time_step.end_time - time)
                               / std::max(time - start_time, 1e-300);
            std::cout << "  t = " << std::setprecision(4) << time << " s  step "
                      << step << "  dt = " << time_step_control.dt()
                      << " s  ETA " << std::setprecision(3) << eta << " s"
                      << std::endl;
          }
      }

    const double wall
      = std::chrono::duration<double>(Clock::now() - start).count()
        + previous_wall_seconds;
    // The final state too, so that a finished run can be continued to a
    // later End time.
    // (An interrupted run wrote its checkpoint at the stop.)
    if (params.checkpoint_interval > 0 && termination != Termination::unstable
        && termination != Termination::error
        && termination != Termination::interrupted)
      write_checkpoint(wall - previous_wall_seconds);
    monitor_file.reset();
    if (membrane && root)
      write_membrane_shape_csv(*membrane, dir + "/membrane_shape.csv");
    write_summary(wall);
    if (verbose)
      {
        std::cout << "fsgmpm: " << termination << " after " << step
                  << " steps, simulated " << std::setprecision(6) << time
                  << " s in " << std::setprecision(3) << wall << " s wall, "
                  << std::setprecision(3) << particle_updates / wall
                  << " particle-updates/s, " << monitors.lost_particles
                  << " lost particles; output in " << dir << "/" << std::endl;
      }
    if (root
        && (termination == Termination::unstable
            || termination == Termination::error
            || termination == Termination::interrupted))
      std::cerr << "fsgmpm: " << diagnosis << std::endl;
    return termination;
  }



  template <int dim>
  void
  Simulator<dim>::write_summary(const double wall) const
  {
    const unsigned int n_points = n_global_particles();
    double             bytes    = particles.bytes_per_particle();
    // What the processes really hold at their peak (the point store, the
    // grid, the libraries): VmHWM.
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    double peak_resident = 1024. * memory.VmHWM, total_resident = peak_resident;
    double largest_halo_fraction = halo_fraction;
    double crossings             = membrane_crossings;
    if (partition)
      {
        crossings
          = Utilities::MPI::sum(crossings, partition->get_communicator());
        largest_halo_fraction
          = Utilities::MPI::max(halo_fraction, partition->get_communicator());
        bytes = Utilities::MPI::max(bytes, partition->get_communicator());
        peak_resident
          = Utilities::MPI::max(peak_resident, partition->get_communicator());
        total_resident
          = Utilities::MPI::sum(total_resident, partition->get_communicator());
      }
    if (!root)
      return;
    std::string               stages  = "{";
    const std::vector<double> seconds = get_stage_seconds();
    for (unsigned int s = 0; s < seconds.size(); ++s)
      stages += (s ? ", " : "") + json_string(stage_names()[s]) + ": "
                + json_number(seconds[s]);
    stages += "}";
    // The last row of monitors.csv by column, and the columns' units.
    std::string final_monitors = "{", units = "{";
    for (unsigned int c = 0; c < monitor_columns.size(); ++c)
      {
        const std::string &column = monitor_columns[c];
        final_monitors
          += (c ? ", " : "") + json_string(column) + ": "
             + json_number(c < last_monitor_row.size() ? last_monitor_row[c]
                                                       : std::nan(""));
        units += (c ? ", " : "") + json_string(column) + ": "
                 + json_string(monitor_units[c]);
      }
    final_monitors += "}";
    units += "}";
    std::vector<std::pair<std::string, std::string>> entries
      = {{"dim", std::to_string(dim)},
         {"particles", std::to_string(n_points)},
         {"steps", std::to_string(step)},
         {"simulated_time", json_number(time)},
         {"wall_seconds", json_number(wall)},
         {"particle_updates_per_second", json_number(particle_updates / wall)},
         {"stage_seconds", stages},
         {"threads", std::to_string(MultithreadInfo::n_threads())},
         {"mpi_ranks", std::to_string(partition ? partition->n_ranks() : 1)},
         {"mpi_repartitions", std::to_string(n_repartitions)},
         {"mpi_imbalance", json_number(imbalance)},
         {"mpi_halo_fraction", json_number(largest_halo_fraction)},
         {"lost_particles", std::to_string(monitors.lost_particles)},
         {"membrane_crossings_undone", json_number(crossings)},
         {"dt_min", json_number(time_step_control.dt_min())},
         {"dt_max", json_number(time_step_control.dt_max())},
         {"dt_last", json_number(time_step_control.dt())},
         {"termination", json_string(to_string(termination))},
         {"diagnosis", json_string(diagnosis)},
         {"final_monitors", final_monitors},
         {"monitor_units", units},
         {"energy_residual",
          json_number(stability_guard.energy_residual(monitors))},
         // 0 when no energy was put in (no motion, stress or gravity):
         // summary.json holds no null.
         {"energy_residual_ratio",
          json_number(stability_guard.energy_scale() > 0
                        ? stability_guard.energy_residual(monitors)
                            / stability_guard.energy_scale()
                        : 0.)},
         // The guard's reading at its worst step: the largest energy
         // created and its largest share of the energy scale (the run
         // stops as unstable above Stability/Energy creation tolerance).
         {"energy_created_largest",
          json_number(stability_guard.largest_created())},
         {"energy_created_largest_share",
          json_number(stability_guard.largest_created_share())},
         {"bytes_per_particle", json_number(bytes)},
         {"peak_resident_bytes", json_number(peak_resident)},
         {"resident_bytes_per_particle",
          json_number(n_points > 0 ? total_resident / n_points : 0.)},
         {"checkpoint_seconds", json_number(checkpoint_seconds)},
         {"version", json_string(FSGMPM_VERSION)},
         {"git_commit", json_string(git_commit())}};
    write_json(params.output_directory + "/summary.json", entries);
  }

  template <int dim>
  double
  Simulator<dim>::get_grid_memory_per_particle() const
  {
    if (particles.size() == 0)
      return 0;
    return double(grid->memory_consumption() + nodes.memory_consumption()
                  + smoothing.memory_consumption()
                  + (whole_grid ? whole_grid->memory_consumption() : 0))
           / particles.size();
  }



  template <int dim>
  double
  Simulator<dim>::get_scene_monitor_value(const std::string &column) const
  {
    const auto &names = scene_monitors->names();
    const auto  it    = std::find(names.begin(), names.end(), column);
    if (it == names.end())
      {
        std::string known;
        for (const auto &name : names)
          known += (known.empty() ? "" : ", ") + name;
        AssertThrow(false,
                    ExcMessage("The scene monitors have no column " + column
                               + " (columns: "
                               + (known.empty() ? "none" : known)
                               + "; Monitors/Scene monitors selects them)."));
      }
    return get_scene_monitors()[it - names.begin()];
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace fsgmpm
