#include <fsgmpm/base/compensated_sum.h>
#include <fsgmpm/base/parameter_parsing.h>
#include <fsgmpm/monitors/geotube_monitor.h>
#include <fsgmpm/monitors/monitor_factory.h>
#include <fsgmpm/particles/body_shape.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsgmpm
{
  const std::vector<std::string> &
  membrane_monitor_names()
  {
    static const std::vector<std::string> names = {"height",
                                                   "width",
                                                   "contact_width",
                                                   "max_tension",
                                                   "mean_tension",
                                                   "top_pressure",
                                                   "bottom_pressure",
                                                   "membrane_length",
                                                   "enclosed_area",
                                                   "fluid_volume",
                                                   "particles_outside"};
    return names;
  }



  template <int dim>
  std::map<std::string, double>
  membrane_monitors(const Membrane<dim>      &membrane,
                    const ParticleStore<dim> &particles,
                    const double              contact_tolerance,
                    const double              strip_width,
                    const unsigned int        fill_body,
                    const MPI_Comm            communicator)
  {
    constexpr double big = std::numeric_limits<double>::max();
    double           x0 = big, x1 = -big, y0 = big, y1 = -big;
    for (const auto &p : membrane.position)
      {
        x0 = std::min(x0, p[0]);
        x1 = std::max(x1, p[0]);
        y0 = std::min(y0, p[1]);
        y1 = std::max(y1, p[1]);
      }
    double c0 = big, c1 = -big;
    for (const auto &p : membrane.position)
      if (p[1] <= y0 + contact_tolerance)
        {
          c0 = std::min(c0, p[0]);
          c1 = std::max(c1, p[0]);
        }

    double max_t = 0, tl = 0, l = 0;
    for (unsigned int e = 0; e < membrane.n_elements(); ++e)
      {
        const double s = membrane.element_size(e);
        max_t          = std::max(max_t, membrane.tension[e]);
        tl += membrane.tension[e] * s;
        l += s;
      }

    // Least-squares p = p0 + p1 (y - y_mean) over the central strip.
    const double xc = 0.5 * (x0 + x1);
    // Compensated sums (n, sy, sp, syy, syp, volume): the fit below
    // subtracts nearly equal sums, so their own rounding must not depend
    // on the order of the points or on how they are split over processes.
    std::vector<CompensatedSum> sums(6);
    for (unsigned int q = 0; q < particles.size(); ++q)
      {
        if (particles.body_id[q] != fill_body)
          continue;
        sums[5].add(particles.volume[q]);
        if (std::abs(particles.position[q][0] - xc) > 0.5 * strip_width)
          continue;
        const double y = particles.position[q][1];
        const double p = -trace(particles.stress[q]) / 3.;
        sums[0].add(1.);
        sums[1].add(y);
        sums[2].add(p);
        sums[3].add(y * y);
        sums[4].add(y * p);
      }
    const std::vector<double> global = sum_over_processes(sums, communicator);
    const double n = global[0], sy = global[1], sp = global[2], syy = global[3],
                 syp = global[4];
    double volume    = global[5];
    double p_top = 0, p_bottom = 0;
    if (n >= 2)
      {
        const double ym = sy / n, pm = sp / n;
        const double var   = syy / n - ym * ym;
        const double slope = var > 0 ? (syp / n - ym * pm) / var : 0.;
        p_top              = pm + slope * (y1 - ym);
        p_bottom           = pm + slope * (y0 - ym);
      }

    // Extruded 3D membrane: length and area per ring (their mean) and the
    // fluid volume per unit thickness, comparable with the 2D scene.
    double length = membrane.total_size(), area = membrane.enclosed_area();
    if (dim == 3 && !membrane.rings.empty())
      {
        double z0 = big, z1 = -big;
        for (const auto &p : membrane.position)
          {
            z0 = std::min(z0, p[dim - 1]);
            z1 = std::max(z1, p[dim - 1]);
          }
        length = area = 0;
        for (const auto &ring : membrane.rings)
          {
            length += membrane.loop_length(ring) / membrane.rings.size();
            area += membrane.loop_area(ring) / membrane.rings.size();
          }
        if (z1 > z0)
          volume /= z1 - z0;
      }

    // Points outside the closed membrane (even-odd rule in x-y; 3D: the
    // first ring of an extruded membrane): fluid that leaked between
    // membrane nodes.
    double outside = 0;
    if (dim == 2 || !membrane.rings.empty())
      {
        std::vector<Point<2>> poly;
        for (const auto &x : membrane.ordered_nodes())
          poly.emplace_back(x[0], x[1]);
        const PolygonInside inside(poly);
        for (unsigned int q = 0; q < particles.size(); ++q)
          if (particles.body_id[q] == fill_body)
            outside += !inside(
              Point<2>(particles.position[q][0], particles.position[q][1]));
        outside = Utilities::MPI::sum(outside, communicator);
      }

    return {{"particles_outside", outside},
            {"height", y1 - y0},
            {"width", x1 - x0},
            {"contact_width", c1 - c0},
            {"max_tension", max_t},
            {"mean_tension", l > 0 ? tl / l : 0.},
            {"top_pressure", p_top},
            {"bottom_pressure", p_bottom},
            {"membrane_length", length},
            {"enclosed_area", area},
            {"fluid_volume", volume}};
  }



  template <int dim>
  void
  GeotubeMonitor<dim>::declare_parameters(ParameterHandler &prm)
  {
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
  }



  template <int dim>
  GeotubeMonitor<dim>::GeotubeMonitor(ParameterHandler        &prm,
                                      const MonitorSetup<dim> &setup)
    : contact_tolerance(parse_auto_or_double(prm.get("Contact tolerance"),
                                             0.1 * setup.cell_size[1],
                                             "Monitors/Contact tolerance"))
    , strip_width(parse_auto_or_double(prm.get("Pressure strip width"),
                                       2 * setup.cell_size[0],
                                       "Monitors/Pressure strip width"))
    , fill_body(setup.container_body)
  {
    AssertThrow(contact_tolerance >= 0 && strip_width > 0,
                ExcMessage("Monitors/Contact tolerance must be >= 0 and "
                           "Monitors/Pressure strip width > 0."));
  }



  template <int dim>
  std::vector<double>
  GeotubeMonitor<dim>::evaluate(const MonitorContext<dim> &context) const
  {
    AssertThrow(context.membrane != nullptr,
                ExcMessage("The geotube monitor needs a membrane "
                           "(Membrane/Enabled)."));
    const auto          values = membrane_monitors(*context.membrane,
                                          context.particles,
                                          contact_tolerance,
                                          strip_width,
                                          fill_body,
                                          context.communicator);
    std::vector<double> row;
    for (const auto &name : membrane_monitor_names())
      row.push_back(values.at(name));
    return row;
  }

  template std::map<std::string, double>
  membrane_monitors<2>(const Membrane<2> &,
                       const ParticleStore<2> &,
                       const double,
                       const double,
                       const unsigned int,
                       const MPI_Comm);
  template std::map<std::string, double>
  membrane_monitors<3>(const Membrane<3> &,
                       const ParticleStore<3> &,
                       const double,
                       const double,
                       const unsigned int,
                       const MPI_Comm);
  template class GeotubeMonitor<2>;
  template class GeotubeMonitor<3>;

  FSGMPM_REGISTER_MONITOR(GeotubeMonitor,
                          "geotube",
                          "the membrane's size, ground contact and tensions, "
                          "the fill's pressure at its top and bottom, "
                          "volume and leaked points")
} // namespace fsgmpm
