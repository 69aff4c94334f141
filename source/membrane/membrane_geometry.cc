#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>

#include <fsgmpm/base/parameter_parsing.h>
#include <fsgmpm/base/real_interval.h>
#include <fsgmpm/membrane/gmsh_surface.h>
#include <fsgmpm/membrane/membrane_geometry.h>
#include <fsgmpm/particles/body_shape.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace fsgmpm
{
  namespace MembraneGeometry
  {
    double
    ellipse_perimeter(const double a, const double b)
    {
      // 4 a E(e): Gauss-Legendre on [0, pi/2] in 64 panels of 8 points; the
      // integrand sqrt(1 - e^2 sin^2) is smooth unless b << a, where the
      // panels still resolve it to well below 1e-12.
      static const double x8[4] = {0.1834346424956498,
                                   0.5255324099163290,
                                   0.7966664774136267,
                                   0.9602898564975363};
      static const double w8[4] = {0.3626837833783620,
                                   0.3137066458778873,
                                   0.2223810344533745,
                                   0.1012285362903763};
      const double        e2    = 1. - (b * b) / (a * a);
      const unsigned int  n     = 64;
      const double        h     = 0.5 * M_PI / n;
      double              s     = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double c = (i + 0.5) * h;
          for (unsigned int k = 0; k < 4; ++k)
            for (const double sign : {-1., 1.})
              {
                const double t  = c + sign * 0.5 * h * x8[k];
                const double st = std::sin(t);
                s += 0.5 * h * w8[k] * std::sqrt(1. - e2 * st * st);
              }
        }
      return 4. * a * s;
    }



    std::pair<double, double>
    ellipse_axes(const double L, const double A)
    {
      AssertThrow(L > 0 && A >= 1e-3 * L * L / (4. * M_PI)
                    && A < L * L / (4. * M_PI),
                  ExcMessage("An ellipse of circumference " + std::to_string(L)
                             + " m cannot enclose " + std::to_string(A)
                             + " m^2: the area must lie in [1e-3, 1) L^2/(4 "
                               "pi) = ["
                             + std::to_string(1e-3 * L * L / (4. * M_PI)) + ", "
                             + std::to_string(L * L / (4. * M_PI))
                             + ") (a circle holds the most; a smaller area "
                               "gives an ellipse flatter than b/a = "
                               "4e-4)."));
      // Bisection on the axis ratio r = b/a in (0, 1]: with a from the
      // area (pi a b = A) the perimeter grows as r falls.
      double lo = 1e-12, hi = 1.;
      for (unsigned int it = 0; it < 200; ++it)
        {
          const double r = 0.5 * (lo + hi);
          const double a = std::sqrt(A / (M_PI * r));
          if (ellipse_perimeter(a, r * a) > L)
            lo = r;
          else
            hi = r;
        }
      const double r = 0.5 * (lo + hi);
      const double a = std::sqrt(A / (M_PI * r));
      return {a, r * a};
    }



    std::vector<Point<2>>
    ellipse_points(const Point<2>    &center,
                   const double       a,
                   const double       b,
                   const unsigned int n)
    {
      // Tabulate the arc length over the parameter, then invert it.
      const unsigned int  m = 20000 * std::max(1u, n / 100);
      std::vector<double> s(m + 1, 0.);
      auto                at = [&](const double t) {
        return Point<2>(center[0] + a * std::sin(t),
                        center[1] - b * std::cos(t));
      };
      for (unsigned int i = 1; i <= m; ++i)
        s[i] = s[i - 1]
               + at(2 * M_PI * i / m).distance(at(2 * M_PI * (i - 1) / m));
      std::vector<Point<2>> p;
      unsigned int          j = 0;
      for (unsigned int k = 0; k < n; ++k)
        {
          const double target = s[m] * k / n;
          while (s[j + 1] < target)
            ++j;
          const double f = (target - s[j]) / (s[j + 1] - s[j]);
          p.push_back(at(2 * M_PI * (j + f) / m));
        }
      return p;
    }



    double
    signed_area(const std::vector<Point<2>> &outline)
    {
      double area = 0;
      for (unsigned int i = 0; i < outline.size(); ++i)
        {
          const auto &p = outline[i], &q = outline[(i + 1) % outline.size()];
          area += 0.5 * (p[0] * q[1] - q[0] * p[1]);
        }
      return area;
    }



    template <int dim>
    Point<dim>
    point_on_arc(const Point<dim> &a,
                 const Point<dim> &b,
                 const Point<dim> &c,
                 const Point<dim> &from,
                 const Point<dim> &to,
                 const double      t)
    {
      const Tensor<1, dim> ab = b - a, ac = c - a;
      const double         d = 2 * (ab[0] * ac[1] - ab[1] * ac[0]);
      if (std::abs(d) <= 1e-12 * (ab.norm_square() + ac.norm_square()))
        return Point<dim>(from + t * (to - from));
      Point<dim> o;
      o[0] = a[0] + (ac[1] * ab.norm_square() - ab[1] * ac.norm_square()) / d;
      o[1] = a[1] + (ab[0] * ac.norm_square() - ac[0] * ab.norm_square()) / d;
      const double r  = std::hypot(from[0] - o[0], from[1] - o[1]);
      const double t1 = std::atan2(from[1] - o[1], from[0] - o[0]);
      double       dt = std::atan2(to[1] - o[1], to[0] - o[0]) - t1;
      dt              = std::remainder(dt, 2 * M_PI); // the short arc
      Point<dim> x    = from;
      x[0]            = o[0] + r * std::cos(t1 + t * dt);
      x[1]            = o[1] + r * std::sin(t1 + t * dt);
      return x;
    }

#define FSGMPM_INSTANTIATE(dim)                             \
  template Point<dim> point_on_arc<dim>(const Point<dim> &, \
                                        const Point<dim> &, \
                                        const Point<dim> &, \
                                        const Point<dim> &, \
                                        const Point<dim> &, \
                                        const double);
    FSGMPM_INSTANTIATE(2)
    FSGMPM_INSTANTIATE(3)
#undef FSGMPM_INSTANTIATE
  } // namespace MembraneGeometry



  template <int dim>
  void
  MembraneDescription<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Membrane");
    {
      prm.declare_entry("Enabled",
                        "false",
                        Patterns::Bool(),
                        "Add a geomembrane coupled to the grid (FEM-MPM, "
                        "shared grid nodes).");
      prm.declare_entry("Shape",
                        "ellipse",
                        Patterns::Selection("ellipse|polygon|gmsh"),
                        "ellipse: closed ellipse of the given circumference "
                        "and enclosed area; polygon: closed polygon (2D); "
                        "gmsh: a surface mesh of triangles (3D). In 3D the "
                        "ellipse and polygon are extruded along z over the "
                        "grid's thickness.");
      prm.declare_entry("Circumference",
                        "9.2",
                        Patterns::Double(0, 1e6),
                        "Shape = ellipse: rest length of the membrane (m, "
                        "at most 1e6).");
      prm.declare_entry("Enclosed area",
                        "5.56",
                        Patterns::Double(0),
                        "Shape = ellipse: area inside the ellipse (m^2), "
                        "from 1e-3 to below 1 times Circumference^2/(4 pi).");
      prm.declare_entry("Lowest point",
                        "3, 0",
                        Patterns::List(Patterns::Double(), 2, 2),
                        "Shape = ellipse: x, y of the ellipse's lowest point "
                        "(m).");
      prm.declare_entry("Polygon vertices",
                        "",
                        Patterns::Anything(),
                        "Shape = polygon: 'x0, y0; x1, y1; ...' (m), a simple "
                        "closed polygon, counter-clockwise.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::Anything(),
                        "Shape = gmsh: ASCII Gmsh file (format 2.2 or 4.1) "
                        "of the membrane surface, 3-node or 6-node "
                        "triangles; at Element degree = 2 the 6-node "
                        "triangles' edge nodes are the middle nodes (the "
                        "curved surface Gmsh meshed), else the edge "
                        "midpoints (relative to the working directory).");
      prm.declare_entry("Element size",
                        "0",
                        Patterns::Double(0),
                        "Initial element length (m); 0: 0.4 grid cells.");
      prm.declare_entry("Split length",
                        "0.5",
                        Patterns::Double(0.1, 1),
                        "A cable longer than this many grid cells is split "
                        "in two (fluid leaks between nodes farther apart than "
                        "about one cell); in [0.1, 1].");
      prm.declare_entry("Tangential coupling",
                        "no-slip",
                        Patterns::Selection("no-slip|slip"),
                        "no-slip: the membrane nodes move with the grid "
                        "velocity (shared nodes, paper); slip (2D closed "
                        "membranes, and in 3D the extruded ellipse or "
                        "polygon, ring by ring): in addition the nodes are "
                        "moved along the membrane each step so that the "
                        "tension is "
                        "uniform, i.e. frictionless contact with the fill "
                        "(a fluid at rest carries no shear).");
      prm.declare_entry("Impermeable to points",
                        "true",
                        Patterns::Bool(),
                        "true: no material point passes through the "
                        "membrane. The grid coupling alone lets a point near "
                        "the membrane cross an element where the grid "
                        "velocity in its cell differs from the membrane's "
                        "(cells holding points of both sides); each point's "
                        "path over a step is tested against the elements "
                        "and a crossing point is put back on its side, its "
                        "normal velocity relative to the membrane removed "
                        "(booked as numerical dissipation). false: the "
                        "coupling through the grid only (the paper's).");
      prm.declare_entry("Ground level",
                        "none",
                        Patterns::Anything(),
                        "y of a rigid frictionless ground that acts on the "
                        "membrane nodes directly (normal penalty, included in "
                        "the time step), so the membrane rests on it instead "
                        "of one cell above a grid wall; the grid must extend "
                        "below it. none: no ground.");
      prm.declare_entry("Ground stiffness",
                        "1e7",
                        RealInterval::above(0, 1e15),
                        "Penalty stiffness of the ground per metre of a "
                        "membrane node's width (N/m^2, at most 1e15; the "
                        "width is 1 m of depth in 2D and the square root of "
                        "the node's share of the membrane's area in 3D): a "
                        "node below the ground gets k times its width times "
                        "its depth upwards. The penetration is about the "
                        "bottom pressure times the element size / k.");
      prm.declare_entry("Axial stiffness",
                        "5e7",
                        RealInterval::above(0, 1e12),
                        "EA = E * thickness (N/m, at most 1e12).");
      prm.declare_entry("Poisson ratio",
                        "0.3",
                        RealInterval(-1, 1, true, true),
                        "In-plane Poisson ratio (3D), in (-1, 1).");
      prm.declare_entry("Initial strain",
                        "0",
                        RealInterval(-0.5, 1, true, true),
                        "Pre-strain eps0: the rest length is the initial "
                        "length / (1 + eps0); > 0 starts in tension.");
      prm.declare_entry("Areal mass",
                        "0.5",
                        RealInterval::above(0, 1e4),
                        "Mass per membrane area (kg/m^2, > 0, at most 1e4).");
      prm.declare_entry("Element degree",
                        "1",
                        Patterns::Integer(1, 2),
                        "Polynomial degree of the membrane's finite elements "
                        "(FE_SimplexP on the membrane's cells): 1 (straight "
                        "cables and flat triangles) or 2 (quadratic: one more "
                        "node on every cell edge, so twice the nodes along "
                        "the membrane for the same Element size).");
    }
    prm.leave_subsection();
  }



  template <int dim>
  MembraneDescription<dim>::MembraneDescription(ParameterHandler &prm)
  {
    prm.enter_subsection("Membrane");
    enabled       = prm.get_bool("Enabled");
    shape         = prm.get("Shape");
    circumference = prm.get_double("Circumference");
    area          = prm.get_double("Enclosed area");
    const auto lp
      = parse_vector<2>(prm.get("Lowest point"), "Membrane/Lowest point");
    bottom = Point<2>(lp);
    AssertThrow(std::abs(bottom[0]) <= 1e9 && std::abs(bottom[1]) <= 1e9,
                ExcMessage("Membrane/Lowest point must lie within +-1e9 m; "
                           "got <"
                           + prm.get("Lowest point") + ">."));
    mesh_file                  = prm.get("Mesh file");
    element_size               = prm.get_double("Element size");
    split_fraction             = prm.get_double("Split length");
    properties.axial_stiffness = prm.get_double("Axial stiffness");
    properties.poisson_ratio   = prm.get_double("Poisson ratio");
    properties.areal_mass      = prm.get_double("Areal mass");
    properties.initial_strain  = prm.get_double("Initial strain");
    properties.element_degree  = prm.get_integer("Element degree");
    tangential_slip            = (prm.get("Tangential coupling") == "slip");
    impermeable_to_points      = prm.get_bool("Impermeable to points");
    {
      const std::string g = Utilities::trim(prm.get("Ground level"));
      if (g != "none")
        {
          try
            {
              ground_level = Utilities::string_to_double(g);
            }
          catch (...)
            {
              AssertThrow(false,
                          ExcMessage("Membrane/Ground level must be a number "
                                     "or none; got <"
                                     + g + ">."));
            }
          AssertThrow(std::abs(ground_level) <= 1e9,
                      ExcMessage("Membrane/Ground level must be a finite "
                                 "number within +-1e9 m or none; got <"
                                 + g + ">."));
          ground_stiffness = prm.get_double("Ground stiffness");
          AssertThrow(ground_stiffness > 0,
                      ExcMessage("Membrane/Ground stiffness must be "
                                 "positive."));
        }
    }
    if (enabled && shape == "polygon")
      {
        polygon = parse_polygon(prm.get("Polygon vertices"),
                                "Membrane/Polygon vertices");
        for (const auto &v : polygon)
          AssertThrow(std::abs(v[0]) <= 1e9 && std::abs(v[1]) <= 1e9,
                      ExcMessage("Membrane/Polygon vertices must lie within "
                                 "+-1e9 m; got <"
                                 + prm.get("Polygon vertices") + ">."));
        try
          {
            PolygonShape check(polygon);
          }
        catch (ExceptionBase &e)
          {
            std::ostringstream info;
            e.print_info(info);
            AssertThrow(false,
                        ExcMessage("Membrane/Polygon vertices: "
                                   + Utilities::trim(info.str())));
          }
      }
    prm.leave_subsection();
    if (!enabled)
      return;
    AssertThrow(split_fraction >= 0.1 && split_fraction <= 1,
                ExcMessage("Membrane/Split length must lie in [0.1, 1] grid "
                           "cells; got "
                           + std::to_string(split_fraction) + "."));
    AssertThrow(properties.axial_stiffness > 0,
                ExcMessage("Membrane/Axial stiffness must be positive."));
    AssertThrow(properties.areal_mass > 0,
                ExcMessage("Membrane/Areal mass must be positive."));
    AssertThrow(!tangential_slip || dim == 2 || shape != "gmsh",
                ExcMessage("Membrane/Tangential coupling = slip needs a 2D "
                           "membrane or, in 3D, an extruded one (Shape = "
                           "ellipse or polygon); a Gmsh surface has no "
                           "rings to slip along."));
    AssertThrow(shape != "gmsh" || dim == 3,
                ExcMessage("Membrane/Shape = gmsh needs a 3D scene (a 2D "
                           "membrane is an ellipse or a polygon)."));
    AssertThrow(shape != "gmsh" || !mesh_file.empty(),
                ExcMessage("Membrane/Mesh file must be given when "
                           "Membrane/Shape = gmsh."));
    if (shape == "ellipse")
      try
        {
          MembraneGeometry::ellipse_axes(circumference, area);
        }
      catch (ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          AssertThrow(false,
                      ExcMessage("Membrane/Circumference and Enclosed area: "
                                 + Utilities::trim(info.str())));
        }
  }



  template <int dim>
  std::vector<Point<2>>
  MembraneDescription<dim>::outline(const double cell_size,
                                    const double size_factor) const
  {
    const double h
      = size_factor * ((element_size > 0) ? element_size : 0.4 * cell_size);
    {
      double length = circumference;
      if (shape != "ellipse")
        {
          length = 0;
          for (unsigned int i = 0; i < polygon.size(); ++i)
            length += polygon[i].distance(polygon[(i + 1) % polygon.size()]);
        }
      AssertThrow(length / h <= 1e6,
                  ExcMessage("The membrane would have more than 1e6 elements "
                             "of "
                             + std::to_string(h)
                             + " m; increase Membrane/Element size or shorten "
                               "the membrane (Membrane/Circumference or "
                               "Polygon vertices)."));
    }
    // The closed outline in x-y, counter-clockwise, with elements of at
    // most h.
    std::vector<Point<2>> outline;
    if (shape == "ellipse")
      {
        const auto [a, b] = MembraneGeometry::ellipse_axes(circumference, area);
        const unsigned int n
          = std::max(8u, (unsigned int)std::ceil(circumference / h));
        outline = MembraneGeometry::ellipse_points(
          Point<2>(bottom[0], bottom[1] + b), a, b, n);
      }
    else
      for (unsigned int i = 0; i < polygon.size(); ++i)
        {
          const Point<2> &p = polygon[i],
                         &q = polygon[(i + 1) % polygon.size()];
          const unsigned int n
            = std::max(1u, (unsigned int)std::ceil(p.distance(q) / h));
          for (unsigned int k = 0; k < n; ++k)
            outline.push_back(p + (double(k) / n) * (q - p));
        }

    // Counter-clockwise, so that the enclosed area is positive.
    if (MembraneGeometry::signed_area(outline) < 0)
      std::reverse(outline.begin(), outline.end());
    return outline;
  }



  template <int dim>
  void
  MembraneDescription<dim>::make_mesh(
    const double                     cell_size,
    const std::pair<double, double> &z_range,
    Triangulation<dim - 1, dim>     &mesh,
    std::map<std::pair<unsigned int, unsigned int>, Point<dim>>
      *edge_middle_points) const
  {
    const double h = (element_size > 0) ? element_size : 0.4 * cell_size;

    if constexpr (dim == 3)
      if (shape == "gmsh")
        {
          // Our own reader: deal.II 9.4's GridIn reads first-order cells
          // only, and a curved membrane needs its 6-node triangles.
          EdgeMiddlePoints middle_points;
          read_gmsh_surface(mesh_file,
                            "Membrane/Mesh file",
                            mesh,
                            middle_points);
          if (edge_middle_points)
            *edge_middle_points = middle_points;
          return;
        }

    // In 3D the quads of the extrusion are split along a diagonal: both
    // sides at most h / sqrt(2) keep the diagonal at most h.
    const double                factor  = (dim == 3) ? 1. / std::sqrt(2.) : 1.;
    const std::vector<Point<2>> outline = this->outline(cell_size, factor);
    const unsigned int          n       = outline.size();
    if constexpr (dim == 2)
      {
        std::vector<Point<2>>    vertices = outline;
        std::vector<CellData<1>> cells(n);
        for (unsigned int i = 0; i < n; ++i)
          cells[i].vertices = {i, (i + 1) % n};
        mesh.create_triangulation(vertices, cells, SubCellData());
      }
    else
      {
        // Rings of the outline along z, each quad split into two triangles
        // with outward normals.
        const unsigned int nz
          = std::max(1u,
                     (unsigned int)std::ceil((z_range.second - z_range.first)
                                             / (factor * h)));
        std::vector<Point<3>> vertices;
        for (unsigned int k = 0; k <= nz; ++k)
          for (const auto &p : outline)
            vertices.emplace_back(p[0],
                                  p[1],
                                  z_range.first
                                    + (z_range.second - z_range.first) * k
                                        / nz);
        std::vector<CellData<2>> cells;
        for (unsigned int k = 0; k < nz; ++k)
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int a = k * n + i, b = k * n + (i + 1) % n,
                                 c = a + n, d = b + n;
              CellData<2> t1(3), t2(3);
              t1.vertices = {a, b, d};
              t2.vertices = {a, d, c};
              cells.push_back(t1);
              cells.push_back(t2);
            }
        mesh.create_triangulation(vertices, cells, SubCellData());
        // Degree 2: the middle nodes of the edges along the outline and of
        // the diagonals on the arcs through the neighbouring outline
        // points (averaged over the two arcs, as the 2D loop's), so that
        // the rest surface is curved as the membrane is (straight rest
        // cells pushed onto the curve would carry a strain (kappa h)^2/24,
        // as large as a geotube's own); those of the edges along z halfway
        // up. The nodes stacked above one another keep one x-y.
        if (edge_middle_points)
          {
            edge_middle_points->clear();
            std::vector<Point<2>> middle(n);
            for (unsigned int i = 0; i < n; ++i)
              {
                const Point<2> &p0 = outline[(i + n - 1) % n], &p1 = outline[i],
                               &p2 = outline[(i + 1) % n],
                               &p3 = outline[(i + 2) % n];
                middle[i]          = Point<2>(
                  0.5
                  * (MembraneGeometry::point_on_arc(p0, p1, p2, p1, p2, 0.5)
                     + MembraneGeometry::point_on_arc(
                       p1, p2, p3, p1, p2, 0.5)));
              }
            auto add = [&](const unsigned int a,
                           const unsigned int b,
                           const Point<2>    &xy) {
              (*edge_middle_points)[{std::min(a, b), std::max(a, b)}]
                = Point<3>(xy[0],
                           xy[1],
                           0.5 * (vertices[a][2] + vertices[b][2]));
            };
            for (unsigned int k = 0; k <= nz; ++k)
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int a = k * n + i, b = k * n + (i + 1) % n;
                  add(a, b, middle[i]);
                  if (k < nz)
                    {
                      add(a, b + n, middle[i]);
                      add(a, a + n, outline[i]);
                    }
                }
          }
      }
  }

  template struct MembraneDescription<2>;
  template struct MembraneDescription<3>;
} // namespace fsgmpm
