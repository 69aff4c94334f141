#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>

#include <fsgmpm/grid/gmsh_reader.h>

#include <fstream>
#include <sstream>

namespace fsgmpm
{
  template <int dim, int spacedim>
  void
  read_gmsh_file(const std::string            &file_name,
                 const std::string            &parameter,
                 const std::string            &what,
                 Triangulation<dim, spacedim> &triangulation)
  {
    std::ifstream in(file_name);
    AssertThrow(in.good(),
                ExcMessage(parameter + ": cannot open the Gmsh file <"
                           + file_name + ">."));
    GridIn<dim, spacedim> grid_in;
    grid_in.attach_triangulation(triangulation);
    // deal.II's reader throws its own exceptions (or standard ones from
    // the stream) for files that are not Gmsh meshes: say which parameter.
    try
      {
        grid_in.read_msh(in);
      }
    catch (ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        AssertThrow(false,
                    ExcMessage(parameter + " <" + file_name
                               + "> is not a readable Gmsh mesh of " + what
                               + ": " + Utilities::trim(info.str())));
      }
    catch (std::exception &e)
      {
        AssertThrow(false,
                    ExcMessage(parameter + " <" + file_name
                               + "> is not a readable Gmsh mesh: " + e.what()));
      }
    AssertThrow(triangulation.n_active_cells() > 0,
                ExcMessage(parameter + " <" + file_name + "> holds no cells."));
  }

  template void
  read_gmsh_file<2, 2>(const std::string &,
                       const std::string &,
                       const std::string &,
                       Triangulation<2, 2> &);
  template void
  read_gmsh_file<3, 3>(const std::string &,
                       const std::string &,
                       const std::string &,
                       Triangulation<3, 3> &);
} // namespace fsgmpm
