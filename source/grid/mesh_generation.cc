#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <fsgmpm/grid/gmsh_reader.h>
#include <fsgmpm/grid/mesh_generation.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace fsgmpm
{
  namespace MeshGeneration
  {
    namespace
    {
      template <int dim>
      void
      check_box(const Point<dim>                &lower,
                const Point<dim>                &upper,
                const std::vector<unsigned int> &subdivisions)
      {
        AssertThrow(subdivisions.size() == dim,
                    ExcMessage("Grid/Subdivisions needs one entry per "
                               "coordinate direction ("
                               + std::to_string(dim) + ")."));
        for (unsigned int d = 0; d < dim; ++d)
          {
            AssertThrow(upper[d] > lower[d],
                        ExcMessage("Grid/Upper corner must be larger than "
                                   "Grid/Lower corner in every direction."));
            AssertThrow(subdivisions[d] > 0,
                        ExcMessage("Grid/Subdivisions must be positive."));
          }
      }
    } // namespace



    template <int dim>
    void
    make_box(const Point<dim>                &lower,
             const Point<dim>                &upper,
             const std::vector<unsigned int> &subdivisions,
             Triangulation<dim>              &triangulation)
    {
      check_box(lower, upper, subdivisions);
      GridGenerator::subdivided_hyper_rectangle_with_simplices(triangulation,
                                                               subdivisions,
                                                               lower,
                                                               upper);
      colorize_bounding_box(triangulation);
    }



    template <int dim>
    SimplexMesh<dim>
    box_simplices(const Point<dim>                &lower,
                  const Point<dim>                &upper,
                  const std::vector<unsigned int> &subdivisions)
    {
      check_box(lower, upper, subdivisions);
      // The cells are numbered by unsigned int, as deal.II's: refuse a box
      // that would overflow them rather than wrap around.
      std::uint64_t n_boxes = 1, n_vertices = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          n_boxes *= subdivisions[d];
          n_vertices *= subdivisions[d] + 1;
        }
      const unsigned int per_box = (dim == 2 ? 2 : 5);
      AssertThrow(n_boxes * per_box < std::numeric_limits<unsigned int>::max()
                    && n_vertices < std::numeric_limits<unsigned int>::max(),
                  ExcMessage("Grid/Subdivisions give more than 2^32 - 1 "
                             "cells or vertices; use a coarser grid."));

      // deal.II 9.4's subdivided_hyper_rectangle_with_simplices(), step by
      // step: the same spacing, vertex order and cell patterns.
      Tensor<1, dim> dx;
      for (unsigned int d = 0; d < dim; ++d)
        dx[d] = (upper[d] - lower[d]) / subdivisions[d];
      // Vertices per row and per column; layers of boxes (1 in 2D).
      const unsigned int nx = subdivisions[0] + 1, ny = subdivisions[1] + 1;
      const unsigned int n_layers = (dim == 3 ? subdivisions[dim - 1] : 1);

      SimplexMesh<dim> mesh;
      mesh.vertices.reserve(n_vertices);
      mesh.cells.reserve(n_boxes * per_box);
      for (unsigned int k = 0; k < n_layers + (dim == 3); ++k)
        for (unsigned int j = 0; j < ny; ++j)
          for (unsigned int i = 0; i < nx; ++i)
            {
              Point<dim> x;
              x[0] = lower[0] + dx[0] * i;
              x[1] = lower[1] + dx[1] * j;
              if constexpr (dim == 3)
                x[2] = lower[2] + dx[2] * k;
              mesh.vertices.push_back(x);
            }

      for (unsigned int k = 0; k < n_layers; ++k)
        for (unsigned int j = 0; j + 1 < ny; ++j)
          for (unsigned int i = 0; i + 1 < nx; ++i)
            {
              // The box's corners, x fastest, then y, then z.
              std::array<unsigned int, 8> q;
              for (unsigned int c = 0; c < (1u << dim); ++c)
                q[c] = ((k + (c >> 2)) * ny + j + ((c >> 1) & 1)) * nx + i
                       + (c & 1);
              if constexpr (dim == 2)
                {
                  mesh.cells.push_back({{q[0], q[1], q[2]}});
                  mesh.cells.push_back({{q[3], q[2], q[1]}});
                }
              else if ((i + j + k) % 2 == 0)
                {
                  mesh.cells.push_back({{q[0], q[1], q[2], q[4]}});
                  mesh.cells.push_back({{q[2], q[1], q[3], q[7]}});
                  mesh.cells.push_back({{q[1], q[4], q[5], q[7]}});
                  mesh.cells.push_back({{q[2], q[4], q[7], q[6]}});
                  mesh.cells.push_back({{q[1], q[2], q[4], q[7]}});
                }
              else
                {
                  mesh.cells.push_back({{q[0], q[1], q[3], q[5]}});
                  mesh.cells.push_back({{q[0], q[3], q[2], q[6]}});
                  mesh.cells.push_back({{q[0], q[4], q[5], q[6]}});
                  mesh.cells.push_back({{q[3], q[5], q[7], q[6]}});
                  mesh.cells.push_back({{q[0], q[3], q[6], q[5]}});
                }
            }
      return mesh;
    }



    template <int dim>
    types::boundary_id
    bounding_box_id(const Point<dim>  &center,
                    const Point<dim>  &lower,
                    const Point<dim>  &upper,
                    types::boundary_id id)
    {
      const double size = lower.distance(upper);
      for (unsigned int d = 0; d < dim; ++d)
        if (std::abs(center[d] - lower[d]) < 1e-10 * size)
          id = 2 * d;
        else if (std::abs(center[d] - upper[d]) < 1e-10 * size)
          id = 2 * d + 1;
      return id;
    }



    template <int dim>
    void
    read_gmsh(const std::string &file_name, Triangulation<dim> &triangulation)
    {
      read_gmsh_file(file_name,
                     "Grid/Mesh file",
                     std::to_string(dim) + "D simplices",
                     triangulation);
      AssertThrow(triangulation.all_reference_cells_are_simplex(),
                  ExcMessage("Grid/Mesh file <" + file_name
                             + "> must contain only triangles (2D) or "
                               "tetrahedra (3D)."));
    }



    SimplexMesh<3>
    extrude_simplices(const SimplexMesh<2> &base, const double thickness)
    {
      AssertThrow(thickness > 0,
                  ExcMessage("The extrusion thickness must be positive."));
      const unsigned int nv = base.vertices.size();
      SimplexMesh<3>     mesh;
      mesh.vertices.resize(2 * nv);
      for (unsigned int i = 0; i < nv; ++i)
        {
          const Point<2> &x     = base.vertices[i];
          mesh.vertices[i]      = Point<3>(x[0], x[1], 0.);
          mesh.vertices[nv + i] = Point<3>(x[0], x[1], thickness);
        }
      mesh.cells.reserve(3 * base.cells.size());
      for (std::array<unsigned int, 3> t : base.cells)
        {
          std::sort(t.begin(), t.end());
          const unsigned int b0 = t[0], b1 = t[1], b2 = t[2];
          const unsigned int t0 = nv + t[0], t1 = nv + t[1], t2 = nv + t[2];
          // Each quadrilateral side (i < j) is cut by the diagonal from the
          // bottom of vertex i to the top of vertex j.
          const std::array<std::array<unsigned int, 4>, 3> tets
            = {{{{b0, b1, b2, t2}}, {{b0, b1, t1, t2}}, {{b0, t0, t1, t2}}}};
          for (auto tet : tets)
            {
              Tensor<2, 3> e;
              for (unsigned int k = 0; k < 3; ++k)
                for (unsigned int d = 0; d < 3; ++d)
                  e[d][k]
                    = mesh.vertices[tet[k + 1]][d] - mesh.vertices[tet[0]][d];
              if (determinant(e) < 0)
                std::swap(tet[2], tet[3]);
              mesh.cells.push_back(tet);
            }
        }
      return mesh;
    }



    void
    extrude_to_tetrahedra(const Triangulation<2> &tria_2d,
                          const double            thickness,
                          Triangulation<3>       &tria_3d)
    {
      SimplexMesh<2> base;
      base.vertices = tria_2d.get_vertices();
      for (const auto &cell : tria_2d.active_cell_iterators())
        {
          AssertThrow(cell->n_vertices() == 3,
                      ExcMessage("Only triangles can be extruded."));
          base.cells.push_back({{cell->vertex_index(0),
                                 cell->vertex_index(1),
                                 cell->vertex_index(2)}});
        }
      const unsigned int       nv   = base.vertices.size();
      const SimplexMesh<3>     mesh = extrude_simplices(base, thickness);
      std::vector<CellData<3>> cells(mesh.cells.size(), CellData<3>(4));
      for (unsigned int c = 0; c < cells.size(); ++c)
        for (unsigned int k = 0; k < 4; ++k)
          cells[c].vertices[k] = mesh.cells[c][k];
      tria_3d.clear();
      tria_3d.create_triangulation(mesh.vertices, cells, SubCellData());

      // Boundary ids: lateral faces from the 2D edges, z faces 4 and 5.
      std::map<std::pair<unsigned int, unsigned int>, types::boundary_id>
        edge_id;
      for (const auto &cell : tria_2d.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              auto a = cell->face(f)->vertex_index(0);
              auto b = cell->face(f)->vertex_index(1);
              edge_id[{std::min(a, b), std::max(a, b)}]
                = cell->face(f)->boundary_id();
            }
      for (const auto &cell : tria_3d.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto   face = cell->face(f);
              const double zc   = face->center()[2];
              if (std::abs(zc) < 1e-12 * thickness)
                face->set_boundary_id(4);
              else if (std::abs(zc - thickness) < 1e-12 * thickness)
                face->set_boundary_id(5);
              else
                {
                  std::vector<unsigned int> base;
                  for (unsigned int v = 0; v < 3; ++v)
                    {
                      const unsigned int i = face->vertex_index(v) % nv;
                      if (std::find(base.begin(), base.end(), i) == base.end())
                        base.push_back(i);
                    }
                  AssertThrow(base.size() == 2, ExcInternalError());
                  const auto it = edge_id.find(
                    {std::min(base[0], base[1]), std::max(base[0], base[1])});
                  AssertThrow(it != edge_id.end(), ExcInternalError());
                  face->set_boundary_id(it->second);
                }
            }
    }



    template <int dim>
    void
    colorize_bounding_box(Triangulation<dim> &triangulation)
    {
      const auto box = GridTools::compute_bounding_box(triangulation);
      const auto lo  = box.get_boundary_points().first;
      const auto hi  = box.get_boundary_points().second;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            cell->face(f)->set_boundary_id(bounding_box_id(
              cell->face(f)->center(), lo, hi, cell->face(f)->boundary_id()));
    }

    template void
    make_box<2>(const Point<2> &,
                const Point<2> &,
                const std::vector<unsigned int> &,
                Triangulation<2> &);
    template void
    make_box<3>(const Point<3> &,
                const Point<3> &,
                const std::vector<unsigned int> &,
                Triangulation<3> &);
    template SimplexMesh<2>
    box_simplices<2>(const Point<2> &,
                     const Point<2> &,
                     const std::vector<unsigned int> &);
    template SimplexMesh<3>
    box_simplices<3>(const Point<3> &,
                     const Point<3> &,
                     const std::vector<unsigned int> &);
    template types::boundary_id
    bounding_box_id<2>(const Point<2> &,
                       const Point<2> &,
                       const Point<2> &,
                       types::boundary_id);
    template types::boundary_id
    bounding_box_id<3>(const Point<3> &,
                       const Point<3> &,
                       const Point<3> &,
                       types::boundary_id);
    template void
    read_gmsh<2>(const std::string &, Triangulation<2> &);
    template void
    read_gmsh<3>(const std::string &, Triangulation<3> &);
    template void
    colorize_bounding_box<2>(Triangulation<2> &);
    template void
    colorize_bounding_box<3>(Triangulation<3> &);
  } // namespace MeshGeneration
} // namespace fsgmpm
