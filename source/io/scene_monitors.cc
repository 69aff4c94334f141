#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/io/container_monitors.h>
#include <fsgmpm/io/membrane_output.h>
#include <fsgmpm/io/scene_monitors.h>

#include <algorithm>
#include <map>
#include <sstream>

#include <cmath>
#include <limits>

namespace fsgmpm
{
  template <int dim>
  void
  SceneMonitors<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Monitors");
    prm.declare_entry("Scene monitors",
                      "",
                      Patterns::MultipleSelection(
                        "front_position|column_height|runout|final_height|"
                        "height|width|contact_width|max_tension|mean_tension|"
                        "top_pressure|bottom_pressure|membrane_length|"
                        "enclosed_area|fluid_volume|particles_outside|"
                        "container_centre_x|container_centre_y|"
                        "container_velocity_y|container_tilt|soil_area|"
                        "soil_points_outside|water_points_inside|"
                        "water_inside_depth|soil_outside_distance|body_mass|"
                        "body_kinetic_energy"),
                      "Extra columns of monitors.csv: front_position (surge "
                      "front from the wall, bottom cell row) and "
                      "column_height (height at the wall), both from the "
                      "non-flagged points plus half a point spacing; "
                      "runout (largest x from the wall where the deposit is "
                      "at least one point spacing thick) and final_height "
                      "(highest point above the base plus half a spacing) "
                      "(m). With a membrane: height, width (max - min of the "
                      "membrane nodes), contact_width (extent of the nodes "
                      "within Contact tolerance of the lowest one), "
                      "max_tension, mean_tension (N/m), top_pressure, "
                      "bottom_pressure (Pa; least-squares line of the "
                      "particle pressure against y in the central strip, at "
                      "the membrane's top and bottom), membrane_length, "
                      "enclosed_area, fluid_volume and particles_outside "
                      "(points of the Container body outside the closed "
                      "membrane, 2D or an extruded 3D membrane). A body "
                      "among others (geocontainer): container_centre_x, "
                      "container_centre_y, container_velocity_y (mass-"
                      "weighted, of the Container body), container_tilt "
                      "(degrees of its major principal axis from x), "
                      "soil_area (its point volumes, per metre in 3D), "
                      "soil_points_outside (its points outside the "
                      "membrane), water_points_inside (other bodies' points "
                      "inside it), water_inside_depth and "
                      "soil_outside_distance (m: how far the deepest of "
                      "those points lies across the membrane). body_mass "
                      "and body_kinetic_energy give "
                      "one column per body: body_mass_0, body_mass_1, ...");
    prm.declare_entry("Container body",
                      "0",
                      Patterns::Integer(0),
                      "Index of the body the membrane holds (the fill), for "
                      "the container and geotube columns.");
    prm.declare_entry("Wall position",
                      "auto",
                      Patterns::Anything(),
                      "x of the wall the column stands against (m); auto: "
                      "the mesh's smallest x.");
    prm.declare_entry("Base position",
                      "auto",
                      Patterns::Anything(),
                      "y of the base (m); auto: the mesh's smallest y.");
    prm.declare_entry("Row height",
                      "auto",
                      Patterns::Anything(),
                      "Height of the bottom cell row (m); auto: the cell size "
                      "in y.");
    prm.declare_entry("Column width",
                      "auto",
                      Patterns::Anything(),
                      "Width of the strip at the wall for column_height (m); "
                      "auto: the cell size in x.");
    prm.declare_entry("Contact tolerance",
                      "auto",
                      Patterns::Anything(),
                      "contact_width: membrane nodes at most this far above "
                      "the lowest node touch the ground (m); auto: a tenth "
                      "of the bottom row height.");
    prm.declare_entry("Pressure strip width",
                      "auto",
                      Patterns::Anything(),
                      "Width of the central strip for top_pressure and "
                      "bottom_pressure (m); auto: two cells.");
    prm.leave_subsection();
  }



  namespace
  {
    double
    auto_or_value(const std::string &text,
                  const double       fallback,
                  const std::string &path)
    {
      const std::string t = Utilities::trim(text);
      if (t == "auto")
        return fallback;
      std::istringstream in(t);
      double             x = 0;
      in >> x;
      AssertThrow(!in.fail() && in.eof() && std::isfinite(x)
                    && std::abs(x) <= 1e9,
                  ExcMessage(path
                             + " must be auto or a finite number (m, within "
                               "+-1e9); got <"
                             + text + ">."));
      return x;
    }
  } // namespace



  template <int dim>
  SceneMonitors<dim>::SceneMonitors(ParameterHandler  &prm,
                                    const Point<dim>  &lower,
                                    const Point<dim>  &cell_size,
                                    const unsigned int n_bodies)
    : n_bodies(n_bodies)
  {
    prm.enter_subsection("Monitors");
    for (const auto &name :
         Utilities::split_string_list(prm.get("Scene monitors"), ','))
      if (name == "body_mass" || name == "body_kinetic_energy")
        for (unsigned int b = 0; b < n_bodies; ++b)
          columns.push_back(name + "_" + std::to_string(b));
      else if (!name.empty())
        columns.push_back(name);
    container = prm.get_integer("Container body");
    AssertThrow(container < n_bodies,
                ExcMessage("Monitors/Container body is "
                           + std::to_string(container) + ", but there "
                           + (n_bodies == 1
                                ? "is 1 body"
                                : "are " + std::to_string(n_bodies) + " bodies")
                           + " (Bodies/Number of bodies); give the index of "
                             "the body the membrane holds."));
    wall_x            = auto_or_value(prm.get("Wall position"),
                           lower[0],
                           "Monitors/Wall position");
    base_y            = auto_or_value(prm.get("Base position"),
                           lower[1],
                           "Monitors/Base position");
    row_height        = auto_or_value(prm.get("Row height"),
                               cell_size[1],
                               "Monitors/Row height");
    column_width      = auto_or_value(prm.get("Column width"),
                                 cell_size[0],
                                 "Monitors/Column width");
    contact_tolerance = auto_or_value(prm.get("Contact tolerance"),
                                      0.1 * cell_size[1],
                                      "Monitors/Contact tolerance");
    strip_width       = auto_or_value(prm.get("Pressure strip width"),
                                2 * cell_size[0],
                                "Monitors/Pressure strip width");
    prm.leave_subsection();
    AssertThrow(contact_tolerance >= 0 && strip_width > 0,
                ExcMessage("Monitors/Contact tolerance must be >= 0 and "
                           "Monitors/Pressure strip width > 0."));
  }



  template <int dim>
  bool
  SceneMonitors<dim>::needs_membrane() const
  {
    for (const auto &name : columns)
      if (std::count(membrane_monitor_names().begin(),
                     membrane_monitor_names().end(),
                     name))
        return true;
    return false;
  }



  template <int dim>
  std::vector<double>
  SceneMonitors<dim>::evaluate(const ParticleStore<dim> &particles,
                               const Membrane<dim>      *membrane) const
  {
    double front = 0, height = 0, runout = 0, top = 0;
    for (unsigned int p = 0; p < particles.size(); ++p)
      {
        const double half_spacing
          = 0.5
            * (dim == 2 ? std::sqrt(particles.volume[p])
                        : std::cbrt(particles.volume[p]));
        const double x = particles.position[p][0] - wall_x;
        const double y = particles.position[p][1] - base_y;
        // A point resting on the base makes the deposit one spacing thick.
        if (y + half_spacing >= 2 * half_spacing * (1 - 1e-3))
          runout = std::max(runout, x + half_spacing);
        top = std::max(top, y + half_spacing);
        if (particles.free_surface[p])
          continue;
        if (y < row_height)
          front = std::max(front, x + half_spacing);
        if (x < column_width)
          height = std::max(height, y + half_spacing);
      }
    std::map<std::string, double> values = {{"front_position", front},
                                            {"column_height", height},
                                            {"runout", runout},
                                            {"final_height", top}};
    if (membrane != nullptr)
      values.merge(membrane_monitors(
        *membrane, particles, contact_tolerance, strip_width, container));
    // Only when asked for: the inside tests cost a polygon walk per point.
    const auto wanted = [&](const std::vector<std::string> &names) {
      for (const auto &name : columns)
        if (std::count(names.begin(), names.end(), name))
          return true;
      return false;
    };
    if (wanted(container_monitor_names()))
      values.merge(container_monitors(particles, membrane, container));
    if (std::any_of(columns.begin(), columns.end(), [](const auto &name) {
          return name.rfind("body_", 0) == 0;
        }))
      values.merge(body_monitors(particles, n_bodies));
    std::vector<double> row;
    for (const auto &name : columns)
      {
        const auto it = values.find(name);
        AssertThrow(it != values.end(),
                    ExcMessage("Monitors/Scene monitors: " + name
                               + " needs a membrane (Membrane/Enabled)."));
        row.push_back(it->second);
      }
    return row;
  }

  template class SceneMonitors<2>;
  template class SceneMonitors<3>;
} // namespace fsgmpm
