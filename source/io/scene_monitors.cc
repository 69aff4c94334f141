#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/io/scene_monitors.h>

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
                        "front_position|column_height|runout|final_height"),
                      "Extra columns of monitors.csv: front_position (surge "
                      "front from the wall, bottom cell row) and "
                      "column_height (height at the wall), both from the "
                      "non-flagged points plus half a point spacing; "
                      "runout (largest x from the wall where the deposit is "
                      "at least one point spacing thick) and final_height "
                      "(highest point above the base plus half a spacing) "
                      "(m).");
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
    prm.leave_subsection();
  }



  namespace
  {
    double
    auto_or_value(const std::string &text,
                  const double       fallback,
                  const std::string &path)
    {
      if (Utilities::trim(text) == "auto")
        return fallback;
      try
        {
          return Utilities::string_to_double(text);
        }
      catch (...)
        {
          AssertThrow(false,
                      ExcMessage(path + " must be a number or auto; got <"
                                 + text + ">."));
        }
      return fallback;
    }
  } // namespace



  template <int dim>
  SceneMonitors<dim>::SceneMonitors(ParameterHandler &prm,
                                    const Point<dim> &lower,
                                    const Point<dim> &cell_size)
  {
    prm.enter_subsection("Monitors");
    for (const auto &name :
         Utilities::split_string_list(prm.get("Scene monitors"), ','))
      if (!name.empty())
        columns.push_back(name);
    wall_x       = auto_or_value(prm.get("Wall position"),
                           lower[0],
                           "Monitors/Wall position");
    base_y       = auto_or_value(prm.get("Base position"),
                           lower[1],
                           "Monitors/Base position");
    row_height   = auto_or_value(prm.get("Row height"),
                               cell_size[1],
                               "Monitors/Row height");
    column_width = auto_or_value(prm.get("Column width"),
                                 cell_size[0],
                                 "Monitors/Column width");
    prm.leave_subsection();
  }



  template <int dim>
  std::vector<double>
  SceneMonitors<dim>::evaluate(const ParticleStore<dim> &particles) const
  {
    double front = 0, height = 0, runout = 0, top = 0;
    for (unsigned int p = 0; p < particles.size(); ++p)
      {
        const double half_spacing
          = 0.5 * std::pow(particles.volume[p], 1. / dim);
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
    std::vector<double> values;
    for (const auto &name : columns)
      values.push_back(name == "front_position"  ? front
                       : name == "column_height" ? height
                       : name == "runout"        ? runout
                                                 : top);
    return values;
  }

  template class SceneMonitors<2>;
  template class SceneMonitors<3>;
} // namespace fsgmpm
