#include <deal.II/base/exceptions.h>
#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/base/format.h>
#include <fsgmpm/grid/moving_wall.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace fsgmpm
{
  namespace
  {
    const std::string section = "Moving wall/";

    /// Numbers separated by @p separator ("," or whitespace when " ").
    std::vector<double>
    read_numbers(const std::string &text,
                 const std::string &separator,
                 const std::string &path)
    {
      std::vector<std::string> items;
      if (separator == " ")
        {
          std::istringstream in(text);
          for (std::string item; in >> item;)
            items.push_back(item);
        }
      else
        items = Utilities::split_string_list(text, separator);
      std::vector<double> values;
      for (const std::string &item : items)
        {
          std::istringstream in(item);
          double             x;
          std::string        rest;
          AssertThrow((in >> x) && !(in >> rest) && std::isfinite(x),
                      ExcMessage(path + ": <" + item + "> is not a number in <"
                                 + text + ">."));
          values.push_back(x);
        }
      return values;
    }
  } // namespace



  void
  MovingWallParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Moving wall");
    {
      prm.declare_entry("Enabled",
                        "false",
                        Patterns::Bool(),
                        "A rigid, frictionless plane wall (a gate) that moves "
                        "in its own plane with a prescribed velocity and "
                        "holds the material on one side: on the grid nodes "
                        "of its plane inside its current extent it acts as a "
                        "slip wall. The plane must pass through grid nodes.");
      prm.declare_entry("Material side",
                        "-x",
                        Patterns::Selection("-x|+x|-y|+y|-z|+z"),
                        "The side of the wall the material is on: '-x' for "
                        "material at smaller x than the wall (a gate on the "
                        "right of a water column).");
      prm.declare_entry("Lower corner",
                        "0, 0",
                        Patterns::Anything(),
                        "A corner of the wall at t = 0 (m); its coordinate "
                        "along the normal axis gives the wall's plane.");
      prm.declare_entry("Upper corner",
                        "0, 1",
                        Patterns::Anything(),
                        "The opposite corner at t = 0 (m): the same "
                        "coordinate along the normal axis, larger in every "
                        "other one.");
      prm.declare_entry("Velocity history",
                        "0: 0 0",
                        Patterns::Anything(),
                        "The wall's velocity (m/s) as 't: v_x v_y[ v_z], "
                        "...' with t in s, from t = 0, strictly increasing; "
                        "piecewise linear in between and held after the last "
                        "time. The normal component must be 0 (the wall "
                        "moves in its own plane). E.g. '0: 0 0, 0.01: 0 2' "
                        "lifts a gate at 2 m/s after a 10 ms ramp.");
    }
    prm.leave_subsection();
  }



  void
  MovingWallParameters::parse_parameters(ParameterHandler  &prm,
                                         const unsigned int dim)
  {
    prm.enter_subsection("Moving wall");
    enabled                        = prm.get_bool("Enabled");
    const std::string side         = prm.get("Material side");
    axis                           = side[1] - 'x';
    outward_sign                   = (side[0] == '-') ? 1. : -1.;
    const std::string lower_text   = prm.get("Lower corner");
    const std::string upper_text   = prm.get("Upper corner");
    const std::string history_text = prm.get("Velocity history");
    prm.leave_subsection();
    if (!enabled)
      return;

    AssertThrow(axis < dim,
                ExcMessage(section + "Material side = " + side
                           + " names an axis a " + std::to_string(dim)
                           + "D scene does not have."));
    lower = read_numbers(lower_text, ",", section + "Lower corner");
    upper = read_numbers(upper_text, ",", section + "Upper corner");
    AssertThrow(lower.size() == dim && upper.size() == dim,
                ExcMessage(section + "Lower corner and Upper corner need "
                           + std::to_string(dim)
                           + " comma-separated "
                             "coordinates each."));
    const double scale = std::abs(upper[axis]) + std::abs(lower[axis]) + 1.;
    const std::string axis_name(1, static_cast<char>('x' + axis));
    AssertThrow(std::abs(upper[axis] - lower[axis]) <= 1e-12 * scale,
                ExcMessage(section + "Lower corner and " + section
                           + "Upper corner: the wall is a plane normal to "
                           + axis_name + " (Material side = " + side
                           + "), so both corners need the same " + axis_name
                           + ", not " + format(lower[axis]) + " and "
                           + format(upper[axis]) + "."));
    for (unsigned int d = 0; d < dim; ++d)
      AssertThrow(d == axis || lower[d] < upper[d],
                  ExcMessage(section + "Upper corner must be larger than "
                             + section + "Lower corner in "
                             + std::string(1, static_cast<char>('x' + d))
                             + " (every coordinate but the normal one, "
                             + axis_name + "); got " + format(lower[d])
                             + " and " + format(upper[d]) + "."));

    const std::string help = " Expected 't: v_x v_y"
                             + std::string(dim == 3 ? " v_z" : "")
                             + ", ...' from t = 0, e.g. '0: 0 0, 0.01: 0 2'.";
    history.clear();
    for (const std::string &item :
         Utilities::split_string_list(history_text, ','))
      {
        const auto parts = Utilities::split_string_list(item, ':');
        AssertThrow(parts.size() == 2,
                    ExcMessage(section + "Velocity history: cannot read <"
                               + item + ">." + help));
        const std::vector<double> t
          = read_numbers(parts[0], " ", section + "Velocity history");
        const std::vector<double> v
          = read_numbers(parts[1], " ", section + "Velocity history");
        AssertThrow(t.size() == 1 && v.size() == dim,
                    ExcMessage(section + "Velocity history: <" + item
                               + "> needs one time and " + std::to_string(dim)
                               + " velocity components." + help));
        AssertThrow(history.empty() ? t[0] == 0. : t[0] > history.back()[0],
                    ExcMessage(section
                               + "Velocity history: the times must "
                                 "start at 0 and increase strictly; <"
                               + item + "> does not." + help));
        AssertThrow(v[axis] == 0.,
                    ExcMessage(section + "Velocity history: <" + item
                               + "> moves the wall along its normal; only "
                                 "motion in the wall's own plane (a lifted "
                                 "or sliding gate) is supported."));
        std::array<double, 4> sample{{t[0], 0., 0., 0.}};
        for (unsigned int d = 0; d < dim; ++d)
          sample[1 + d] = v[d];
        history.push_back(sample);
      }
    AssertThrow(!history.empty(),
                ExcMessage(section + "Velocity history is empty." + help));
  }



  template <int dim>
  MovingWall<dim>::MovingWall(const MovingWallParameters &wall_parameters,
                              const BackgroundGrid<dim>  &background_grid)
    : parameters(wall_parameters)
    , grid(background_grid)
  {
    Assert(parameters.enabled, ExcInternalError());
    const unsigned int axis = parameters.axis;
    normal[axis]            = parameters.outward_sign;

    // "On the plane" and "inside the extent" to round-off of the mesh:
    // relative to its shortest edge.
    double shortest = std::numeric_limits<double>::max();
    for (unsigned int c = 0; c < grid.n_base_cells(); ++c)
      for (unsigned int i = 0; i < dim + 1; ++i)
        for (unsigned int j = i + 1; j < dim + 1; ++j)
          shortest
            = std::min(shortest,
                       grid.node_positions[grid.cell_nodes[c][i]].distance(
                         grid.node_positions[grid.cell_nodes[c][j]]));
    tolerance = 1e-6 * shortest;

    const double      plane = parameters.lower[axis];
    const std::string where = "Moving wall/Lower corner and Upper corner: the "
                              "wall's plane "
                              + std::string(1, static_cast<char>('x' + axis))
                              + " = " + format(plane);
    for (unsigned int i = 0; i < grid.n_nodes(); ++i)
      if (std::abs(grid.node_positions[i][axis] - plane) <= tolerance)
        plane_nodes.push_back(i);
    active.assign(grid.n_nodes(), 0);
    set_time(0.);
    // A process's window of the grid (MPI) may hold none of the wall: the
    // whole grid was checked at the start of the run.
    if (grid.is_window())
      return;
    AssertThrow(n_active > 0,
                ExcMessage(where
                           + " holds no grid node inside the wall's "
                             "extent at t = 0. The wall acts on grid "
                             "nodes, so its plane must be a grid line "
                             "(for a box mesh, a multiple of the cell "
                             "size from Grid/Lower corner) and its "
                             "extent must cover some of them."));

    // A cell that the plane cuts inside the wall's extent would let the
    // material through between the wall's nodes (an unstructured mesh
    // whose edges do not follow the plane).
    for (unsigned int c = 0; c < grid.n_base_cells(); ++c)
      {
        double lowest = 0, highest = 0;
        bool   overlaps = true;
        for (unsigned int d = 0; d < dim; ++d)
          if (d != axis)
            {
              double cell_min = std::numeric_limits<double>::max(),
                     cell_max = -cell_min;
              for (unsigned int k = 0; k < dim + 1; ++k)
                {
                  const double x
                    = grid.node_positions[grid.cell_nodes[c][k]][d];
                  cell_min = std::min(cell_min, x);
                  cell_max = std::max(cell_max, x);
                }
              overlaps = overlaps && cell_max > parameters.lower[d] + tolerance
                         && cell_min < parameters.upper[d] - tolerance;
            }
        for (unsigned int k = 0; k < dim + 1; ++k)
          {
            const double s
              = grid.node_positions[grid.cell_nodes[c][k]][axis] - plane;
            lowest  = std::min(lowest, s);
            highest = std::max(highest, s);
          }
        AssertThrow(!overlaps || lowest > -tolerance || highest < tolerance,
                    ExcMessage(where + " cuts through cell " + std::to_string(c)
                               + " inside the wall's extent: the mesh's edges "
                                 "must follow the plane there, or the "
                                 "material passes between the wall's nodes."));
      }
  }



  template <int dim>
  Tensor<1, dim>
  MovingWall<dim>::velocity(const double t) const
  {
    const auto    &h = parameters.history;
    Tensor<1, dim> v;
    unsigned int   k = 0;
    while (k + 1 < h.size() && h[k + 1][0] <= t)
      ++k;
    const double s
      = (k + 1 < h.size())
          ? std::clamp((t - h[k][0]) / (h[k + 1][0] - h[k][0]), 0., 1.)
          : 0.;
    for (unsigned int d = 0; d < dim; ++d)
      v[d] = h[k][1 + d]
             + ((k + 1 < h.size()) ? s * (h[k + 1][1 + d] - h[k][1 + d]) : 0.);
    return v;
  }



  template <int dim>
  Tensor<1, dim>
  MovingWall<dim>::displacement(const double t) const
  {
    Assert(t >= 0, ExcMessage("The wall's motion starts at t = 0."));
    // Trapezoidal rule on each linear piece: exact.
    const auto    &h = parameters.history;
    Tensor<1, dim> u;
    for (unsigned int k = 0; k < h.size() && h[k][0] < t; ++k)
      {
        const bool   last = (k + 1 == h.size());
        const double t1   = last ? t : std::min(t, h[k + 1][0]);
        const double s = last ? 0. : (t1 - h[k][0]) / (h[k + 1][0] - h[k][0]);
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double v1
              = h[k][1 + d] + (last ? 0. : s * (h[k + 1][1 + d] - h[k][1 + d]));
            u[d] += 0.5 * (t1 - h[k][0]) * (h[k][1 + d] + v1);
          }
      }
    return u;
  }



  template <int dim>
  void
  MovingWall<dim>::set_time(const double t)
  {
    wall_velocity          = velocity(t);
    const Tensor<1, dim> u = displacement(t);
    n_active               = 0;
    for (const unsigned int i : plane_nodes)
      {
        bool inside = true;
        for (unsigned int d = 0; d < dim; ++d)
          if (d != parameters.axis)
            inside = inside
                     && grid.node_positions[i][d]
                          >= parameters.lower[d] + u[d] - tolerance
                     && grid.node_positions[i][d]
                          <= parameters.upper[d] + u[d] + tolerance;
        active[i] = inside;
        n_active += inside;
      }
  }

  template class MovingWall<2>;
  template class MovingWall<3>;
} // namespace fsgmpm
