#include <deal.II/base/exceptions.h>

#include <fsgmpm/particles/body_shape.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace fsgmpm
{
  template <int dim>
  BoxShape<dim>::BoxShape(const Point<dim> &lower, const Point<dim> &upper)
    : lower(lower)
    , upper(upper)
  {
    for (unsigned int d = 0; d < dim; ++d)
      AssertThrow(upper[d] > lower[d],
                  ExcMessage("Box upper corner must exceed the lower corner "
                             "in every direction."));
  }

  template <int dim>
  bool
  BoxShape<dim>::inside(const Point<dim> &x) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (x[d] < lower[d] || x[d] > upper[d])
        return false;
    return true;
  }

  template <int dim>
  std::vector<Point<dim>>
  BoxShape<dim>::outline_points() const
  {
    std::vector<Point<dim>> corners;
    for (unsigned int i = 0; i < (1u << dim); ++i)
      {
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = (i & (1u << d)) ? upper[d] : lower[d];
        corners.push_back(p);
      }
    return corners;
  }

  template <int dim>
  std::string
  BoxShape<dim>::description() const
  {
    std::ostringstream s;
    s << "box [" << lower << "] - [" << upper << "]";
    return s.str();
  }



  template <int dim>
  EllipseShape<dim>::EllipseShape(const Point<dim>     &center,
                                  const Tensor<1, dim> &semi_axes)
    : center(center)
    , semi_axes(semi_axes)
  {
    for (unsigned int d = 0; d < dim; ++d)
      AssertThrow(semi_axes[d] > 0,
                  ExcMessage("Ellipse semi-axes must be positive."));
  }

  template <int dim>
  bool
  EllipseShape<dim>::inside(const Point<dim> &x) const
  {
    double r = 0;
    for (unsigned int d = 0; d < dim; ++d)
      r += (x[d] - center[d]) * (x[d] - center[d])
           / (semi_axes[d] * semi_axes[d]);
    return r <= 1.;
  }

  template <int dim>
  std::vector<Point<dim>>
  EllipseShape<dim>::outline_points() const
  {
    std::vector<Point<dim>> pts;
    for (unsigned int d = 0; d < dim; ++d)
      for (const double s : {-1., 1.})
        {
          Point<dim> p = center;
          p[d] += s * semi_axes[d];
          pts.push_back(p);
        }
    return pts;
  }

  template <int dim>
  std::string
  EllipseShape<dim>::description() const
  {
    std::ostringstream s;
    s << "ellipse centre (" << center << ") semi-axes (" << semi_axes << ")";
    return s.str();
  }



  namespace
  {
    double
    cross(const Point<2> &o, const Point<2> &a, const Point<2> &b)
    {
      return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    }

    bool
    segments_intersect(const Point<2> &a,
                       const Point<2> &b,
                       const Point<2> &c,
                       const Point<2> &d)
    {
      const double d1 = cross(c, d, a), d2 = cross(c, d, b);
      const double d3 = cross(a, b, c), d4 = cross(a, b, d);
      return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0))
             && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
    }
  } // namespace

  PolygonShape::PolygonShape(const std::vector<Point<2>> &v)
    : inside_test(v)
  {
    const std::vector<Point<2>> &vertices = v;
    const unsigned int           n        = vertices.size();
    AssertThrow(n >= 3, ExcMessage("A polygon needs at least three vertices."));
    double size = 0, twice_area = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        const Point<2> &a = vertices[i], &b = vertices[(i + 1) % n];
        AssertThrow(a.distance(b) > 0,
                    ExcMessage("Vertices " + std::to_string(i) + " and "
                               + std::to_string((i + 1) % n)
                               + " of the polygon coincide; give each "
                                 "vertex once."));
        size = std::max(size, a.distance(vertices[0]));
        twice_area += a[0] * b[1] - b[0] * a[1];
      }
    // Two edges can cross only where their y ranges overlap: a sweep over
    // y tests each edge against the edges that start (in y) before it ends,
    // not all n^2 / 2 pairs (10 million for a membrane of 4 600 vertices,
    // 0.3 s). The first crossing pair in (i, j) order is reported, as the
    // test of all pairs did.
    const auto y_range = [&](const unsigned int i) {
      const double y0 = vertices[i][1], y1 = vertices[(i + 1) % n][1];
      return std::make_pair(std::min(y0, y1), std::max(y0, y1));
    };
    std::vector<unsigned int> by_low_y(n);
    std::iota(by_low_y.begin(), by_low_y.end(), 0u);
    std::sort(by_low_y.begin(),
              by_low_y.end(),
              [&](const unsigned int a, const unsigned int b) {
                return y_range(a).first < y_range(b).first;
              });
    std::pair<unsigned int, unsigned int> crossing(n, n);
    for (unsigned int a = 0; a < n; ++a)
      {
        const double top = y_range(by_low_y[a]).second;
        for (unsigned int b = a + 1; b < n && y_range(by_low_y[b]).first <= top;
             ++b)
          {
            const unsigned int i = std::min(by_low_y[a], by_low_y[b]);
            const unsigned int j = std::max(by_low_y[a], by_low_y[b]);
            // Adjacent edges share a vertex and are not tested.
            if (j == i + 1 || (i == 0 && j == n - 1))
              continue;
            if (segments_intersect(vertices[i],
                                   vertices[(i + 1) % n],
                                   vertices[j],
                                   vertices[(j + 1) % n]))
              crossing = std::min(crossing, std::make_pair(i, j));
          }
      }
    AssertThrow(crossing.first == n,
                ExcMessage("The polygon intersects itself (edges "
                           + std::to_string(crossing.first) + " and "
                           + std::to_string(crossing.second) + ")."));
    AssertThrow(std::abs(twice_area) > 1e-12 * size * size,
                ExcMessage("The polygon encloses no area (its vertices lie on "
                           "one line)."));
  }

  bool
  inside_polygon(const std::vector<Point<2>> &vertices, const Point<2> &x)
  {
    bool               in = false;
    const unsigned int n  = vertices.size();
    for (unsigned int i = 0, j = n - 1; i < n; j = i++)
      {
        if (edge_crosses_ray(vertices[i], vertices[j], x))
          in = !in;
      }
    return in;
  }

  bool
  PolygonShape::inside(const Point<2> &x) const
  {
    return inside_test(x);
  }

  std::vector<Point<2>>
  PolygonShape::outline_points() const
  {
    return inside_test.get_vertices();
  }

  std::string
  PolygonShape::description() const
  {
    return "polygon with " + std::to_string(inside_test.get_vertices().size())
           + " vertices";
  }

  template <int dim>
  CrossSectionShape<dim>::CrossSectionShape(const std::vector<Point<2>> &v,
                                            const double                 z0,
                                            const double                 z1)
    : polygon(v)
    , z0(z0)
    , z1(z1)
  {}

  template <int dim>
  bool
  CrossSectionShape<dim>::inside(const Point<dim> &x) const
  {
    if (dim == 3 && (x[dim - 1] < z0 || x[dim - 1] > z1))
      return false;
    return polygon.inside(Point<2>(x[0], x[1]));
  }

  template <int dim>
  std::vector<Point<dim>>
  CrossSectionShape<dim>::outline_points() const
  {
    std::vector<Point<dim>> points;
    for (const auto &p : polygon.outline_points())
      {
        Point<dim> q;
        q[0] = p[0];
        q[1] = p[1];
        if (dim == 3)
          q[dim - 1] = 0.5 * (z0 + z1);
        points.push_back(q);
      }
    return points;
  }

  template <int dim>
  std::string
  CrossSectionShape<dim>::description() const
  {
    return "the inside of the membrane, " + polygon.description()
           + ", from Membrane/Circumference, Enclosed area and Lowest point "
             "(Shape = ellipse) or Membrane/Polygon vertices";
  }

  template class CrossSectionShape<2>;
  template class CrossSectionShape<3>;
  template class BoxShape<2>;
  template class BoxShape<3>;
  template class EllipseShape<2>;
  template class EllipseShape<3>;
} // namespace fsgmpm
