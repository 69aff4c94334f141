#ifndef fsgmpm_membrane_gmsh_surface_h
#define fsgmpm_membrane_gmsh_surface_h

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <string>
#include <utility>

namespace fsgmpm
{
  using namespace dealii;

  /// The middle points of a curved surface mesh's edges, keyed by the
  /// edge's two vertex indices (smaller first) in its Triangulation.
  using EdgeMiddlePoints
    = std::map<std::pair<unsigned int, unsigned int>, Point<3>>;

  /**
   * Read a membrane surface from the ASCII Gmsh file @p file_name (format
   * 2.2 or 4.1) of 3-node or 6-node triangles (Gmsh element types 2 and 9;
   * lines and points of physical groups are skipped). The triangles'
   * corners make @p surface; for 6-node (second-order) triangles the edge
   * nodes go to @p middle_points, so that a degree-2 membrane takes the
   * curved geometry Gmsh meshed (deal.II 9.4's GridIn reads first-order
   * cells only). Any other element type, a binary file, a node that is
   * referenced but not defined, a mix of first- and second-order triangles
   * or an edge whose two triangles give different middle nodes throws an
   * ExcMessage naming @p parameter.
   */
  void
  read_gmsh_surface(const std::string   &file_name,
                    const std::string   &parameter,
                    Triangulation<2, 3> &surface,
                    EdgeMiddlePoints    &middle_points);
} // namespace fsgmpm

#endif
