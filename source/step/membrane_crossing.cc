#include <deal.II/base/bounding_box.h>

#include <fsgmpm/base/parallel_reductions.h>
#include <fsgmpm/step/membrane_crossing.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fsgmpm
{
  namespace
  {
    /// The element's normal (not normalised) and its signed distance
    /// function's sign carrier: cross(e1, w) in 2D, (e1 x e2) . w in 3D.
    template <int dim>
    Tensor<1, dim>
    element_normal(const std::array<Point<dim>, dim> &x)
    {
      Tensor<1, dim> n;
      if constexpr (dim == 2)
        {
          const Tensor<1, 2> e = x[1] - x[0];
          n[0]                 = -e[1];
          n[1]                 = e[0];
        }
      else
        n = cross_product_3d(x[1] - x[0], x[2] - x[0]);
      return n;
    }

    /// The weights of the point of the element nearest to the projection
    /// of @p p on its line or plane (barycentric, unclamped).
    template <int dim>
    std::array<double, dim>
    element_weights(const std::array<Point<dim>, dim> &x, const Point<dim> &p)
    {
      std::array<double, dim> w;
      if constexpr (dim == 2)
        {
          const Tensor<1, 2> e = x[1] - x[0];
          const double s = ((p - x[0]) * e) / std::max(e.norm_square(), 1e-300);
          w              = {{1 - s, s}};
        }
      else
        {
          const Tensor<1, 3> e1 = x[1] - x[0], e2 = x[2] - x[0], r = p - x[0];
          const double       d00 = e1 * e1, d01 = e1 * e2, d11 = e2 * e2;
          const double       d20 = r * e1, d21 = r * e2;
          const double       denom = std::max(d00 * d11 - d01 * d01, 1e-300);
          const double       v     = (d11 * d20 - d01 * d21) / denom;
          const double       u     = (d00 * d21 - d01 * d20) / denom;
          w                        = {{1 - v - u, v, u}};
        }
      return w;
    }
  } // namespace



  template <int dim>
  MembraneCrossing<dim>::MembraneCrossing(const Membrane<dim> &membrane)
    : membrane(membrane)
  {}



  template <int dim>
  void
  MembraneCrossing<dim>::remember_start(const NodalFields<dim>   &nodes,
                                        const ParticleStore<dim> &particles,
                                        const double              dt)
  {
    start_node = membrane.position;
    followed.clear();
    start_point.clear();
    if (start_node.empty())
      return;
    // Points and membrane nodes move with velocities interpolated from the
    // grid's, so neither moves farther than dt max|v_i|.
    double v_max = 0;
    for (const unsigned int i : nodes.active_nodes)
      v_max = std::max(v_max, nodes.velocity[i].norm());
    BoundingBox<dim> box(start_node);
    const double     reach = 2 * dt * v_max;
    const double     size  = box.get_boundary_points().first.distance(
      box.get_boundary_points().second);
    box.extend(reach + 1e-9 * size);
    for (unsigned int p = 0; p < particles.size(); ++p)
      if (box.point_inside(particles.position[p]))
        {
          followed.push_back(p);
          start_point.push_back(particles.position[p]);
        }
  }



  template <int dim>
  typename MembraneCrossing<dim>::Outcome
  MembraneCrossing<dim>::keep_points_on_their_side(
    const double        dt,
    ParticleStore<dim> &particles)
  {
    Outcome     outcome;
    const auto &elements = membrane.elements;
    if (followed.empty() || elements.empty())
      return outcome;
    AssertThrow(start_node.size() == membrane.position.size(),
                ExcMessage("The membrane's nodes changed between "
                           "MembraneCrossing::remember_start() and "
                           "keep_points_on_their_side()."));
    const auto &end_node = membrane.position;

    // Bins of the elements' swept boxes, a little larger than the largest
    // element's, so that each element lies in at most 2^dim bins.
    std::vector<BoundingBox<dim>> swept(elements.size());
    Point<dim>                    low, high;
    for (unsigned int d = 0; d < dim; ++d)
      {
        low[d]  = std::numeric_limits<double>::max();
        high[d] = -low[d];
      }
    double bin = 0;
    for (unsigned int e = 0; e < elements.size(); ++e)
      {
        // The box of the element's nodes at the start and the end (no
        // allocation per element and step).
        const unsigned int first = elements[e][0];
        swept[e] = BoundingBox<dim>({start_node[first], start_node[first]});
        for (const unsigned int a : elements[e])
          {
            swept[e].merge_with(
              BoundingBox<dim>({start_node[a], start_node[a]}));
            swept[e].merge_with(BoundingBox<dim>({end_node[a], end_node[a]}));
          }
        for (unsigned int d = 0; d < dim; ++d)
          {
            low[d]  = std::min(low[d], swept[e].lower_bound(d));
            high[d] = std::max(high[d], swept[e].upper_bound(d));
            bin     = std::max(bin, swept[e].side_length(d));
          }
      }
    std::array<unsigned int, dim> n_bins;
    double                        n_total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_total *= (high[d] - low[d]) / std::max(bin, 1e-300) + 1;
    // At most about 2^20 bins (a thin membrane in a large box).
    if (n_total > double(1 << 20))
      bin *= std::pow(n_total / double(1 << 20), 1. / dim);
    bin                = std::max(bin * 1.01, 1e-12);
    unsigned int total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        n_bins[d] = static_cast<unsigned int>((high[d] - low[d]) / bin) + 1;
        total *= n_bins[d];
      }
    const auto bin_range = [&](const Point<dim> &lo, const Point<dim> &hi) {
      std::array<std::pair<unsigned int, unsigned int>, dim> r;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double a
            = std::clamp((lo[d] - low[d]) / bin, 0., n_bins[d] - 1.);
          const double b
            = std::clamp((hi[d] - low[d]) / bin, 0., n_bins[d] - 1.);
          r[d] = {static_cast<unsigned int>(a), static_cast<unsigned int>(b)};
        }
      return r;
    };
    const auto for_each_bin = [&](const auto &r, const auto &f) {
      if constexpr (dim == 2)
        {
          for (unsigned int j = r[1].first; j <= r[1].second; ++j)
            for (unsigned int i = r[0].first; i <= r[0].second; ++i)
              f(i + n_bins[0] * j);
        }
      else
        {
          for (unsigned int k = r[2].first; k <= r[2].second; ++k)
            for (unsigned int j = r[1].first; j <= r[1].second; ++j)
              for (unsigned int i = r[0].first; i <= r[0].second; ++i)
                f(i + n_bins[0] * (j + n_bins[1] * k));
        }
    };
    // Compressed rows: the elements of each bin.
    std::vector<unsigned int> offset(total + 1, 0);
    for (unsigned int e = 0; e < elements.size(); ++e)
      for_each_bin(bin_range(swept[e].get_boundary_points().first,
                             swept[e].get_boundary_points().second),
                   [&](const unsigned int b) { ++offset[b + 1]; });
    for (unsigned int b = 0; b < total; ++b)
      offset[b + 1] += offset[b];
    std::vector<unsigned int> in_bin(offset.back());
    {
      std::vector<unsigned int> fill(offset.begin(), offset.end() - 1);
      for (unsigned int e = 0; e < elements.size(); ++e)
        for_each_bin(bin_range(swept[e].get_boundary_points().first,
                               swept[e].get_boundary_points().second),
                     [&](const unsigned int b) { in_bin[fill[b]++] = e; });
    }

    const auto nodes_at = [&](const unsigned int e, const double t) {
      std::array<Point<dim>, dim> x;
      for (unsigned int k = 0; k < dim; ++k)
        {
          const unsigned int a = elements[e][k];
          x[k] = start_node[a] + t * (end_node[a] - start_node[a]);
        }
      return x;
    };
    // Does the path p0 -> p1 cross element e? Then puts p1 back on p0's
    // side and returns the element's unit normal toward that side and the
    // element's velocity there.
    constexpr double tolerance = 1e-6;
    const auto       cross     = [&](const unsigned int e,
                           const Point<dim>  &p0,
                           Point<dim>        &p1,
                           Tensor<1, dim>    &normal,
                           Tensor<1, dim>    &element_velocity) {
      const auto distance = [&](const double t) {
        const auto x = nodes_at(e, t);
        return element_normal<dim>(x) * (p0 + t * (p1 - p0) - x[0]);
      };
      const double d0 = distance(0), d1 = distance(1);
      if (d0 == 0 || (d0 > 0) == (d1 > 0))
        return false;
      // The first time the point is on the element's line or plane.
      double a = 0, b = 1;
      for (unsigned int it = 0; it < 50; ++it)
        {
          const double m = 0.5 * (a + b);
          if ((distance(m) > 0) == (d0 > 0))
            a = m;
          else
            b = m;
        }
      const double t = 0.5 * (a + b);
      const auto   w = element_weights<dim>(nodes_at(e, t), p0 + t * (p1 - p0));
      for (const double wk : w)
        if (wk < -tolerance)
          return false;
      // Back on its side at the end of the step, a hundredth of the
      // element's size off it.
      const auto           x    = nodes_at(e, 1);
      const Tensor<1, dim> n    = element_normal<dim>(x);
      const double         norm = n.norm();
      if (!(norm > 0))
        return false;
      const double size = dim == 2 ? norm : std::sqrt(norm);
      const double side = d0 > 0 ? 1. : -1.;
      normal            = side * n / norm;
      p1 += (0.01 * size - normal * (p1 - x[0])) * normal;
      // The element's velocity at the point nearest p1.
      auto   w1  = element_weights<dim>(x, p1);
      double sum = 0;
      for (double &wk : w1)
        {
          wk = std::max(wk, 0.);
          sum += wk;
        }
      element_velocity = Tensor<1, dim>();
      for (unsigned int k = 0; k < dim; ++k)
        {
          const unsigned int node = elements[e][k];
          element_velocity
            += (w1[k] / sum) * (end_node[node] - start_node[node]) / dt;
        }
      return true;
    };

    std::vector<double> removed(followed.size(), 0.);
    std::vector<char>   corrected(followed.size(), 0);
    Reductions::parallel_range(
      followed.size(),
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int f = begin; f < end; ++f)
          {
            const unsigned int p  = followed[f];
            const Point<dim>  &p0 = start_point[f];
            Point<dim>        &p1 = particles.position[p];
            // A corrected point may now cross a neighbouring element (at a
            // corner): look again, a few times.
            for (unsigned int pass = 0; pass < 4; ++pass)
              {
                Point<dim> lo = p0, hi = p0;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    lo[d] = std::min(lo[d], p1[d]);
                    hi[d] = std::max(hi[d], p1[d]);
                  }
                bool outside = false;
                for (unsigned int d = 0; d < dim; ++d)
                  outside = outside || hi[d] < low[d] || lo[d] > high[d];
                if (outside)
                  break;
                bool again = false;
                for_each_bin(bin_range(lo, hi), [&](const unsigned int b) {
                  for (unsigned int k = offset[b]; k < offset[b + 1] && !again;
                       ++k)
                    {
                      Tensor<1, dim> normal, element_velocity;
                      if (!cross(in_bin[k], p0, p1, normal, element_velocity))
                        continue;
                      again        = true;
                      corrected[f] = 1;
                      // The normal velocity that carried it across, relative
                      // to the element, is taken.
                      Tensor<1, dim> &v = particles.velocity[p];
                      const double    u = (v - element_velocity) * normal;
                      if (u < 0)
                        {
                          const double before = v.norm_square();
                          v -= u * normal;
                          removed[f] += 0.5 * particles.mass[p]
                                        * (before - v.norm_square());
                        }
                    }
                });
                if (!again)
                  break;
              }
          }
      },
      64);
    for (unsigned int f = 0; f < followed.size(); ++f)
      {
        outcome.corrected += corrected[f];
        outcome.kinetic_energy_removed += removed[f];
      }
    return outcome;
  }



  template class MembraneCrossing<2>;
  template class MembraneCrossing<3>;
} // namespace fsgmpm
