// Point location on simplex grids: the cell reported by PointLocator must
// contain the point (every barycentric coordinate >= -1e-12), checked
// against a brute-force test over all cells -- not against deal.II 9.4's
// own locator, which uses the unit-cube test on simplices. Structured,
// distorted and Gmsh meshes (with negatively oriented cells), 2D and 3D,
// points inside, on faces, edges and vertices, and outside.

#include <deal.II/grid/grid_tools.h>

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/mesh_generation.h>
#include <fsgmpm/particles/body_shape.h>
#include <fsgmpm/particles/particle_store.h>
#include <fsgmpm/particles/point_locator.h>
#include <fsgmpm/particles/polygon_inside.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "grid_comparison.h"

using namespace fsgmpm;

namespace
{
  constexpr double tolerance = 1e-12;

  std::string
  data_dir()
  {
    const char *d = std::getenv("FSGMPM_TEST_DATA");
    return d ? d : FSGMPM_TEST_SOURCE_DIR;
  }

  template <int dim>
  double
  min_barycentric(const BackgroundGrid<dim> &grid,
                  const unsigned int         c,
                  const Point<dim>          &x)
  {
    const auto l = grid.barycentric(c, x);
    return *std::min_element(l.begin(), l.end());
  }

  // Brute force: is x in some cell (up to the tolerance)?
  template <int dim>
  bool
  inside_some_cell(const BackgroundGrid<dim> &grid, const Point<dim> &x)
  {
    for (unsigned int c = 0; c < grid.n_cells(); ++c)
      if (min_barycentric(grid, c, x) >= -tolerance)
        return true;
    return false;
  }

  template <int dim>
  std::vector<Point<dim>>
  test_points(const BackgroundGrid<dim> &grid, std::mt19937 &rng)
  {
    std::vector<Point<dim>>                points;
    std::uniform_real_distribution<double> u(0, 1);
    // Random points inside cells, on vertices, edge midpoints and face
    // centroids (shared by several cells), and random points in and
    // around the bounding box (some outside).
    for (unsigned int c = 0; c < grid.n_cells(); ++c)
      {
        std::array<double, dim + 1> l;
        double                      s = 0;
        for (auto &v : l)
          s += (v = -std::log(u(rng)));
        for (auto &v : l)
          v /= s;
        points.push_back(grid.position(c, l));
        for (unsigned int a = 0; a < dim + 1; ++a)
          {
            points.push_back(grid.node_positions[grid.cell_nodes[c][a]]);
            for (unsigned int b = a + 1; b < dim + 1; ++b)
              points.push_back(
                0.5
                * (grid.node_positions[grid.cell_nodes[c][a]]
                   + grid.node_positions[grid.cell_nodes[c][b]]));
            // Centroid of the face opposite a.
            Point<dim> f;
            for (unsigned int b = 0; b < dim + 1; ++b)
              if (b != a)
                f += grid.node_positions[grid.cell_nodes[c][b]] / double(dim);
            points.push_back(f);
          }
      }
    for (unsigned int i = 0; i < 500; ++i)
      {
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double len = grid.upper_corner[d] - grid.lower_corner[d];
            p[d] = grid.lower_corner[d] - 0.2 * len + 1.4 * len * u(rng);
          }
        points.push_back(p);
      }
    return points;
  }

  template <int dim>
  void
  check_grid(const BackgroundGrid<dim> &grid, const std::string &what)
  {
    std::mt19937                            rng(42);
    std::uniform_int_distribution<unsigned> any_cell(0, grid.n_cells() - 1);
    const PointLocator<dim>                 locator(grid, tolerance);
    unsigned int                            n_inside = 0, n_outside = 0;
    for (const auto &x : test_points(grid, rng))
      {
        // Start the walk both from a random (usually distant) cell and from
        // the brute-force answer's neighbourhood.
        const unsigned int c = locator.locate(x, any_cell(rng));
        if (inside_some_cell(grid, x))
          {
            ++n_inside;
            ASSERT_NE(c, BackgroundGrid<dim>::invalid)
              << what << ": point " << x << " is in the mesh but not found";
            EXPECT_GE(min_barycentric(grid, c, x), -tolerance)
              << what << ": point " << x << " reported in cell " << c
              << " that does not contain it";
            // The search around any cell that holds x gives the search of
            // all cells' answer, also on vertices, edges and faces (ties).
            const unsigned int all = grid.find_cell_brute_force(x, tolerance);
            EXPECT_EQ(grid.best_cell_around(x, tolerance, c), all)
              << what << ": point " << x;
            // So the hinted location is locate()'s, with a hint beside the
            // answer or anywhere.
            const unsigned int guess = any_cell(rng);
            for (const unsigned int hint :
                 {grid.cell_neighbors[all][0], all, any_cell(rng)})
              if (hint != BackgroundGrid<dim>::invalid)
                {
                  EXPECT_EQ(locator.locate(x, guess, hint),
                            locator.locate(x, guess))
                    << what << ": point " << x;
                }
          }
        else
          {
            ++n_outside;
            EXPECT_EQ(c, BackgroundGrid<dim>::invalid)
              << what << ": point " << x << " outside the mesh was located";
          }
      }
    EXPECT_GT(n_inside, 100u);
    EXPECT_GT(n_outside, 10u);
  }

  template <int dim>
  void
  distort(Triangulation<dim> &tria)
  {
    GridTools::transform(
      [](const Point<dim> &p) {
        Point<dim> q = p;
        for (unsigned int d = 0; d < dim; ++d)
          q[d]
            += 0.04 * std::sin(3. * p[(d + 1) % dim] + 1.) * p[d] * (1. - p[d]);
        return q;
      },
      tria);
  }
} // namespace



namespace
{
  // The grid of a box straight from MeshGeneration::box_simplices() must be
  // the grid of deal.II's mesh of that box, array for array.
  template <int dim>
  void
  expect_same_grid(const BackgroundGrid<dim> &a, const BackgroundGrid<dim> &b)
  {
    SCOPED_TRACE(std::to_string(dim) + "D box of " + std::to_string(a.n_cells())
                 + " cells");
    Testing::expect_same_grid_arrays(a, b);
  }

  template <int dim>
  void
  expect_same_box_grid(const Point<dim>                &lower,
                       const Point<dim>                &upper,
                       const std::vector<unsigned int> &subdivisions)
  {
    Triangulation<dim> tria;
    MeshGeneration::make_box(lower, upper, subdivisions, tria);
    expect_same_grid(BackgroundGrid<dim>(std::move(tria)),
                     BackgroundGrid<dim>(MeshGeneration::box_simplices(
                       lower, upper, subdivisions)));
  }

  // The extruded box: deal.II's mesh of extrude_to_tetrahedra() on
  // make_box() against the arrays of extrude_simplices() on box_simplices().
  void
  expect_same_extruded_grid(const Point<2>                  &lower,
                            const Point<2>                  &upper,
                            const std::vector<unsigned int> &subdivisions,
                            const double                     thickness)
  {
    Triangulation<2> base;
    MeshGeneration::make_box(lower, upper, subdivisions, base);
    Triangulation<3> tria;
    MeshGeneration::extrude_to_tetrahedra(base, thickness, tria);
    expect_same_grid(
      BackgroundGrid<3>(std::move(tria)),
      BackgroundGrid<3>(MeshGeneration::extrude_simplices(
        MeshGeneration::box_simplices(lower, upper, subdivisions), thickness)));
  }
} // namespace

TEST(BoxGrid, SameGridAsDealIIsMesh)
{
  // Odd and even counts (the 3D pattern alternates by parity), one box
  // thick, corners off the origin, unequal spacings.
  expect_same_box_grid(Point<2>(0, 0), Point<2>(1, 1), {1, 1});
  expect_same_box_grid(Point<2>(-0.3, 0.2), Point<2>(2.1, 0.9), {7, 4});
  expect_same_box_grid(Point<2>(-1, -2), Point<2>(3, 1), {40, 33});
  expect_same_box_grid(Point<3>(0, 0, 0), Point<3>(1, 1, 1), {1, 1, 1});
  expect_same_box_grid(Point<3>(-0.3, 0.2, 0.1),
                       Point<3>(2.1, 0.9, 0.35),
                       {5, 4, 1});
  expect_same_box_grid(Point<3>(-1, -2, 0), Point<3>(3, 1, 2), {8, 7, 6});
  expect_same_extruded_grid(Point<2>(0, 0), Point<2>(1, 1), {1, 1}, 0.1);
  expect_same_extruded_grid(Point<2>(-0.3, 0.2),
                            Point<2>(2.1, 0.9),
                            {9, 4},
                            0.05);
}

TEST(BoxGrid, BadBoxesAreRefused)
{
  EXPECT_THROW(MeshGeneration::box_simplices(Point<2>(0, 0),
                                             Point<2>(1, 1),
                                             {4}),
               ExceptionBase);
  EXPECT_THROW(MeshGeneration::box_simplices(Point<2>(0, 0),
                                             Point<2>(1, 0),
                                             {4, 4}),
               ExceptionBase);
  EXPECT_THROW(MeshGeneration::box_simplices(Point<3>(0, 0, 0),
                                             Point<3>(1, 1, 1),
                                             {4, 0, 4}),
               ExceptionBase);
  EXPECT_THROW(
    MeshGeneration::extrude_simplices(
      MeshGeneration::box_simplices(Point<2>(0, 0), Point<2>(1, 1), {2, 2}),
      0.),
    ExceptionBase);
  // 5 * 2000^3 tetrahedra overflow the cells' unsigned int numbers.
  EXPECT_THROW(MeshGeneration::box_simplices(Point<3>(0, 0, 0),
                                             Point<3>(1, 1, 1),
                                             {2000, 2000, 2000}),
               ExceptionBase);

  // A cell of zero area (three vertices on a line, centred at x = 1) and
  // a cell naming a vertex that is not there.
  MeshGeneration::SimplexMesh<2> line;
  line.vertices = {Point<2>(0, 0), Point<2>(1, 0), Point<2>(2, 0)};
  line.cells    = {{{0, 1, 2}}};
  try
    {
      const BackgroundGrid<2> grid(line);
      ADD_FAILURE() << "a degenerate cell was accepted";
    }
  catch (const ExceptionBase &e)
    {
      EXPECT_NE(std::string(e.what()).find("cell 0 near 1 is degenerate"),
                std::string::npos)
        << e.what();
    }
  line.cells = {{{0, 1, 3}}};
  EXPECT_THROW(BackgroundGrid<2> grid(line), ExceptionBase);

  // Three triangles on one edge (a mesh that is not conforming): a clear
  // error, not a neighbour picked at random.
  MeshGeneration::SimplexMesh<2> fan;
  fan.vertices = {Point<2>(0, 0),
                  Point<2>(1, 0),
                  Point<2>(0.5, 1),
                  Point<2>(0.5, -1),
                  Point<2>(0.5, 2)};
  fan.cells    = {{{0, 1, 2}}, {{0, 1, 3}}, {{0, 1, 4}}};
  try
    {
      const BackgroundGrid<2> grid(fan);
      ADD_FAILURE() << "a face of three cells was accepted";
    }
  catch (const ExceptionBase &e)
    {
      EXPECT_NE(std::string(e.what()).find(
                  "cell 0 is shared by more than two cells"),
                std::string::npos)
        << e.what();
    }
}



TEST(PointLocation, Structured2D)
{
  Triangulation<2> tria;
  MeshGeneration::make_box(Point<2>(0, 0), Point<2>(1, 0.5), {10, 5}, tria);
  check_grid(BackgroundGrid<2>(std::move(tria)), "structured 2D");
}

TEST(PointLocation, Structured3D)
{
  Triangulation<3> tria;
  MeshGeneration::make_box(Point<3>(0, 0, 0),
                           Point<3>(1, 1, 1),
                           {3, 3, 3},
                           tria);
  check_grid(BackgroundGrid<3>(std::move(tria)), "structured 3D");
}

TEST(PointLocation, Distorted2D)
{
  Triangulation<2> tria;
  MeshGeneration::make_box(Point<2>(0, 0), Point<2>(1, 1), {8, 8}, tria);
  distort(tria);
  check_grid(BackgroundGrid<2>(std::move(tria)), "distorted 2D");
}

TEST(PointLocation, Distorted3D)
{
  Triangulation<3> tria;
  MeshGeneration::make_box(Point<3>(0, 0, 0),
                           Point<3>(1, 1, 1),
                           {3, 3, 3},
                           tria);
  distort(tria);
  check_grid(BackgroundGrid<3>(std::move(tria)), "distorted 3D");
}

TEST(PointLocation, Gmsh2D)
{
  Triangulation<2> tria;
  MeshGeneration::read_gmsh(data_dir() + "/meshes/square_triangles.msh", tria);
  check_grid(BackgroundGrid<2>(std::move(tria)), "gmsh 2D");
}

TEST(PointLocation, Gmsh3DWithNegativelyOrientedTets)
{
  Triangulation<3> tria;
  MeshGeneration::read_gmsh(data_dir() + "/meshes/cube_tetrahedra.msh", tria);
  check_grid(BackgroundGrid<3>(std::move(tria)), "gmsh 3D");
}

TEST(PointLocation, ExtrudedSlab)
{
  Triangulation<2> base;
  MeshGeneration::make_box(Point<2>(0, 0), Point<2>(1, 0.5), {6, 3}, base);
  Triangulation<3> slab;
  MeshGeneration::extrude_to_tetrahedra(base, 0.1, slab);
  check_grid(BackgroundGrid<3>(std::move(slab)), "extruded slab");
}

namespace
{
  // The grid's neighbours against deal.II's own: the cell across the face
  // opposite local vertex k is deal.II's neighbour across that face.
  template <int dim>
  void
  expect_deal_iis_neighbours(const Triangulation<dim> &tria,
                             const std::string        &name)
  {
    Triangulation<dim> copy;
    copy.copy_triangulation(tria);
    const BackgroundGrid<dim> grid(std::move(copy));
    unsigned int              n_inner = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          unsigned int opposite = 0;
          for (unsigned int v = 0; v < cell->n_vertices(); ++v)
            {
              bool on_face = false;
              for (unsigned int w = 0; w < cell->face(f)->n_vertices(); ++w)
                on_face
                  = on_face
                    || cell->face(f)->vertex_index(w) == cell->vertex_index(v);
              if (!on_face)
                opposite = v;
            }
          const unsigned int expected
            = cell->at_boundary(f) ? BackgroundGrid<dim>::invalid
                                   : cell->neighbor(f)->active_cell_index();
          n_inner += !cell->at_boundary(f);
          EXPECT_EQ(grid.cell_neighbors[cell->active_cell_index()][opposite],
                    expected)
            << name << ", cell " << cell->active_cell_index() << ", face " << f;
        }
    EXPECT_GT(n_inner, 0u) << name;
  }
} // namespace

TEST(GridNeighbours, AsDealIIsNeighbours)
{
  Triangulation<2> square, distorted, gmsh_2d;
  MeshGeneration::make_box(Point<2>(0, 0), Point<2>(1, 0.5), {10, 5}, square);
  expect_deal_iis_neighbours(square, "box 2D");
  MeshGeneration::make_box(Point<2>(0, 0), Point<2>(1, 1), {8, 8}, distorted);
  distort(distorted);
  expect_deal_iis_neighbours(distorted, "distorted 2D");
  MeshGeneration::read_gmsh(data_dir() + "/meshes/square_triangles.msh",
                            gmsh_2d);
  expect_deal_iis_neighbours(gmsh_2d, "gmsh 2D");

  Triangulation<3> cube, gmsh_3d, slab;
  MeshGeneration::make_box(Point<3>(0, 0, 0),
                           Point<3>(1, 1, 1),
                           {3, 4, 5},
                           cube);
  expect_deal_iis_neighbours(cube, "box 3D");
  MeshGeneration::read_gmsh(data_dir() + "/meshes/cube_tetrahedra.msh",
                            gmsh_3d);
  expect_deal_iis_neighbours(gmsh_3d, "gmsh 3D");
  Triangulation<2> base;
  MeshGeneration::make_box(Point<2>(0, 0), Point<2>(1, 0.5), {6, 3}, base);
  MeshGeneration::extrude_to_tetrahedra(base, 0.1, slab);
  expect_deal_iis_neighbours(slab, "extruded slab");
}



// The case deal.II 9.4's stock sort gets wrong (doc/foundation_validation.md):
// points on a triangulated square rotated slowly and re-located by walking
// from their previous cell every step must always be in a cell that contains
// them.
TEST(PointLocation, SlowRotationWalk)
{
  Triangulation<2> tria;
  MeshGeneration::make_box(Point<2>(0, 0), Point<2>(1, 1), {32, 32}, tria);
  const BackgroundGrid<2>   grid(std::move(tria));
  const PointLocator<2>     locator(grid, tolerance);
  std::vector<Point<2>>     x;
  std::vector<unsigned int> cell;
  for (unsigned int i = 0; i < 96; ++i)
    for (unsigned int j = 0; j < 96; ++j)
      {
        const Point<2> p(0.2 + 0.6 * (i + 0.5) / 96,
                         0.2 + 0.6 * (j + 0.5) / 96);
        x.push_back(p);
        cell.push_back(grid.find_cell_brute_force(p, tolerance));
      }
  const Point<2> centre(0.5, 0.5);
  const double   angle = 0.02;
  unsigned int   wrong = 0;
  for (unsigned int step = 0; step < 20; ++step)
    for (unsigned int p = 0; p < x.size(); ++p)
      {
        const Tensor<1, 2> r = x[p] - centre;
        x[p]                 = centre
               + Point<2>(std::cos(angle) * r[0] - std::sin(angle) * r[1],
                          std::sin(angle) * r[0] + std::cos(angle) * r[1]);
        cell[p] = locator.locate(x[p], cell[p]);
        if (cell[p] == BackgroundGrid<2>::invalid
            || min_barycentric(grid, cell[p], x[p]) < -tolerance)
          ++wrong;
      }
  EXPECT_EQ(wrong, 0u);
}



// PolygonInside (the fill of a membrane, the monitors' leak counts) gives
// inside_polygon()'s answer for every point, on vertices, edges and at the
// vertices' heights too (where the even-odd rule's ties are), for a
// membrane-like loop of 4 600 vertices, a non-convex star, a staircase with
// horizontal edges and a triangle.
TEST(PolygonInside, SameAnswerAsInsidePolygon)
{
  std::mt19937                           rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::vector<Point<2>>>     polygons(4);
  for (unsigned int i = 0; i < 4600; ++i)
    {
      const double t = 2 * M_PI * i / 4600;
      polygons[0].emplace_back(3 + 1.6 * std::cos(t), 0.7 + 0.7 * std::sin(t));
    }
  for (unsigned int i = 0; i < 200; ++i)
    {
      const double t = 2 * M_PI * i / 200, r = 0.3 + u(rng);
      polygons[1].emplace_back(r * std::cos(t), r * std::sin(t));
    }
  for (unsigned int i = 0; i < 10; ++i)
    {
      polygons[2].emplace_back(i, i);
      polygons[2].emplace_back(i + 1, i);
    }
  polygons[2].emplace_back(0, 10);
  polygons[3] = {Point<2>(0, 0), Point<2>(1, 0), Point<2>(0.3, 0.8)};

  for (const auto &v : polygons)
    {
      const PolygonInside inside(v);
      double              x0 = v[0][0], x1 = x0, y0 = v[0][1], y1 = y0;
      for (const auto &p : v)
        {
          x0 = std::min(x0, p[0]);
          x1 = std::max(x1, p[0]);
          y0 = std::min(y0, p[1]);
          y1 = std::max(y1, p[1]);
        }
      std::vector<Point<2>> points;
      for (unsigned int k = 0; k < 20000; ++k)
        points.emplace_back(x0 - 0.1 * (x1 - x0) + 1.2 * (x1 - x0) * u(rng),
                            y0 - 0.1 * (y1 - y0) + 1.2 * (y1 - y0) * u(rng));
      for (unsigned int i = 0; i < v.size(); ++i)
        {
          points.push_back(v[i]);
          points.push_back(0.5 * (v[i] + v[(i + 1) % v.size()]));
          points.emplace_back(x0 + (x1 - x0) * u(rng), v[i][1]);
        }
      unsigned int n_in = 0;
      for (const auto &x : points)
        {
          const bool expected = inside_polygon(v, x);
          ASSERT_EQ(inside(x), expected) << "point " << x;
          n_in += expected;
        }
      EXPECT_GT(n_in, points.size() / 10);
      EXPECT_LT(n_in, points.size());
      EXPECT_EQ(inside.get_vertices(), v);
    }
}



// PolygonShape refuses a self-intersecting outline by a sweep over y; it
// must name the first crossing pair of edges (i < j, in (i, j) order) that
// a test of all pairs finds, here with its own orientation test.
TEST(PolygonShape, SelfIntersectionAsATestOfAllPairs)
{
  const auto side
    = [](const Point<2> &o, const Point<2> &a, const Point<2> &b) {
        const double c
          = (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
        return (c > 0) - (c < 0);
      };
  std::mt19937                           rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  unsigned int                           n_crossing = 0, n_simple = 0;
  for (unsigned int trial = 0; trial < 400; ++trial)
    {
      const unsigned int    n = 4 + trial % 37;
      std::vector<Point<2>> v(n);
      // Half random points (they nearly always cross), half star-shaped
      // (simple) outlines with a random radius per vertex.
      for (unsigned int k = 0; k < n; ++k)
        {
          if (trial % 2 == 0)
            v[k] = Point<2>(u(rng), u(rng));
          else
            {
              const double angle = 2 * M_PI * k / n, r = 0.5 + 0.4 * u(rng);
              v[k] = Point<2>(r * std::cos(angle), r * std::sin(angle));
            }
        }
      std::string expected;
      for (unsigned int i = 0; i < n && expected.empty(); ++i)
        for (unsigned int j = i + 2; j < n && expected.empty(); ++j)
          {
            if (i == 0 && j == n - 1)
              continue;
            const Point<2> &a = v[i], &b = v[(i + 1) % n], &c = v[j],
                           &d = v[(j + 1) % n];
            if (side(c, d, a) * side(c, d, b) < 0
                && side(a, b, c) * side(a, b, d) < 0)
              expected = "edges " + std::to_string(i) + " and "
                         + std::to_string(j) + ")";
          }
      if (expected.empty())
        {
          ++n_simple;
          EXPECT_NO_THROW(PolygonShape shape(v)) << "trial " << trial;
        }
      else
        {
          ++n_crossing;
          try
            {
              PolygonShape shape(v);
              ADD_FAILURE() << "trial " << trial << ": no error, " << expected;
            }
          catch (const ExceptionBase &e)
            {
              EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
                << "trial " << trial << ": " << e.what();
            }
        }
    }
  // Both kinds were tried.
  EXPECT_GT(n_crossing, 100u);
  EXPECT_GT(n_simple, 100u);
}



// ParticleStore::cache_cell_geometry() (3D): each occupied cell's cached
// geometry is the one BackgroundGrid::geometry() computes, bit for bit,
// after a sort, after keep_cell_ranges() drops cells (slots renumbered)
// and with MPI-like cells appended after the sorted ones but merged into
// occupied_cells in order (their slots are not their places there); a
// sort forgets it. In 2D nothing is cached.
TEST(ParticleStore, CachedGeometryIsTheCellsOwn)
{
  const BackgroundGrid<3> grid(
    MeshGeneration::box_simplices(Point<3>(0, 0, 0),
                                  Point<3>(1.2, 0.5, 0.3),
                                  std::vector<unsigned int>{6, 5, 3}));
  const auto expect_cached = [&](const ParticleStore<3> &ps) {
    for (const unsigned int c : ps.occupied_cells)
      {
        const CellGeometry<3> *g = ps.cached_geometry(c);
        ASSERT_NE(g, nullptr) << "cell " << c;
        const CellGeometry<3> own = grid.geometry(c);
        EXPECT_EQ(g->x0, own.x0) << "cell " << c;
        EXPECT_EQ(g->inverse_edges, own.inverse_edges) << "cell " << c;
        EXPECT_EQ(g->volume, own.volume) << "cell " << c;
      }
  };
  const auto centre = [&](const unsigned int c) {
    Point<3> x;
    for (const auto &v : grid.vertices(c))
      x += v / 4.;
    return x;
  };
  // Two points in every third cell, added from the last cell down.
  ParticleStore<3> ps;
  for (unsigned int c = grid.n_cells(); c-- > 0;)
    if (c % 3 == 0)
      for (unsigned int k = 0; k < 2; ++k)
        ps.add(centre(c), c, 1., 1., {}, {}, 0, 0);
  ps.sort_by_cell(grid.n_cells());
  EXPECT_EQ(ps.cached_geometry(ps.occupied_cells[0]), nullptr);
  ps.cache_cell_geometry(grid);
  expect_cached(ps);
  // Keep every other occupied cell: new slots, the cache along.
  std::vector<unsigned int> kept;
  for (unsigned int i = 0; i < ps.occupied_cells.size(); i += 2)
    kept.push_back(ps.occupied_cells[i]);
  ps.keep_cell_ranges(kept);
  expect_cached(ps);
  // Cells appended after the sorted ones (as DistributedPoints::add_ghosts
  // does) have slots at the end but places in the middle of
  // occupied_cells: not cached yet, then cached by their slots.
  std::vector<unsigned int> added;
  for (unsigned int c = 1; c < grid.n_cells(); c += 7)
    if (ps.occupied_slot(c) == numbers::invalid_unsigned_int
        && ps.cell_end(c) == 0)
      {
        const unsigned int begin = ps.size();
        ps.add(centre(c), c, 1., 1., {}, {}, 0, 0);
        ps.append_cell_range(c, begin, ps.size());
        added.push_back(c);
      }
  ASSERT_GT(added.size(), 10u);
  std::vector<unsigned int> merged;
  std::merge(ps.occupied_cells.begin(),
             ps.occupied_cells.end(),
             added.begin(),
             added.end(),
             std::back_inserter(merged));
  ps.occupied_cells.swap(merged);
  EXPECT_EQ(ps.cached_geometry(added[0]), nullptr);
  ps.cache_cell_geometry(grid);
  expect_cached(ps);
  ps.sort_by_cell(grid.n_cells());
  for (const unsigned int c : ps.occupied_cells)
    EXPECT_EQ(ps.cached_geometry(c), nullptr);

  // 2D: nothing cached.
  const BackgroundGrid<2> grid_2d(MeshGeneration::box_simplices(
    Point<2>(0, 0), Point<2>(1, 1), std::vector<unsigned int>{4, 4}));
  ParticleStore<2>        ps_2d;
  ps_2d.add(Point<2>(0.1, 0.1), 0, 1., 1., {}, {}, 0, 0);
  ps_2d.sort_by_cell(grid_2d.n_cells());
  ps_2d.cache_cell_geometry(grid_2d);
  EXPECT_EQ(ps_2d.cached_geometry(0), nullptr);
}



// The runs of points of one material that the time step, the stress update
// and the energies look their material up for: each run ends at the first
// point of another material or at the bound given.
TEST(ParticleStore, MaterialRunsEndAtTheNextMaterial)
{
  ParticleStore<2>                 ps;
  const std::vector<std::uint16_t> materials = {0, 0, 1, 1, 1, 0, 2};
  for (const std::uint16_t m : materials)
    ps.add(Point<2>(), 0, 1., 1., {}, {}, m, 0);
  std::vector<unsigned int> ends;
  for (unsigned int p = 0; p < ps.size(); p = ps.material_run_end(p, ps.size()))
    ends.push_back(ps.material_run_end(p, ps.size()));
  EXPECT_EQ(ends, (std::vector<unsigned int>{2, 5, 6, 7}));
  // A bound inside a run ends it there.
  EXPECT_EQ(ps.material_run_end(2, 4), 4u);
  EXPECT_EQ(ps.material_run_end(6, 7), 7u);
}
