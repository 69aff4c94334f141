#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/base/format.h>
#include <fsgmpm/base/parameter_parsing.h>
#include <fsgmpm/base/real_interval.h>
#include <fsgmpm/membrane/membrane_geometry.h>
#include <fsgmpm/monitors/scene_monitors.h>
#include <fsgmpm/scene/body.h>
#include <fsgmpm/scene/parameters.h>

#include <limits>
#include <sstream>

namespace fsgmpm
{
  namespace
  {
    /// Largest coordinate of a box corner (m).
    constexpr double max_coordinate = 1e9;
  } // namespace



  template <int dim>
  void
  Parameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Simulation");
    {
      prm.declare_entry("Dimension",
                        "2",
                        Patterns::Integer(2, 3),
                        "2 (plane strain, triangles) or 3 (tetrahedra).");
      prm.declare_entry("Update scheme",
                        "MUSL",
                        Patterns::Selection("MUSL|USL"),
                        "MUSL: stress and positions from the remapped nodal "
                        "velocities of Eq. (20) (paper); USL: from the "
                        "grid-updated velocities.");
      prm.declare_entry(
        "Velocity transfer",
        "FLIP",
        Patterns::Selection("FLIP|APIC|APIC affine remap"),
        "How the grid velocity goes back to the points. FLIP (paper Eq. 19): "
        "v_p += dt a(x_p); keeps sub-cell velocity noise on the points that "
        "the grid does not see. APIC (Jiang et al. 2015): v_p = v(x_p) plus "
        "the cell's velocity gradient, mapped back affinely; drops the "
        "sub-cell noise, keeps resolved (affine) motion; the MUSL remap of "
        "Eq. (20) smooths the velocity once more each step, so its "
        "dissipation depends on the time step. APIC affine remap (MUSL "
        "only): the remap carries the affine term too, which on linear "
        "simplices keeps the grid-updated velocity, at the nodes whose "
        "points fill at least 1/4 of their volume (blended to the mass "
        "average below, where the remap suppresses the small-mass "
        "instability): less dissipation, independent of the time step "
        "(doc/accuracy_vs_cost.md).");
      prm.declare_entry(
        "Stress integration",
        "points",
        Patterns::Selection("points|nodal projection"),
        "How the internal force of Eq. (3) is integrated. points (paper): "
        "sum_p V_p sigma_p grad N_i(x_p); a point that crosses a cell edge "
        "moves its whole V_p sigma_p to the next cell's gradients, so the "
        "nodal forces jump by V_p sigma_p |grad N|. nodal projection: the "
        "points' stresses are projected to the nodes (sum_p N_i V_p sigma_p "
        "over the node's share of the occupied cells' volume) and the force "
        "of the cells filled to 3/4 or more is integrated from that linear "
        "field (double mapping, as DDMP; blended down to the points' own "
        "force at a fill of 1/2), with the work-conjugate nodally averaged "
        "strain rate in the stress update: continuous as points cross "
        "edges inside the material. Accuracy and cost: "
        "doc/accuracy_vs_cost.md.");
      prm.declare_entry(
        "FLIP noise relaxation time",
        "0",
        Patterns::Double(0),
        "Velocity transfer = FLIP: if > 0, blend each step's FLIP update "
        "with the fraction beta = 1 - exp(-dt/tau) of the grid's velocity "
        "(PIC's, or XPIC's: XPIC order), so that the sub-cell velocity noise "
        "FLIP keeps decays over tau seconds whatever the time step. With PIC "
        "the resolved motion pays a viscosity of about h^2 / (6 tau), "
        "thousands of times water's (measured by the viscous_decay test: "
        "doc/accuracy_vs_cost.md); 0: pure FLIP (paper Eq. 19).");
      prm.declare_entry(
        "XPIC order",
        "1",
        Patterns::Integer(1, 8),
        "The velocity FLIP's noise relaxes to (FLIP noise relaxation time > "
        "0): 1, PIC's grid velocity; m >= 2, XPIC(m)'s (Hammerquist and "
        "Nairn 2017), which drops the same sub-cell noise but keeps a "
        "grid-resolved mode to 1 - (1 - a)^m where PIC keeps a, about 1 - "
        "(kh)^2/6; each order above 1 costs one more pass over the points.");
      prm.declare_entry(
        "Contact friction coefficient",
        "0",
        Patterns::Double(0),
        "Coulomb friction coefficient where bodies of different Bodies/Body "
        "N/Velocity field meet (multi-field contact, Bardenhagen et al. "
        "2000): 0 frictionless, a large value sticks while in contact. "
        "Unused when all bodies share one field.");
      prm.declare_entry(
        "Contact volume fraction",
        "0.9",
        Patterns::Double(0, 1),
        "Multi-field contact acts at a node only where the points of both "
        "fields fill at least this fraction of the node's volume (0 to 1): "
        "bodies that merely share a node across a gap of up to a cell are "
        "not yet in contact. 0: Bardenhagen's original test (both fields "
        "have mass), which stops bodies up to a cell and a half early "
        "(doc/geocontainer_validation.md).");
      prm.declare_entry("Gravity",
                        "0, -9.81",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Gravitational acceleration (m/s^2, at most 1e5 in "
                        "magnitude); y is vertical. In 3D a two-entry value "
                        "means z = 0.");
      prm.declare_entry("Gravity ramp time",
                        "0",
                        Patterns::Double(0),
                        "Gravity grows linearly from 0 over this time (s).");
      prm.declare_entry("Number of threads",
                        "0",
                        Patterns::Integer(0, 1024),
                        "Threads for the particle and grid loops (0: all "
                        "cores or DEAL_II_NUM_THREADS; at most 1024).");
      prm.declare_entry(
        "Repartition imbalance",
        "1.2",
        Patterns::Double(0),
        "MPI runs: split the cells again (METIS, weighted by the points per "
        "cell) before a step if the most loaded process holds more than "
        "this many times the mean number of points (0: never; values in "
        "(0, 1) are refused). The results do not depend on it.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Damping");
    {
      prm.declare_entry("Local damping coefficient",
                        "0",
                        RealInterval(0, 1, false, true),
                        "alpha of local non-viscous damping F = -alpha "
                        "|F_unbalanced| sign(v), 0 <= alpha < 1.");
      prm.declare_entry("Mass scaling",
                        "false",
                        Patterns::Bool(),
                        "Dynamic relaxation: give grid nodes that a stiff "
                        "membrane would make the time-step limit fictitious "
                        "inertia (no weight, no momentum) so that the "
                        "material points' limit governs; changes the motion "
                        "but not the static state. Quasi-static runs only, and "
                        "only with damping (local or kinetic).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Grid");
    {
      prm.declare_entry("Type",
                        "box",
                        Patterns::Selection("box|gmsh|extruded box"),
                        "box: a box split into simplices; gmsh: read Mesh "
                        "file; extruded box (3D only): the 2D box of the "
                        "first two coordinates extruded by Extrusion "
                        "thickness with one layer of tetrahedra, so that it "
                        "matches the 2D plane-strain mesh.");
      prm.declare_entry("Extrusion thickness",
                        "0.1",
                        RealInterval::above(0),
                        "Type = extruded box: thickness in z (m, > 0; "
                        "1e-3 to 1e3 times the cell size).");
      prm.declare_entry("Lower corner",
                        "0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Type = box: lower corner (m, within +-1e9).");
      prm.declare_entry("Upper corner",
                        "1, 0.6",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Type = box: upper corner (m, within +-1e9).");
      prm.declare_entry("Subdivisions",
                        "40, 24",
                        Patterns::List(Patterns::Integer(1), 2, 3),
                        "Type = box: number of squares/cubes per direction, "
                        "each split into 2 triangles (2D) or 5-6 tets (3D); "
                        "at most 1e7 squares/cubes, each at least 1e-6 m.");
      prm.declare_entry("Cell size",
                        "0",
                        Patterns::Double(0),
                        "Type = box or extruded box: if > 0, the square size "
                        "(m) that sets Subdivisions (rounded to the nearest "
                        "integer per direction); one parameter for mesh "
                        "studies.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::Anything(),
                        "Type = gmsh: path of a .msh file of triangles or "
                        "tetrahedra (relative to the working directory).");
      prm.declare_entry("Boundary conditions",
                        "0: roller, 1: roller, 2: roller, 3: free",
                        Patterns::Anything(),
                        "Walls by boundary id: 'id: type, ...' with type "
                        "free; fixed (no slip); roller (bilateral: no "
                        "normal motion, neither into nor away from the "
                        "wall; material sticks to it); slip (unilateral, "
                        "frictionless: no penetration, material may leave "
                        "the wall, e.g. water along tank sides); or "
                        "'friction <mu>' (unilateral Coulomb contact, "
                        "applied once per step in the grid update). Box "
                        "ids: 0/1 x-min/max, 2/3 y-min/max, 4/5 z-min/max. "
                        "Ids not listed are free.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Output");
    {
      prm.declare_entry("Directory",
                        "output",
                        Patterns::Anything(),
                        "Output directory (created; relative to the working "
                        "directory).");
      prm.declare_entry("Output interval",
                        "0.02",
                        Patterns::Double(0),
                        "Write VTU files every this much simulated time "
                        "(s; 0: use Output every n steps).");
      prm.declare_entry("Output every n steps",
                        "0",
                        Patterns::Integer(0),
                        "Write VTU files every n steps (0: never, unless "
                        "Output interval > 0).");
      prm.declare_entry("Write particles",
                        "true",
                        Patterns::Bool(),
                        "Write the material points (VTU/PVD).");
      prm.declare_entry("Format",
                        "vtu",
                        Patterns::Selection("vtu|hdf5"),
                        "File format of the points and the membrane: vtu "
                        "(one .vtu per step and a .pvd collection) or hdf5 "
                        "(one .h5 per step and an .xdmf collection, for "
                        "ParaView's XDMF reader: full double precision, "
                        "uncompressed, about 4x the size of the compressed "
                        "single-precision VTU files and about 30x faster to "
                        "write). The grid is always VTU.");
      prm.declare_entry("Membrane output",
                        "pieces",
                        Patterns::Selection("pieces|finite elements"),
                        "How the membrane is written: pieces (its straight "
                        "elements, the cells at degree 1 and their halves "
                        "or quarters at degree 2, as ASCII VTU or in "
                        "HDF5, with tension and stretch per piece, read by "
                        "doc/scripts) or finite elements (deal.II's DataOut "
                        "of the MembraneFE cells, quadratic cells at degree "
                        "2, with tension, minor_tension, the tension "
                        "tensor (N/m, x-y-z) and stretch per cell and "
                        "velocity and displacement per node; VTU only).");
      prm.declare_entry("Report",
                        "false",
                        Patterns::Bool(),
                        "At the end of the run, plot its monitors (against "
                        "the scene's reference where it has one) into "
                        "report.png in the output directory, with "
                        "doc/scripts/plot.py of the source tree "
                        "(python3-matplotlib); a warning if that fails.");
      prm.declare_entry("Write grid",
                        "false",
                        Patterns::Bool(),
                        "Write the background grid with nodal fields.");
      prm.declare_entry("Monitor every n steps",
                        "1",
                        Patterns::Integer(1),
                        "Append a row to monitors.csv every n steps.");
      prm.declare_entry("Quiet",
                        "false",
                        Patterns::Bool(),
                        "Suppress the progress line.");
      prm.declare_entry(
        "Checkpoint interval",
        "0",
        Patterns::Double(0),
        "Write the whole state to DIRECTORY/checkpoints/ (HDF5) every this "
        "much simulated time, and at the end of the run (s; 0: never). The "
        "last two are kept; fsgmpm scene.prm --restart DIRECTORY continues "
        "from the newest one that reads back intact, exactly as the run "
        "would have gone on.");
    }
    prm.leave_subsection();

    // The run-control pieces declare their own entries.
    TimeStepControl::Settings::declare_parameters(prm);
    DynamicRelaxation::Settings::declare_parameters(prm);
    StabilityGuard::Settings::declare_parameters(prm);
    MovingWallParameters::declare_parameters(prm);
    BodyDescription<dim>::declare_parameters(prm);
    MembraneDescription<dim>::declare_parameters(prm);
    SceneMonitors<dim>::declare_parameters(prm);
  }



  template <int dim>
  Parameters<dim>::Parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Simulation");
    use_musl          = (prm.get("Update scheme") == "MUSL");
    use_apic          = (prm.get("Velocity transfer") != "FLIP");
    apic_affine_remap = (prm.get("Velocity transfer") == "APIC affine remap");
    AssertThrow(use_musl || !apic_affine_remap,
                ExcMessage("Simulation/Velocity transfer = APIC affine remap "
                           "changes the remap of Update scheme = MUSL, which "
                           "USL does not have: use MUSL, or APIC with USL."));
    stress_integration = (prm.get("Stress integration") == "nodal projection")
                           ? Stages::StressIntegration::nodal_projection
                           : Stages::StressIntegration::points;
    flip_noise_relaxation_time = prm.get_double("FLIP noise relaxation time");
    xpic_order                 = prm.get_integer("XPIC order");
    AssertThrow(xpic_order == 1
                  || (flip_noise_relaxation_time > 0 && !use_apic),
                ExcMessage("Simulation/XPIC order = "
                           + std::to_string(xpic_order)
                           + " sets the velocity FLIP's noise relaxes to: "
                             "use it with Velocity transfer = FLIP and FLIP "
                             "noise relaxation time > 0 (or set it to 1)."));
    contact_friction        = prm.get_double("Contact friction coefficient");
    contact_volume_fraction = prm.get_double("Contact volume fraction");
    gravity = parse_vector<dim>(prm.get("Gravity"), "Simulation/Gravity");
    AssertThrow(gravity.norm() <= 1e5,
                ExcMessage("Simulation/Gravity must not exceed 1e5 m/s^2 "
                           "(10^4 g) in magnitude; got <"
                           + prm.get("Gravity") + ">."));
    gravity_ramp_time     = prm.get_double("Gravity ramp time");
    n_threads             = prm.get_integer("Number of threads");
    repartition_imbalance = prm.get_double("Repartition imbalance");
    AssertThrow(repartition_imbalance == 0 || repartition_imbalance >= 1,
                ExcMessage("Simulation/Repartition imbalance is the ratio of "
                           "the most loaded process's points to the mean, at "
                           "least 1 (or 0: never repartition); got "
                           + prm.get("Repartition imbalance") + "."));
    prm.leave_subsection();
    time_step.parse_parameters(prm);
    relaxation.parse_parameters(prm);
    stability.parse_parameters(prm);

    prm.enter_subsection("Damping");
    local_damping = prm.get_double("Local damping coefficient");
    mass_scaling  = prm.get_bool("Mass scaling");
    prm.leave_subsection();
    AssertThrow(local_damping >= 0 && local_damping < 1,
                ExcMessage("Damping/Local damping coefficient must lie in "
                           "[0, 1); got "
                           + std::to_string(local_damping) + "."));
    // The fictitious inertia is recomputed every step and is not in the
    // points' momentum: undamped, it feeds the membrane's stiff directions
    // (the geotube released with it and no damping blew up at 0.16 s).
    AssertThrow(!mass_scaling || local_damping > 0
                  || relaxation.kinetic_damping,
                ExcMessage("Damping/Mass scaling is a dynamic-relaxation "
                           "device and needs damping: set Damping/Local "
                           "damping coefficient > 0 (0.7 in the shipped "
                           "geotubes) or Damping/Kinetic damping = true, or "
                           "set Mass scaling = false for a dynamic run."));

    prm.enter_subsection("Grid");
    grid_type           = prm.get("Type");
    extrusion_thickness = prm.get_double("Extrusion thickness");
    AssertThrow(grid_type != "extruded box" || dim == 3,
                ExcMessage("Grid/Type = extruded box needs Simulation/"
                           "Dimension = 3."));
    AssertThrow(grid_type != "extruded box" || extrusion_thickness > 0,
                ExcMessage("Grid/Extrusion thickness must be positive."));
    if (grid_type == "box" || grid_type == "extruded box")
      {
        const unsigned int box_dim = (grid_type == "box") ? dim : 2;
        const auto         lo
          = parse_vector<dim>(prm.get("Lower corner"), "Grid/Lower corner");
        const auto hi
          = parse_vector<dim>(prm.get("Upper corner"), "Grid/Upper corner");
        lower_corner = Point<dim>(lo);
        upper_corner = Point<dim>(hi);
        if (box_dim == 2 && dim == 3)
          upper_corner[2] = extrusion_thickness;
        for (unsigned int d = 0; d < box_dim; ++d)
          {
            AssertThrow(upper_corner[d] > lower_corner[d],
                        ExcMessage("Grid/Upper corner must exceed Grid/Lower "
                                   "corner in every coordinate"
                                   + std::string(dim == 3 && box_dim == 3
                                                   ? " (in 3D give x, y, z)"
                                                   : "")
                                   + "; got <" + prm.get("Lower corner")
                                   + "> and <" + prm.get("Upper corner")
                                   + ">."));
            AssertThrow(std::abs(lower_corner[d]) <= max_coordinate
                          && std::abs(upper_corner[d]) <= max_coordinate,
                        ExcMessage("Grid/Lower corner and Grid/Upper corner "
                                   "must lie within +-1e9 m; got <"
                                   + prm.get("Lower corner") + "> and <"
                                   + prm.get("Upper corner") + ">."));
          }
        const auto items
          = Utilities::split_string_list(prm.get("Subdivisions"), ',');
        AssertThrow(items.size() == box_dim,
                    ExcMessage("Grid/Subdivisions must have "
                               + std::to_string(box_dim) + " entries; got <"
                               + prm.get("Subdivisions") + ">."));
        for (const auto &s : items)
          subdivisions.push_back(Utilities::string_to_int(s));
        const double cell_size = prm.get_double("Cell size");
        if (cell_size > 0)
          for (unsigned int d = 0; d < box_dim; ++d)
            {
              const double n = (upper_corner[d] - lower_corner[d]) / cell_size;
              AssertThrow(n <= 100000,
                          ExcMessage("Grid/Cell size is too small for the "
                                     "box: more than 100000 cells per "
                                     "direction."));
              AssertThrow(n >= 0.5,
                          ExcMessage("Grid/Cell size (" + prm.get("Cell size")
                                     + " m) is larger than the box (Grid/"
                                       "Lower corner to Grid/Upper corner) "
                                       "in direction "
                                     + std::to_string(d) + "."));
              subdivisions[d] = std::max<long>(1, std::lround(n));
            }
        // Enough cells to be useful, few enough to fit in memory, and
        // cells well above the round-off of their coordinates.
        double n_cells = 1;
        for (unsigned int d = 0; d < box_dim; ++d)
          {
            n_cells *= subdivisions[d];
            const double h
              = (upper_corner[d] - lower_corner[d]) / subdivisions[d];
            AssertThrow(h >= 1e-6
                          && h >= 1e-9
                                    * std::max(std::abs(lower_corner[d]),
                                               std::abs(upper_corner[d])),
                        ExcMessage("Grid cells would be " + format(h)
                                   + " m wide in direction " + std::to_string(d)
                                   + ": at least 1e-6 m and 1e-9 of the "
                                     "coordinates are needed; check Grid/"
                                     "Lower corner, Grid/Upper corner and "
                                     "Grid/Subdivisions or Grid/Cell size."));
          }
        if (grid_type == "extruded box")
          {
            double h_min = std::numeric_limits<double>::max();
            for (unsigned int d = 0; d < 2; ++d)
              h_min = std::min(h_min,
                               (upper_corner[d] - lower_corner[d])
                                 / subdivisions[d]);
            AssertThrow(extrusion_thickness >= 1e-3 * h_min
                          && extrusion_thickness <= 1e3 * h_min,
                        ExcMessage("Grid/Extrusion thickness must lie within "
                                   "1e-3 to 1e3 times the cell size ("
                                   + format(h_min) + " m); got "
                                   + prm.get("Extrusion thickness") + "."));
          }
        AssertThrow(n_cells <= 1e7,
                    ExcMessage("Grid/Subdivisions (or Grid/Cell size) give "
                               + format(n_cells)
                               + " squares/cubes; at most 1e7 are allowed."));
      }
    mesh_file = prm.get("Mesh file");
    AssertThrow(grid_type != "gmsh" || !mesh_file.empty(),
                ExcMessage("Grid/Mesh file must be given when Grid/Type = "
                           "gmsh."));
    walls = parse_wall_conditions(prm.get("Boundary conditions"),
                                  "Grid/Boundary conditions");
    prm.leave_subsection();
    moving_wall.parse_parameters(prm, dim);

    prm.enter_subsection("Output");
    output_directory   = prm.get("Directory");
    output_interval    = prm.get_double("Output interval");
    output_every_steps = prm.get_integer("Output every n steps");
    write_particles    = prm.get_bool("Write particles");
    write_grid         = prm.get_bool("Write grid");
    output_format      = prm.get("Format");
    membrane_output    = prm.get("Membrane output");
    AssertThrow(membrane_output == "pieces" || output_format == "vtu",
                ExcMessage("Output/Membrane output = finite elements is "
                           "written as VTU (deal.II's DataOut); set "
                           "Output/Format = vtu, or Membrane output = "
                           "pieces for HDF5."));
    monitor_every_steps = prm.get_integer("Monitor every n steps");
    quiet               = prm.get_bool("Quiet");
    checkpoint_interval = prm.get_double("Checkpoint interval");
    prm.leave_subsection();
    AssertThrow(!output_directory.empty(),
                ExcMessage("Output/Directory must not be empty."));
  }

  template struct Parameters<2>;
  template struct Parameters<3>;
} // namespace fsgmpm
