// A membrane surface from Gmsh with second-order (6-node) triangles:
// the reader (membrane/gmsh_surface.h) and a degree-2 Membrane on the curved
// geometry. (a) The elliptic cylinder of the geotube A5.56 (written by
// tests/meshes/make_elliptic_cylinder.py in formats 4.1 and 2.2) gives the
// corners as the triangulation's vertices and every edge's middle node, all
// on the ellipse (measured residual 3.3e-8; asserted 1e-7: the script's
// ellipse axes come from its own polygonal perimeter) and at the middle z.
// (b) A first-order file gives no middle nodes, and a Membrane on it is the
// one fsgmpm extrudes from Membrane/Shape = ellipse with the same nodes
// (80 around, 2 layers): nodes at the same places (measured 1.8e-8 m,
// asserted 1e-7: the script's ellipse), forces under the same deformation
// equal to 2e-7 of the largest (measured 4e-8). (c) Bad files throw
// messages that say what to fix. (d) The degree-2 Membrane built on it has
// its edge nodes where Gmsh put them, is unloaded at rest (curved rest
// cells; measured 8.6e-8 N with EA = 5e7 N/m, asserted 3e-7 N) and, stretched
// uniformly in x-y by lambda, carries the exact plane-stress Saint
// Venant-Kirchhoff stresses in every cell: hoop lambda EA/(1-nu^2)
// (lambda^2-1)/2 and axial nu EA/(1-nu^2) (lambda^2-1)/2 / lambda (Cauchy; the
// P2 interpolant of the cylinder is a cylinder, so this holds at every
// quadrature point; measured 1.4e-12, asserted 1e-11).

#include <deal.II/grid/tria.h>

#include <fsgmpm/membrane/gmsh_surface.h>
#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/membrane/membrane_geometry.h>
#include <fsgmpm/scene/parameter_path.h>
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <string>

using namespace fsgmpm;

namespace
{
  const std::string meshes = std::string(FSGMPM_TEST_SOURCE_DIR) + "/meshes/";

  // Residual of the ellipse of the geotube A5.56 (lowest point (3, 0)).
  double
  off_ellipse(const Point<3> &p)
  {
    static const std::pair<double, double> axes
      = MembraneGeometry::ellipse_axes(9.2, 5.56);
    const double a = axes.first, b = axes.second;
    const double x = (p[0] - 3.) / a, y = (p[1] - b) / b;
    return std::abs(x * x + y * y - 1.);
  }

  std::string
  error_of(const std::string &content)
  {
    const std::string file = "gmsh_surface_bad.msh";
    std::ofstream(file) << content;
    Triangulation<2, 3> surface;
    EdgeMiddlePoints    middle;
    try
      {
        read_gmsh_surface(file, "Membrane/Mesh file", surface, middle);
      }
    catch (ExceptionBase &e)
      {
        // deal.II wraps the message: compare with single spaces.
        std::string message;
        for (const char c : std::string(e.what()))
          if (!std::isspace(c))
            message += c;
          else if (!message.empty() && message.back() != ' ')
            message += ' ';
        return message;
      }
    return "no error";
  }

  const std::string header = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  const std::string nodes  = "$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"
                             "4 0.5 0 0\n5 0.5 0.5 0.1\n6 0 0.5 0\n$EndNodes\n";
} // namespace



TEST(GmshSurface, SecondOrderEllipticCylinderInBothFormats)
{
  for (const auto &[file, n, nz] :
       {std::tuple<std::string, unsigned int, unsigned int>{
          "geotube_A5.56_p2.msh", 40, 1},
        {"geotube_A5.56_p2_coarse_v2.msh", 8, 1}})
    {
      Triangulation<2, 3> surface;
      EdgeMiddlePoints    middle;
      read_gmsh_surface(meshes + file, "Membrane/Mesh file", surface, middle);
      EXPECT_EQ(surface.n_active_cells(), 2 * n * nz) << file;
      EXPECT_EQ(surface.n_used_vertices(), n * (nz + 1)) << file;
      // Ring edges, vertical edges and diagonals.
      EXPECT_EQ(middle.size(), n * (3 * nz + 1)) << file;
      double worst = 0;
      for (const auto &v : surface.get_vertices())
        worst = std::max(worst, off_ellipse(v));
      for (const auto &[edge, m] : middle)
        {
          worst         = std::max(worst, off_ellipse(m));
          const auto &v = surface.get_vertices();
          EXPECT_NEAR(m[2],
                      0.5 * (v[edge.first][2] + v[edge.second][2]),
                      1e-12);
          // On the curved surface, not the chord: off the straight midpoint.
          if (std::abs(v[edge.first][2] - v[edge.second][2]) < 1e-12)
            {
              EXPECT_GT(m.distance(0.5 * (v[edge.first] + v[edge.second])),
                        1e-5);
            }
        }
      std::printf("measured %s: largest ellipse residual %.1e\n",
                  file.c_str(),
                  worst);
      EXPECT_LT(worst, 1e-7) << file;
    }
}

TEST(GmshSurface, FirstOrderFileIsTheExtrusion)
{
  Triangulation<2, 3> surface;
  EdgeMiddlePoints    middle;
  read_gmsh_surface(meshes + "geotube_A5.56_p1.msh",
                    "Membrane/Mesh file",
                    surface,
                    middle);
  EXPECT_EQ(surface.n_active_cells(), 2u * 80 * 2);
  EXPECT_TRUE(middle.empty());

  // The extrusion: elements of 0.1627 m give 80 around (ceil(9.2 sqrt(2) /
  // h)) and 2 along the 0.16 m slab.
  ParameterHandler prm;
  MembraneDescription<3>::declare_parameters(prm);
  set_parameter(prm, "Membrane/Enabled", "true");
  set_parameter(prm, "Membrane/Circumference", 9.2);
  set_parameter(prm, "Membrane/Enclosed area", 5.56);
  set_parameter(prm, "Membrane/Lowest point", "3, 0");
  set_parameter(prm, "Membrane/Element size", 0.1627);
  const MembraneDescription<3> description(prm);
  Triangulation<2, 3>          extruded;
  description.make_mesh(0.16, {0., 0.16}, extruded);
  Membrane<3> from_gmsh(surface, description.properties);
  Membrane<3> built_in(extruded, description.properties);
  ASSERT_EQ(from_gmsh.n_nodes(), built_in.n_nodes());
  ASSERT_EQ(from_gmsh.n_elements(), built_in.n_elements());
  // The same deformation of both, then the force on each node against
  // the force on the built-in node at the same place.
  auto deform = [](Membrane<3> &m) {
    for (auto &x : m.position)
      x += Tensor<1, 3>({0.01 * std::sin(3 * x[0]),
                         0.02 * std::cos(2 * x[1]) * x[2],
                         0.005 * x[0]});
    m.compute_forces();
  };
  deform(from_gmsh);
  deform(built_in);
  double largest = 0, worst_force = 0, worst_place = 0;
  for (const auto &f : built_in.force)
    largest = std::max(largest, f.norm());
  for (unsigned int a = 0; a < from_gmsh.n_nodes(); ++a)
    {
      unsigned int b    = 0;
      double       best = 1e300;
      for (unsigned int k = 0; k < built_in.n_nodes(); ++k)
        if (from_gmsh.position[a].distance(built_in.position[k]) < best)
          {
            best = from_gmsh.position[a].distance(built_in.position[k]);
            b    = k;
          }
      worst_place = std::max(worst_place, best);
      worst_force = std::max(worst_force,
                             (from_gmsh.force[a] - built_in.force[b]).norm());
    }
  std::printf("measured Gmsh against extrusion: nodes within %.1e m, forces "
              "within %.1e of the largest (%.3e N)\n",
              worst_place,
              worst_force / largest,
              largest);
  EXPECT_LT(worst_place, 1e-7);
  EXPECT_LT(worst_force, 2e-7 * largest);
}

TEST(GmshSurface, BadFilesSayWhatToFix)
{
  EXPECT_NE(error_of("$MeshFormat\n4.1 1 8\n$EndMeshFormat\n").find("binary"),
            std::string::npos);
  EXPECT_NE(error_of(header + nodes
                     + "$Elements\n1\n1 3 2 1 1 1 2 5 3\n"
                       "$EndElements\n")
              .find("type 3"),
            std::string::npos);
  EXPECT_NE(error_of(header + nodes
                     + "$Elements\n2\n1 2 2 1 1 1 2 3\n"
                       "2 9 2 1 1 1 2 3 4 5 6\n$EndElements\n")
              .find("mixes first- and second-order"),
            std::string::npos);
  EXPECT_NE(error_of(header + nodes
                     + "$Elements\n1\n1 2 2 1 1 1 2 7\n"
                       "$EndElements\n")
              .find("node 7"),
            std::string::npos);
  EXPECT_NE(error_of(header + nodes
                     + "$Elements\n1\n1 1 2 1 1 1 2\n"
                       "$EndElements\n")
              .find("no triangles"),
            std::string::npos);
  EXPECT_NE(error_of("$MeshFormat\n4 0 8\n$EndMeshFormat\n")
              .find("formats 2.2 and 4.1 are read"),
            std::string::npos);
  EXPECT_NE(error_of("no mesh here\n").find("not a Gmsh mesh"),
            std::string::npos);
  // Two triangles sharing edge 1-2 with different middle nodes (4 and 5).
  EXPECT_NE(error_of(
              header
              + "$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0.5 0.5 0\n"
                "5 0.5 0.5 0.2\n6 0 0.5 0\n7 1 1 0\n8 0.5 0 0\n$EndNodes\n"
                "$Elements\n2\n1 9 2 1 1 1 2 3 8 4 6\n"
                "2 9 2 1 1 2 7 3 8 8 5\n$EndElements\n")
              .find("not conforming"),
            std::string::npos);
  EXPECT_NE(error_of("").find("not a Gmsh mesh"), std::string::npos);
}

TEST(GmshSurface, DegreeTwoCylinderStretchIsExact)
{
  Triangulation<2, 3> surface;
  EdgeMiddlePoints    middle;
  read_gmsh_surface(meshes + "geotube_A5.56_p2.msh",
                    "Membrane/Mesh file",
                    surface,
                    middle);
  MembraneProperties props;
  props.axial_stiffness = 5e7;
  props.poisson_ratio   = 0.3;
  props.element_degree  = 2;
  Membrane<3> membrane(surface, props, middle);
  ASSERT_EQ(membrane.n_nodes(), surface.n_used_vertices() + middle.size());
  // Every Gmsh node is a membrane node at its place.
  for (const auto &[edge, m] : middle)
    {
      double nearest = 1e300;
      for (const auto &x : membrane.position)
        nearest = std::min(nearest, x.distance(m));
      EXPECT_LT(nearest, 1e-14);
    }
  // At rest (curved rest cells through the Gmsh nodes): no force.
  double largest_force = 0;
  for (const auto &f : membrane.force)
    largest_force = std::max(largest_force, f.norm());
  std::printf("measured force at rest %.1e N\n", largest_force);
  EXPECT_LT(largest_force, 3e-7);

  const double lambda = 1.01;
  const auto [a, b]   = MembraneGeometry::ellipse_axes(9.2, 5.56);
  for (auto &x : membrane.position)
    for (unsigned int d = 0; d < 2; ++d)
      x[d] = (d == 0 ? 3. : b) + lambda * (x[d] - (d == 0 ? 3. : b));
  const double E     = 0.5 * (lambda * lambda - 1);
  const double C     = props.axial_stiffness / (1 - 0.3 * 0.3);
  const double hoop  = lambda * C * E;
  const double axial = 0.3 * C * E / lambda;
  double       worst = 0;
  // The principal Cauchy stresses of every cell (MembraneFE).
  std::vector<Point<3>> x(membrane.get_fe().n_support_points());
  for (unsigned int i = 0; i < x.size(); ++i)
    x[i] = membrane.position[membrane.support_point_node(i)];
  std::vector<Tensor<1, 3>>          force;
  std::vector<std::array<double, 2>> stress;
  std::vector<SymmetricTensor<2, 3>> tensor;
  membrane.get_fe().internal_forces(x, force, &stress, &tensor);
  ASSERT_EQ(stress.size(), surface.n_active_cells());
  ASSERT_EQ(tensor.size(), surface.n_active_cells());
  for (const auto &s : stress)
    worst = std::max(
      {worst, std::abs(s[0] - hoop) / hoop, std::abs(s[1] - axial) / hoop});
  // The cell average of the tension tensor hoop t t^T + axial e_z e_z^T
  // (t horizontal, turning over a curved cell): zz is the axial tension,
  // xz and yz vanish, the trace is hoop + axial, and the horizontal part
  // is hoop times a matrix of trace 1 that is positive semi-definite.
  double worst_tensor = 0;
  for (const auto &s : tensor)
    {
      const double det_xy = s[0][0] * s[1][1] - s[0][1] * s[0][1];
      worst_tensor        = std::max({worst_tensor,
                                      std::abs(s[2][2] - axial) / hoop,
                                      std::abs(s[0][2]) / hoop,
                                      std::abs(s[1][2]) / hoop,
                                      std::abs(trace(s) - hoop - axial) / hoop,
                                      std::max(0., -det_xy) / (hoop * hoop)});
    }
  std::printf("measured uniform stretch: hoop %.6e N/m, largest relative "
              "error %.1e (principal), %.1e (tension tensor)\n",
              hoop,
              worst,
              worst_tensor);
  EXPECT_LT(worst, 1e-11);
  EXPECT_LT(worst_tensor, 1e-11);
}
