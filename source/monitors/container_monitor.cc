#include <deal.II/base/bounding_box.h>

#include <fsgmpm/base/compensated_sum.h>
#include <fsgmpm/monitors/container_monitor.h>
#include <fsgmpm/monitors/monitor_factory.h>
#include <fsgmpm/particles/body_shape.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsgmpm
{
  const std::vector<std::string> &
  container_monitor_names()
  {
    static const std::vector<std::string> names = {"container_centre_x",
                                                   "container_centre_y",
                                                   "container_velocity_y",
                                                   "container_tilt",
                                                   "soil_area",
                                                   "soil_points_outside",
                                                   "water_points_inside",
                                                   "water_inside_depth",
                                                   "soil_outside_distance"};
    return names;
  }



  template <int dim>
  std::map<std::string, double>
  container_monitors(const ParticleStore<dim> &particles,
                     const Membrane<dim>      *membrane,
                     const unsigned int        container,
                     const MPI_Comm            communicator)
  {
    // Compensated sums over this process's points, then over the
    // processes: the tilt below takes the angle of nearly cancelling
    // moments, which must not depend on the order of the points.
    std::vector<CompensatedSum> sums(5); // m, m x, m y, m v_y, volume
    for (unsigned int p = 0; p < particles.size(); ++p)
      if (particles.body_id[p] == container)
        {
          sums[0].add(particles.mass[p]);
          sums[1].add(particles.mass[p] * particles.position[p][0]);
          sums[2].add(particles.mass[p] * particles.position[p][1]);
          sums[3].add(particles.mass[p] * particles.velocity[p][1]);
          sums[4].add(particles.volume[p]);
        }
    const std::vector<double> first = sum_over_processes(sums, communicator);
    const double              m = first[0], mvy = first[3];
    double                    volume = first[4];
    const double xc = m > 0 ? first[1] / m : 0., yc = m > 0 ? first[2] / m : 0.;

    // Principal axis of the second moment: tan 2 theta = 2 Ixy/(Ixx - Iyy)
    // with Ixx = sum m dx^2 (spread along x).
    std::vector<CompensatedSum> moments(3); // Ixx, Iyy, Ixy
    for (unsigned int p = 0; p < particles.size(); ++p)
      if (particles.body_id[p] == container)
        {
          const double dx = particles.position[p][0] - xc,
                       dy = particles.position[p][1] - yc;
          moments[0].add(particles.mass[p] * dx * dx);
          moments[1].add(particles.mass[p] * dy * dy);
          moments[2].add(particles.mass[p] * dx * dy);
        }
    const std::vector<double> second
      = sum_over_processes(moments, communicator);
    const double tilt
      = 0.5 * std::atan2(2 * second[2], second[0] - second[1]) * 180. / M_PI;

    // Distance of a point from the membrane polygon (how far an offending
    // point has crossed it: within a cell is the resolution of grid-node
    // coupling, more is a leak).
    const auto distance
      = [](const std::vector<Point<2>> &poly, const Point<2> &x) {
          double d2 = std::numeric_limits<double>::max();
          for (unsigned int k = 0; k < poly.size(); ++k)
            {
              const Point<2>    &a = poly[k];
              const Tensor<1, 2> e = poly[(k + 1) % poly.size()] - a;
              const double       t
                = std::clamp(((x - a) * e) / std::max(e.norm_square(), 1e-300),
                             0.,
                             1.);
              d2 = std::min(d2, (x - (a + t * e)).norm_square());
            }
          return std::sqrt(d2);
        };
    double soil_outside = 0, water_inside = 0;
    double soil_outside_distance = 0, water_inside_depth = 0;
    if (membrane != nullptr && (dim == 2 || !membrane->rings.empty()))
      {
        std::vector<Point<2>> poly;
        for (const auto &x : membrane->ordered_nodes())
          poly.emplace_back(x[0], x[1]);
        // A point off the polygon's bounding box (by more than round-off)
        // is outside: its ray crosses the polygon an even number of times
        // or not at all, so inside_polygon() would say so too. Most water
        // points are, and the tests evaluate this at every step.
        BoundingBox<2> box(poly);
        const double   diagonal = box.get_boundary_points().first.distance(
          box.get_boundary_points().second);
        box.extend(1e-9 * diagonal);
        const PolygonInside inside_test(poly);
        for (unsigned int p = 0; p < particles.size(); ++p)
          {
            const Point<2> x(particles.position[p][0],
                             particles.position[p][1]);
            const bool     inside = box.point_inside(x, 0.) && inside_test(x);
            if (particles.body_id[p] == container && !inside)
              {
                ++soil_outside;
                soil_outside_distance
                  = std::max(soil_outside_distance, distance(poly, x));
              }
            else if (particles.body_id[p] != container && inside)
              {
                ++water_inside;
                water_inside_depth
                  = std::max(water_inside_depth, distance(poly, x));
              }
          }
      }
    double counts[2] = {soil_outside, water_inside};
    Utilities::MPI::sum(counts, communicator, counts);
    soil_outside = counts[0];
    water_inside = counts[1];
    if (dim == 3)
      {
        // Per unit thickness, comparable with the plane-strain scene.
        double z0 = std::numeric_limits<double>::max(), z1 = -z0;
        for (const auto &x : particles.position)
          {
            z0 = std::min(z0, x[dim - 1]);
            z1 = std::max(z1, x[dim - 1]);
          }
        if (membrane != nullptr)
          for (const auto &x : membrane->position)
            {
              z0 = std::min(z0, x[dim - 1]);
              z1 = std::max(z1, x[dim - 1]);
            }
        z0 = Utilities::MPI::min(z0, communicator);
        z1 = Utilities::MPI::max(z1, communicator);
        if (z1 > z0)
          volume /= z1 - z0;
      }
    // The largest crossing distances: a maximum over the processes.
    double depths[2] = {water_inside_depth, soil_outside_distance};
    Utilities::MPI::max(depths, communicator, depths);
    water_inside_depth    = depths[0];
    soil_outside_distance = depths[1];
    return {{"container_centre_x", xc},
            {"container_centre_y", yc},
            {"container_velocity_y", m > 0 ? mvy / m : 0.},
            {"container_tilt", tilt},
            {"soil_area", volume},
            {"soil_points_outside", soil_outside},
            {"water_points_inside", water_inside},
            {"water_inside_depth", water_inside_depth},
            {"soil_outside_distance", soil_outside_distance}};
  }



  template <int dim>
  ContainerMonitor<dim>::ContainerMonitor(ParameterHandler &,
                                          const MonitorSetup<dim> &setup)
    : container(setup.container_body)
  {}



  template <int dim>
  std::vector<double>
  ContainerMonitor<dim>::evaluate(const MonitorContext<dim> &context) const
  {
    const auto          values = container_monitors(context.particles,
                                           context.membrane,
                                           container,
                                           context.communicator);
    std::vector<double> row;
    for (const auto &name : container_monitor_names())
      row.push_back(values.at(name));
    return row;
  }



  template std::map<std::string, double>
  container_monitors<2>(const ParticleStore<2> &,
                        const Membrane<2> *,
                        const unsigned int,
                        const MPI_Comm);
  template std::map<std::string, double>
  container_monitors<3>(const ParticleStore<3> &,
                        const Membrane<3> *,
                        const unsigned int,
                        const MPI_Comm);
  template class ContainerMonitor<2>;
  template class ContainerMonitor<3>;

  FSGMPM_REGISTER_MONITOR(ContainerMonitor,
                          "container",
                          "centre, vertical velocity, tilt and area of the "
                          "body the membrane holds, and the points that "
                          "crossed the membrane either way")
} // namespace fsgmpm
