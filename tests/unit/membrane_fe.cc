// The membrane on deal.II's FE machinery (MembraneFE)
// against the hand-written elements (MembraneMechanics) and patch tests:
// (a) degree 1 gives the hand-written cables' (2D ring) and triangles' (3D
// curved patch) nodal forces for a general deformation (measured: 2D
// 8.9e-15, 3D 8.5e-15 of the largest force; asserted 5e-14); (b) degree 2:
// a uniform stretch of a straight cable and of a flat sheet loads only the
// support points on the boundary, with the exact resultant (tension times
// length), and the interior ones carry nothing (1e-12 of the resultant);
// (c) a rigid rotation rotates the degree-2 forces; (d) the HRZ lumped
// masses are positive and sum to the membrane's mass; (e) a bad degree
// throws. Exact results (b)-(d) to 1e-12 relative, as membrane_patch.

#include <deal.II/grid/tria.h>

#include <fsgmpm/membrane/membrane_fe.h>
#include <fsgmpm/membrane/membrane_mechanics.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace fsgmpm;

namespace
{
  constexpr double EA = 2e5, nu = 0.3;

  // A closed ring of n cables of radius r (2D), or an open polyline.
  Triangulation<1, 2>
  cable_mesh(const unsigned int n, const bool closed)
  {
    std::vector<Point<2>>    vertices;
    std::vector<CellData<1>> cells;
    for (unsigned int i = 0; i < n + (closed ? 0 : 1); ++i)
      vertices.emplace_back(closed ? Point<2>(std::cos(2 * M_PI * i / n),
                                              std::sin(2 * M_PI * i / n))
                                   : Point<2>(0.5 * i, 0.));
    for (unsigned int i = 0; i < n; ++i)
      {
        CellData<1> c;
        c.vertices = {i, (i + 1) % unsigned(vertices.size())};
        cells.push_back(c);
      }
    Triangulation<1, 2> tria;
    tria.create_triangulation(vertices, cells, SubCellData());
    return tria;
  }

  // An m x m sheet of squares split into triangles, on the surface
  // z = @p bend (x^2 + y^2) over [0, 1]^2.
  Triangulation<2, 3>
  sheet_mesh(const unsigned int m, const double bend)
  {
    std::vector<Point<3>>    vertices;
    std::vector<CellData<2>> cells;
    for (unsigned int j = 0; j <= m; ++j)
      for (unsigned int i = 0; i <= m; ++i)
        {
          const double x = double(i) / m, y = double(j) / m;
          vertices.emplace_back(x, y, bend * (x * x + y * y));
        }
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int i = 0; i < m; ++i)
        {
          const unsigned int v0 = j * (m + 1) + i, v1 = v0 + 1, v2 = v0 + m + 1,
                             v3 = v2 + 1;
          CellData<2> a, b;
          a.vertices = {v0, v1, v3};
          b.vertices = {v0, v3, v2};
          cells.push_back(a);
          cells.push_back(b);
        }
    Triangulation<2, 3> tria;
    tria.create_triangulation(vertices, cells, SubCellData());
    return tria;
  }

  template <int dim>
  Point<dim>
  deform(const Point<dim> &X)
  {
    // A general smooth deformation: stretch, shear, bend and rotate.
    Point<dim> x;
    x[0] = 1.1 * X[0] + 0.05 * X[1] + 0.02 * X[1] * X[1] + 0.3;
    x[1] = 0.03 * X[0] + 1.2 * X[1] + 0.01 * X[0] * X[0] - 0.1;
    if constexpr (dim == 3)
      {
        x[0] += 0.04 * X[2];
        x[1] += 0.02 * X[2];
        x[2] = 1.05 * X[2] + 0.06 * X[0] - 0.02 * X[1];
      }
    return x;
  }

  template <int dim>
  double
  largest(const std::vector<Tensor<1, dim>> &f)
  {
    double m = 0;
    for (const auto &v : f)
      m = std::max(m, v.norm());
    return m;
  }

  // The support point of each triangulation vertex (degree 1).
  template <int dim>
  std::vector<unsigned int>
  vertex_to_support(const MembraneFE<dim>             &fe,
                    const Triangulation<dim - 1, dim> &tria)
  {
    std::vector<unsigned int> map(tria.n_vertices());
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      for (unsigned int i = 0; i < fe.n_support_points(); ++i)
        if (fe.rest_support_points()[i].distance(tria.get_vertices()[v])
            < 1e-12)
          map[v] = i;
    return map;
  }
} // namespace

TEST(MembraneFE, DegreeOneCablesEqualTheHandWrittenOnes)
{
  const auto            tria = cable_mesh(24, true);
  MembraneFE<2>         fe(tria, 1, EA, nu);
  const auto            support = vertex_to_support(fe, tria);
  std::vector<Point<2>> x;
  for (const auto &X : fe.rest_support_points())
    x.push_back(deform(X));
  const auto f_fe = fe.internal_forces(x);

  std::vector<Tensor<1, 2>> f_hand(fe.n_support_points());
  for (const auto &cell : tria.active_cell_iterators())
    {
      const unsigned int a = support[cell->vertex_index(0)],
                         b = support[cell->vertex_index(1)];
      Tensor<1, 2> fa, fb;
      MembraneMechanics::cable_forces(x[a], x[b], cell->measure(), EA, fa, fb);
      f_hand[a] += fa;
      f_hand[b] += fb;
    }
  double error = 0;
  for (unsigned int i = 0; i < f_fe.size(); ++i)
    error = std::max(error, (f_fe[i] - f_hand[i]).norm());
  std::cout << "[ measured ] 2D degree 1 against hand-written: "
            << error / largest(f_hand) << std::endl;
  EXPECT_GT(largest(f_hand), 1e3);
  EXPECT_LT(error, 5e-14 * largest(f_hand));

  // The tension and the tension tensor of each cable: T and T t t^T, with
  // T = EA max(0, l/L - 1) and t the chord's direction.
  std::vector<Tensor<1, 2>>          f;
  std::vector<std::array<double, 2>> stress;
  std::vector<SymmetricTensor<2, 2>> tensor;
  fe.internal_forces(x, f, &stress, &tensor);
  double worst = 0, largest_T = 0;
  for (const auto &cell : tria.active_cell_iterators())
    {
      const unsigned int c = cell->active_cell_index();
      const Tensor<1, 2> chord
        = x[support[cell->vertex_index(1)]] - x[support[cell->vertex_index(0)]];
      const double T = EA * std::max(0., chord.norm() / cell->measure() - 1);
      const Tensor<1, 2>          t = chord / chord.norm();
      const SymmetricTensor<2, 2> expected
        = T * symmetrize(outer_product(t, t));
      largest_T = std::max(largest_T, T);
      worst     = std::max(
        {worst, std::abs(stress[c][0] - T), (tensor[c] - expected).norm()});
    }
  std::cout << "[ measured ] 2D cable tension and tension tensor: "
            << worst / largest_T << std::endl;
  EXPECT_GT(largest_T, 1e3);
  EXPECT_LT(worst, 1e-13 * largest_T);
}

TEST(MembraneFE, DegreeOneTrianglesEqualTheHandWrittenOnes)
{
  const auto            tria = sheet_mesh(4, 0.3);
  MembraneFE<3>         fe(tria, 1, EA, nu);
  const auto            support = vertex_to_support(fe, tria);
  std::vector<Point<3>> x;
  for (const auto &X : fe.rest_support_points())
    x.push_back(deform(X));
  const auto f_fe = fe.internal_forces(x);

  std::vector<Tensor<1, 3>> f_hand(fe.n_support_points());
  for (const auto &cell : tria.active_cell_iterators())
    {
      const unsigned int n[3] = {support[cell->vertex_index(0)],
                                 support[cell->vertex_index(1)],
                                 support[cell->vertex_index(2)]};
      const auto         ref
        = MembraneMechanics::make_triangle_reference(cell->vertex(0),
                                                     cell->vertex(1),
                                                     cell->vertex(2));
      std::array<Tensor<1, 3>, 3> f;
      MembraneMechanics::triangle_forces(
        ref, x[n[0]], x[n[1]], x[n[2]], EA, nu, f);
      for (unsigned int k = 0; k < 3; ++k)
        f_hand[n[k]] += f[k];
    }
  double error = 0;
  for (unsigned int i = 0; i < f_fe.size(); ++i)
    error = std::max(error, (f_fe[i] - f_hand[i]).norm());
  std::cout << "[ measured ] 3D degree 1 against hand-written: "
            << error / largest(f_hand) << std::endl;
  EXPECT_GT(largest(f_hand), 1e3);
  EXPECT_LT(error, 5e-14 * largest(f_hand));
}

TEST(MembraneFE, DegreeTwoUniformStretchLoadsOnlyTheBoundary)
{
  // A straight cable of 3 m stretched by 10%: T = EA 0.1 at both ends.
  {
    const auto    tria = cable_mesh(6, false);
    MembraneFE<2> fe(tria, 2, EA, nu);
    EXPECT_EQ(fe.n_support_points(), 13u);
    std::vector<Point<2>> x;
    for (const auto &X : fe.rest_support_points())
      x.push_back(Point<2>(1.1 * X[0], X[1]));
    const auto   f = fe.internal_forces(x);
    const double T = EA * 0.1;
    for (unsigned int i = 0; i < f.size(); ++i)
      {
        const double X = fe.rest_support_points()[i][0];
        Tensor<1, 2> expected;
        if (X < 1e-12)
          expected[0] = T;
        else if (X > 3 - 1e-12)
          expected[0] = -T;
        EXPECT_LT((f[i] - expected).norm(), 1e-12 * T) << "X = " << X;
      }
  }
  // A flat unit sheet stretched equibiaxially by lambda: the first
  // Piola-Kirchhoff traction lambda S, S = EA/(1 - nu) (lambda^2 - 1)/2,
  // on every edge; the support points inside carry nothing.
  {
    const auto            tria = sheet_mesh(3, 0.);
    MembraneFE<3>         fe(tria, 2, EA, nu);
    const double          lambda = 1.08;
    std::vector<Point<3>> x;
    for (const auto &X : fe.rest_support_points())
      x.push_back(Point<3>(lambda * X[0], lambda * X[1], 0.));
    const auto   f = fe.internal_forces(x);
    const double S = EA / (1 - nu) * (lambda * lambda - 1) / 2;
    Tensor<1, 3> right_edge;
    double       inner = 0;
    for (unsigned int i = 0; i < f.size(); ++i)
      {
        const Point<3> &X   = fe.rest_support_points()[i];
        const bool boundary = X[0] < 1e-12 || X[0] > 1 - 1e-12 || X[1] < 1e-12
                              || X[1] > 1 - 1e-12;
        if (!boundary)
          inner = std::max(inner, f[i].norm());
        if (X[0] > 1 - 1e-12)
          right_edge += f[i];
      }
    // The edge x = 1 (length 1) pulls with -lambda S e_x on the body; its
    // corners share the other edges' tractions, which cancel in x.
    EXPECT_NEAR(right_edge[0], -lambda * S, 1e-12 * lambda * S);
    EXPECT_LT(inner, 1e-12 * lambda * S);
  }
}

TEST(MembraneFE, DegreeTwoRigidRotationRotatesTheForces)
{
  const auto    tria = sheet_mesh(2, 0.2);
  MembraneFE<3> fe(tria, 2, EA, nu);
  Tensor<2, 3>  R; // 0.7 rad about (1, 2, 2)/3
  {
    const Tensor<1, 3> k({1. / 3, 2. / 3, 2. / 3});
    Tensor<2, 3>       K;
    K[0][1] = -k[2], K[0][2] = k[1], K[1][0] = k[2];
    K[1][2] = -k[0], K[2][0] = -k[1], K[2][1] = k[0];
    for (unsigned int d = 0; d < 3; ++d)
      R[d][d] = 1;
    R += std::sin(0.7) * K + (1 - std::cos(0.7)) * K * K;
  }
  std::vector<Point<3>> x, y;
  for (const auto &X : fe.rest_support_points())
    {
      x.push_back(deform(X));
      y.push_back(Point<3>(R * deform(X)));
    }
  const auto fx = fe.internal_forces(x), fy = fe.internal_forces(y);
  double     error = 0;
  for (unsigned int i = 0; i < fx.size(); ++i)
    error = std::max(error, (fy[i] - R * fx[i]).norm());
  EXPECT_GT(largest(fx), 1e3);
  EXPECT_LT(error, 1e-12 * largest(fx));
}

TEST(MembraneFE, LumpedMassesArePositiveAndComplete)
{
  for (const unsigned int degree : {1u, 2u})
    {
      const auto    tria = sheet_mesh(3, 0.);
      MembraneFE<3> fe(tria, degree, EA, nu);
      const auto    m     = fe.lumped_masses(0.4);
      double        total = 0;
      for (const double mi : m)
        {
          EXPECT_GT(mi, 0.);
          total += mi;
        }
      EXPECT_NEAR(total, 0.4, 1e-14) << "degree " << degree;
    }
  const auto    tria = cable_mesh(10, true);
  MembraneFE<2> fe(tria, 2, EA, nu);
  double        total = 0;
  for (const double mi : fe.lumped_masses(0.4))
    total += mi;
  EXPECT_NEAR(total, 0.4 * 10 * 2 * std::sin(M_PI / 10), 1e-13);
}

TEST(MembraneFE, BadDegreeThrows)
{
  const auto tria = cable_mesh(4, true);
  EXPECT_THROW(MembraneFE<2>(tria, 3, EA, nu), std::exception);
  EXPECT_THROW(MembraneFE<2>(tria, 1, -1., nu), std::exception);
}
