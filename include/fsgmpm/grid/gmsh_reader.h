#ifndef fsgmpm_grid_gmsh_reader_h
#define fsgmpm_grid_gmsh_reader_h

#include <deal.II/grid/tria.h>

#include <string>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * Read the Gmsh file @p file_name into @p triangulation (the background
   * mesh, dim = spacedim = 2 or 3; membrane surfaces, which may be of
   * second order, have their own reader, membrane/gmsh_surface.h). Any
   * failure (a missing or unreadable file, a file that is not a mesh, a
   * mesh of other cells or dimension, no cells) throws an ExcMessage that
   * names the parameter @p parameter (e.g. "Grid/Mesh file") and says that
   * @p what (e.g. "2D simplices") was expected.
   */
  template <int dim, int spacedim>
  void
  read_gmsh_file(const std::string            &file_name,
                 const std::string            &parameter,
                 const std::string            &what,
                 Triangulation<dim, spacedim> &triangulation);
} // namespace fsgmpm

#endif
