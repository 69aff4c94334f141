#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/base/format.h>
#include <fsgmpm/base/parameter_parsing.h>
#include <fsgmpm/base/real_interval.h>
#include <fsgmpm/materials/material_factory.h>
#include <fsgmpm/scene/body.h>
#include <fsgmpm/scene/shape_factory.h>


namespace fsgmpm
{
  template <int dim>
  void
  BodyDescription<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Bodies");
    prm.declare_entry("Number of bodies",
                      "1",
                      Patterns::Integer(1, max_n_bodies),
                      "How many of the subsections Body 0, Body 1, ... are "
                      "used.");
    for (unsigned int b = 0; b < max_n_bodies; ++b)
      {
        prm.enter_subsection("Body " + std::to_string(b));
        prm.declare_entry("Shape",
                          "box",
                          Patterns::Selection(ShapeFactory::pattern()
                                              + "|membrane"),
                          "Region the body fills initially, one of the "
                          "registered body shapes (a program adds its own "
                          "with FSGMPM_REGISTER_SHAPE, scene/shape_factory.h): "
                            + ShapeFactory::documentation()
                            + "; or membrane: the inside of the closed "
                              "membrane of subsection Membrane.");
        ShapeFactory::declare_parameters(prm);
        prm.declare_entry("Particles per cell",
                          "4",
                          Patterns::Integer(1, 4096),
                          "Material points per background cell: (2^dim)^L, "
                          "i.e. 1, 4, 16, 64 in 2D and 1, 8, 64 in 3D.");
        prm.declare_entry("Density",
                          "1000",
                          Patterns::Double(1e-3, 1e5),
                          "Mass density (kg/m^3, 1e-3 to 1e5).");
        prm.declare_entry("Initial velocity",
                          "0, 0",
                          Patterns::List(Patterns::Double(), 2, 3),
                          "Initial velocity (m/s, at most 1e5 in magnitude); "
                          "in 3D a two-entry value means z = 0.");
        prm.declare_entry("Material model",
                          "linear elastic",
                          Patterns::Selection(MaterialFactory::pattern()),
                          "Constitutive model of the body, one of the "
                          "registered material models (a program adds its "
                          "own with FSGMPM_REGISTER_MATERIAL, "
                          "materials/material_factory.h): "
                            + MaterialFactory::documentation() + ".");
        prm.declare_entry("Volumetric smoothing",
                          "default",
                          Patterns::Selection("default|none|NMD|ANP|NMD+ANP"),
                          "Volumetric-locking remedies (paper Section 3): NMD "
                          "(Eqs. 22-25), ANP (Eqs. 28-29), both, or none; "
                          "default: NMD+ANP for fluids, none for solids; "
                          "none with Simulation/Stress integration = nodal "
                          "projection (NMD or ANP are refused with it).");
        prm.declare_entry(
          "Smoothing weights",
          "point volume",
          Patterns::Selection("point volume|capped cell volume"),
          "Weights of the NMD and ANP nodal averages: each point's volume "
          "(paper, Eqs. 24 and 29), or each cell's points together weighing "
          "at most the cell's volume, min(sum_p V_p, V_c), which keeps a "
          "fluid's points from packing in violent flow "
          "(doc/geocontainer_validation.md, Section 6).");
        prm.declare_entry(
          "Smoothing stabilisation",
          "0",
          Patterns::Double(0, 1),
          "With NMD or ANP: the share alpha of each cell's own volumetric "
          "strain rate and of each point's own pressure kept beside the "
          "nodal averages; with Simulation/Stress integration = nodal "
          "projection: the share alpha of each cell's own volumetric "
          "strain rate and of its points' mean stress kept beside the "
          "projected fields (0: the averages alone; 1: no smoothing of the "
          "volumetric part; "
          "0.5, twice the smallest share that kept a tank of water at rest "
          "still for 10 s, is the measured choice for still or slow water). "
          "The averages alone have a null space, patterns of compression "
          "and expansion that average out at every node, in which the "
          "points pack without pressure: under gravity they do, and water "
          "at rest starts to slosh after some 0.5 s; alpha gives those "
          "patterns the stiffness alpha K, and so stiffens rotational flow "
          "that spans only a few cells (0.5 turns most of such a flow's "
          "kinetic energy into compression) and the flow round a body (a "
          "geocontainer with its water at 0.5 sinks at a fifth of its "
          "speed): doc/water_validation.md, Still water.");
        prm.declare_entry("ANP mapping",
                          "element_mean",
                          Patterns::Selection("element_mean|interpolate"),
                          "How the nodal ANP pressure goes back to the points: "
                          "the mean of the cell's nodes (paper) or "
                          "interpolated at the point.");
        prm.declare_entry("Free surface detection",
                          "default",
                          Patterns::Selection("default|true|false"),
                          "Flag free-surface and drop points (zero pressure, "
                          "volume reset, left out of ANP); default: on for "
                          "fluids, off for solids. Switch off for a fluid "
                          "enclosed by a membrane.");
        prm.declare_entry("Free surface threshold",
                          "0.6",
                          RealInterval(0, 1, true, true),
                          "f_c: a point whose interpolated nodal volume "
                          "fraction is at most f_c is a free-surface point, "
                          "0 < f_c < 1.");
        prm.declare_entry(
          "Initial stress",
          "none",
          Patterns::Selection("none|geostatic|hydrostatic"),
          "none: stress free; geostatic: sigma_yy = -rho g "
          "(y_top - y) from the body's top, sigma_xx = sigma_zz "
          "= K0 sigma_yy; hydrostatic: pressure rho g (y_top - y), for "
          "fluids with the matching density (uses Simulation/Gravity).");
        prm.declare_entry("K0",
                          "0.5",
                          Patterns::Double(0, 10),
                          "Lateral stress ratio for Initial stress = "
                          "geostatic (0 to 10).");
        prm.declare_entry(
          "Velocity field",
          "0",
          Patterns::Integer(0, 1),
          "Velocity field of the body's points (0 or 1). Bodies in the same "
          "field share one nodal velocity, so they stick where they touch "
          "(the paper's model); bodies in different fields meet through "
          "Contact (Bardenhagen et al. 2000): they cannot interpenetrate, "
          "slide with Contact/Friction coefficient, and separate freely. "
          "The membrane moves with field 0.");
        MaterialFactory::declare_parameters(prm);
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }



  namespace
  {
    // Sanity bounds: far beyond any physical value, low enough that
    // energies and stresses stay finite.
    // (Density, 1e-3 to 1e5 kg/m^3, and K0, 0 to 10, are bounded by their
    // Patterns.)
    constexpr double max_speed = 1e5; // m/s

  } // namespace



  template <int dim>
  std::vector<BodyDescription<dim>>
  BodyDescription<dim>::parse_bodies(ParameterHandler &prm)
  {
    // The nodal stress projection averages the whole strain rate at the
    // nodes; NMD or ANP on top of it is unstable (doc/accuracy_vs_cost.md).
    prm.enter_subsection("Simulation");
    const bool projection
      = (prm.get("Stress integration") == "nodal projection");
    prm.leave_subsection();

    std::vector<BodyDescription<dim>> bodies;
    prm.enter_subsection("Bodies");
    const unsigned int n = prm.get_integer("Number of bodies");
    for (unsigned int b = 0; b < n; ++b)
      {
        BodyDescription<dim> body;
        body.path = "Bodies/Body " + std::to_string(b);
        prm.enter_subsection("Body " + std::to_string(b));
        const std::string shape = prm.get("Shape");
        if (shape == "membrane")
          body.fills_membrane = true; // the shape is set with the membrane
        else
          body.shape = ShapeFactory::create<dim>(shape, prm, body.path);
        body.particles_per_cell = prm.get_integer("Particles per cell");
        {
          unsigned int n = body.particles_per_cell;
          while (n % (1u << dim) == 0)
            n /= (1u << dim);
          AssertThrow(n == 1,
                      ExcMessage(
                        body.path
                        + "/Particles per cell must be a "
                          "power of "
                        + std::to_string(1u << dim) + " in "
                        + std::to_string(dim) + "D (1, "
                        + std::to_string(1u << dim) + ", "
                        + std::to_string(1u << (2 * dim)) + ", ...); got "
                        + std::to_string(body.particles_per_cell) + "."));
        }
        body.density = prm.get_double("Density");
        body.initial_velocity
          = parse_vector<dim>(prm.get("Initial velocity"),
                              body.path + "/Initial velocity");
        AssertThrow(body.initial_velocity.norm() <= max_speed,
                    ExcMessage(body.path + "/Initial velocity must not exceed "
                               + format(max_speed) + " m/s; got <"
                               + prm.get("Initial velocity") + ">."));
        const std::string initial = prm.get("Initial stress");
        body.initial_stress
          = initial == "geostatic"
              ? BodyDescription<dim>::InitialStress::geostatic
              : (initial == "hydrostatic"
                   ? BodyDescription<dim>::InitialStress::hydrostatic
                   : BodyDescription<dim>::InitialStress::none);
        body.k0             = prm.get_double("K0");
        body.velocity_field = prm.get_integer("Velocity field");
        AssertThrow(!body.fills_membrane || body.velocity_field == 0,
                    ExcMessage(body.path
                               + "/Shape = membrane needs Velocity field = 0: "
                                 "the membrane and its fill move with field "
                                 "0."));
        body.material = MaterialFactory::create(prm.get("Material model"),
                                                prm,
                                                body.density,
                                                body.path);

        const bool        fluid     = body.material->is_fluid();
        const std::string smoothing = prm.get("Volumetric smoothing");
        AssertThrow(
          !projection || smoothing == "default" || smoothing == "none",
          ExcMessage(
            body.path + "/Volumetric smoothing = " + smoothing
            + " cannot be combined with Simulation/Stress integration = "
              "nodal projection, which already averages the strain rate at "
              "the nodes (with NMD or ANP on top the dam break goes unstable "
              "at 0.3 s): set it to none or default."));
        body.options.nmd = (smoothing == "default")
                             ? fluid && !projection
                             : (smoothing.find("NMD") == 0);
        body.options.anp = (smoothing == "default")
                             ? fluid && !projection
                             : (smoothing.find("ANP") != std::string::npos);
        body.options.anp_interpolate
          = (prm.get("ANP mapping") == "interpolate");
        body.options.smoothing_stabilisation
          = prm.get_double("Smoothing stabilisation");
        body.options.capped_weights
          = (prm.get("Smoothing weights") == "capped cell volume");
        const std::string detect = prm.get("Free surface detection");
        body.options.detect_free_surface
          = (detect == "default") ? fluid : (detect == "true");
        body.options.free_surface_threshold
          = prm.get_double("Free surface threshold");
        AssertThrow(body.options.free_surface_threshold > 0
                      && body.options.free_surface_threshold < 1,
                    ExcMessage(body.path
                               + "/Free surface threshold must lie in the open "
                                 "interval (0, 1); got "
                               + prm.get("Free surface threshold") + "."));
        prm.leave_subsection();
        bodies.push_back(std::move(body));
      }
    prm.leave_subsection();
    return bodies;
  }

  template struct BodyDescription<2>;
  template struct BodyDescription<3>;
} // namespace fsgmpm
