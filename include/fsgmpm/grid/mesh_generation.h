#ifndef fsgmpm_grid_mesh_generation_h
#define fsgmpm_grid_mesh_generation_h

#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * Functions that make the simplex background triangulation.
   *
   * Boundary ids of box-like meshes follow deal.II's colorize convention:
   * 0/1 for the faces at x = min/max, 2/3 for y, 4/5 for z.
   */
  namespace MeshGeneration
  {
    /// A box [lower, upper] split into simplices with the given number of
    /// (quadrilateral/hexahedral) subdivisions per direction.
    template <int dim>
    void
    make_box(const Point<dim>                &lower,
             const Point<dim>                &upper,
             const std::vector<unsigned int> &subdivisions,
             Triangulation<dim>              &triangulation);

    /// Read a Gmsh .msh file of triangles (2D) or tetrahedra (3D). Physical
    /// boundary tags become boundary ids.
    template <int dim>
    void
    read_gmsh(const std::string &file_name, Triangulation<dim> &triangulation);

    /// Extrude a 2D triangulation by @p thickness in z with one layer and
    /// split every prism into three tetrahedra with a rule that depends only
    /// on global vertex numbers, so neighbouring prisms match. Boundary ids:
    /// the lateral faces keep the id of the 2D edge they come from, the faces
    /// at z = 0 and z = thickness get ids 4 and 5.
    void
    extrude_to_tetrahedra(const Triangulation<2> &triangulation_2d,
                          const double            thickness,
                          Triangulation<3>       &triangulation_3d);

    /// Set boundary ids 0..2*dim-1 on the faces that lie on the planes of
    /// the bounding box (x = min, x = max, y = min, ...).
    template <int dim>
    void
    colorize_bounding_box(Triangulation<dim> &triangulation);
  } // namespace MeshGeneration
} // namespace fsgmpm

#endif
