#ifndef fsgmpm_grid_mesh_generation_h
#define fsgmpm_grid_mesh_generation_h

#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <deal.II/base/types.h>

#include <array>
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

    /// A simplex mesh as two arrays: vertex positions, and each cell's
    /// vertex numbers in deal.II's CellData order.
    template <int dim>
    struct SimplexMesh
    {
      std::vector<Point<dim>>                        vertices;
      std::vector<std::array<unsigned int, dim + 1>> cells;
    };

    /**
     * make_box()'s mesh without a Triangulation: the vertices and cells
     * that GridGenerator::subdivided_hyper_rectangle_with_simplices() hands
     * to Triangulation::create_triangulation(), in the same order (rows of
     * vertices; 2 triangles per square, 5 tetrahedra per cube alternating
     * between two patterns). Creating deal.II's mesh holds about 300 B per
     * triangle at its peak, against about 20 B here: on one process of an MPI
     * run, or of a large serial one, it was the largest memory of the run.
     * BackgroundGrid(const SimplexMesh &) builds the grid of make_box()
     * from it, array for array (tested).
     */
    template <int dim>
    SimplexMesh<dim>
    box_simplices(const Point<dim>                &lower,
                  const Point<dim>                &upper,
                  const std::vector<unsigned int> &subdivisions);

    /// colorize_bounding_box()'s rule for one boundary face: the id of the
    /// plane of the bounding box [@p lower, @p upper] that the face's centre
    /// @p center lies on, or @p id if it lies on none.
    template <int dim>
    types::boundary_id
    bounding_box_id(const Point<dim>  &center,
                    const Point<dim>  &lower,
                    const Point<dim>  &upper,
                    types::boundary_id id);

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

    /// extrude_to_tetrahedra()'s vertices and cells without a Triangulation
    /// (each prism's three tetrahedra in the same order). Of a box
    /// (box_simplices()), BackgroundGrid(const SimplexMesh &) gives the grid
    /// of extrude_to_tetrahedra() on make_box(), boundary ids included (the
    /// box's sides are the bounding box's planes; tested).
    SimplexMesh<3>
    extrude_simplices(const SimplexMesh<2> &base, const double thickness);

    /// Set boundary ids 0..2*dim-1 on the faces that lie on the planes of
    /// the bounding box (x = min, x = max, y = min, ...).
    template <int dim>
    void
    colorize_bounding_box(Triangulation<dim> &triangulation);
  } // namespace MeshGeneration
} // namespace fsgmpm

#endif
