// The geocontainer's crossing monitors in 3D (container_monitors()): a
// point is judged against the membrane's cross-section at its own z (the
// rings and the triangles' diagonals between the faces), not one face. A tube
// of 16 nodes on a circle of radius 0.1 m, two rings (z = 0 and 0.04 m),
// the back ring moved 3 mm in +x. Near the back face (z = 0.039) a water
// point 1.5 mm outside the section on the left (inside the front ring) and
// a sand point 1.5 mm inside the section on the right (outside the front
// ring) are neither "water inside" nor "sand outside"; the same points near
// the front face (z = 0.001), where they are on the other side of the
// section, are. Judged by the front ring alone (as the monitor once was),
// both points near the back face counted.
#include <deal.II/grid/tria.h>

#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/monitors/container_monitor.h>
#include <fsgmpm/particles/particle_store.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace fsgmpm;

namespace
{
  Membrane<3>
  tube(const unsigned int n, const double r, const double depth)
  {
    std::vector<Point<3>>    vertices;
    std::vector<CellData<2>> cells;
    for (const double z : {0., depth})
      for (unsigned int i = 0; i < n; ++i)
        {
          const double t = 2 * M_PI * i / n;
          vertices.emplace_back(r * std::cos(t), r * std::sin(t), z);
        }
    for (unsigned int i = 0; i < n; ++i)
      {
        const unsigned int j = (i + 1) % n;
        CellData<2>        a, b;
        a.vertices = {i, j, n + j};
        b.vertices = {i, n + j, n + i};
        cells.push_back(a);
        cells.push_back(b);
      }
    Triangulation<2, 3> mesh;
    mesh.create_triangulation(vertices, cells, SubCellData());
    MembraneProperties p;
    p.axial_stiffness = 1e5;
    p.areal_mass      = 0.5;
    return Membrane<3>(mesh, p);
  }

  // (water inside, sand outside) for a water point at (x_w, 0, z) and a
  // sand point (body 0) at (x_s, 0, z).
  std::pair<double, double>
  counts(const Membrane<3> &m, const double x_w, const double x_s, double z)
  {
    ParticleStore<3>   ps;
    const Tensor<1, 3> v;
    ps.add(Point<3>(x_w, 0, z), 0, 1, 1, v, SymmetricTensor<2, 3>(), 0, 1);
    ps.add(Point<3>(x_s, 0, z), 0, 1, 1, v, SymmetricTensor<2, 3>(), 0, 0);
    const auto values = container_monitors<3>(ps, &m, 0);
    return {values.at("water_points_inside"), values.at("soil_points_outside")};
  }
} // namespace

TEST(ContainerMonitor, ThreeDPointsAreJudgedAtTheirOwnDepth)
{
  Membrane<3> m = tube(16, 0.1, 0.04);
  ASSERT_EQ(m.rings.size(), 2u);
  for (unsigned int a = 0; a < m.n_nodes(); ++a)
    if (m.position[a][2] > 0.02)
      m.position[a][0] += 0.003;
  // The section at z = 0.039 spans x from -0.097075 to 0.102925.
  const double x_w = -0.0985, x_s = 0.1015;
  const auto [water_back, sand_back] = counts(m, x_w, x_s, 0.039);
  EXPECT_EQ(water_back, 0.);
  EXPECT_EQ(sand_back, 0.);
  const auto [water_front, sand_front] = counts(m, x_w, x_s, 0.001);
  EXPECT_EQ(water_front, 1.);
  EXPECT_EQ(sand_front, 1.);
}
