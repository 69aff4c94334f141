#include <deal.II/base/bounding_box.h>

#include <fsgmpm/base/compensated_sum.h>
#include <fsgmpm/monitors/container_monitor.h>
#include <fsgmpm/monitors/monitor_factory.h>
#include <fsgmpm/particles/body_shape.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>

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
        // The membrane's cross-section that a point is tested against: in
        // 2D the loop; in 3D the exact section of the triangulated surface
        // at the point's own z between the two rings around it (each ring a
        // z level of nodes forming one closed loop), so that a point is not
        // judged by a face of the slab where the membrane stands a
        // millimetre elsewhere. Ring j + 1's nodes are matched to ring j's
        // by their nearest (x, y).
        std::vector<std::vector<unsigned int>> rings;
        std::vector<double>                    levels;
        if (dim == 3 && membrane->rings.size() >= 2)
          {
            std::vector<std::pair<double, unsigned int>> by_z;
            for (unsigned int r = 0; r < membrane->rings.size(); ++r)
              {
                double z = 0;
                for (const unsigned int a : membrane->rings[r])
                  z += membrane->position[a][dim - 1];
                by_z.emplace_back(z / membrane->rings[r].size(), r);
              }
            std::sort(by_z.begin(), by_z.end());
            const auto xy_distance
              = [&](const unsigned int a, const unsigned int b) {
                  return std::hypot(membrane->position[a][0]
                                      - membrane->position[b][0],
                                    membrane->position[a][1]
                                      - membrane->position[b][1]);
                };
            for (const auto &[z, r] : by_z)
              {
                std::vector<unsigned int> ring = membrane->rings[r];
                if (!rings.empty())
                  {
                    if (ring.size() != rings.back().size())
                      continue; // rings that do not correspond
                    std::vector<unsigned int> matched(ring.size());
                    for (unsigned int k = 0; k < ring.size(); ++k)
                      matched[k] = *std::min_element(
                        ring.begin(),
                        ring.end(),
                        [&](const unsigned int a, const unsigned int b) {
                          return xy_distance(a, rings.back()[k])
                                 < xy_distance(b, rings.back()[k]);
                        });
                    ring = matched;
                  }
                rings.push_back(ring);
                levels.push_back(z);
              }
          }
        else
          rings.push_back(membrane->loop_nodes());
        // The membrane's edges, to find each quad's diagonal.
        std::set<std::pair<unsigned int, unsigned int>> edges;
        if (rings.size() > 1)
          for (const auto &element : membrane->elements)
            for (unsigned int q = 0; q < element.size(); ++q)
              for (unsigned int r = q + 1; r < element.size(); ++r)
                edges.emplace(std::min(element[q], element[r]),
                              std::max(element[q], element[r]));
        const auto xy = [&](const unsigned int a) {
          return Point<2>(membrane->position[a][0], membrane->position[a][1]);
        };
        // Each quad's diagonal between rings j and j + 1, found once (not
        // per point): 1 from r_j[k] to r_j+1[k + 1], 2 from r_j[k + 1] to
        // r_j+1[k], 0 none.
        std::vector<std::vector<std::uint8_t>> quad_diagonal(
          rings.size() > 1 ? rings.size() - 1 : 0);
        for (unsigned int j = 0; j + 1 < rings.size(); ++j)
          {
            const auto &r0 = rings[j], &r1 = rings[j + 1];
            quad_diagonal[j].resize(r0.size(), 0);
            for (unsigned int k = 0; k < r0.size(); ++k)
              {
                const unsigned int l = (k + 1) % r0.size();
                if (edges.count(
                      {std::min(r0[k], r1[l]), std::max(r0[k], r1[l])}))
                  quad_diagonal[j][k] = 1;
                else if (edges.count(
                           {std::min(r0[l], r1[k]), std::max(r0[l], r1[k])}))
                  quad_diagonal[j][k] = 2;
              }
          }
        // The section at height z: the points of the rings' edges and of
        // each quad's diagonal at z (into @p section, a buffer reused from
        // point to point).
        const auto section_at = [&](const double           z,
                                    std::vector<Point<2>> &section) {
          section.clear();
          if (rings.size() == 1 || z <= levels.front() || z >= levels.back())
            {
              for (const unsigned int a :
                   rings.size() == 1 || z <= levels.front() ? rings.front()
                                                            : rings.back())
                section.push_back(xy(a));
              return;
            }
          const unsigned int j
            = std::upper_bound(levels.begin(), levels.end(), z) - levels.begin()
              - 1;
          const double s  = (z - levels[j]) / (levels[j + 1] - levels[j]);
          const auto  &r0 = rings[j], &r1 = rings[j + 1];
          const auto   at = [&](const unsigned int a, const unsigned int b) {
            return Point<2>((1 - s) * xy(a) + s * xy(b));
          };
          for (unsigned int k = 0; k < r0.size(); ++k)
            {
              const unsigned int l = (k + 1) % r0.size();
              section.push_back(at(r0[k], r1[k]));
              if (quad_diagonal[j][k] == 1)
                section.push_back(at(r0[k], r1[l]));
              else if (quad_diagonal[j][k] == 2)
                section.push_back(at(r0[l], r1[k]));
            }
        };
        // The rings' bounding box: a point off it (by more than
        // round-off) is outside: its ray crosses the polygon an even number
        // of times or not at all, so inside_polygon() would say so too.
        // Most water points are, and the tests evaluate this at every step.
        std::vector<Point<2>> all;
        for (const auto &ring : rings)
          for (const unsigned int a : ring)
            all.push_back(xy(a));
        BoundingBox<2> box(all);
        const double   diagonal = box.get_boundary_points().first.distance(
          box.get_boundary_points().second);
        box.extend(1e-9 * diagonal);
        // One loop (2D): tested through its bands; in 3D each point's own
        // section, once, by the plain even-odd rule (the same bits).
        std::vector<Point<2>> single, section;
        section_at(0, single);
        const PolygonInside          single_test(single);
        const std::vector<Point<2>> *poly = &single;
        for (unsigned int p = 0; p < particles.size(); ++p)
          {
            const Point<2> x(particles.position[p][0],
                             particles.position[p][1]);
            const bool     in_box = box.point_inside(x, 0.);
            if (rings.size() > 1
                && (in_box || particles.body_id[p] == container))
              {
                section_at(particles.position[p][dim - 1], section);
                poly = &section;
              }
            const bool inside
              = in_box
                && (rings.size() == 1 ? single_test(x)
                                      : inside_polygon(section, x));
            if (particles.body_id[p] == container && !inside)
              {
                ++soil_outside;
                soil_outside_distance
                  = std::max(soil_outside_distance, distance(*poly, x));
              }
            else if (particles.body_id[p] != container && inside)
              {
                ++water_inside;
                water_inside_depth
                  = std::max(water_inside_depth, distance(*poly, x));
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
