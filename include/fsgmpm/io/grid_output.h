#ifndef fsgmpm_io_grid_output_h
#define fsgmpm_io_grid_output_h

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/nodal_fields.h>

#include <string>

namespace fsgmpm
{
  /// Write the background grid with the nodal mass and velocity (VTU,
  /// atomically).
  template <int dim>
  void
  write_grid_vtu(const BackgroundGrid<dim> &grid,
                 const NodalFields<dim>    &nodes,
                 const std::string         &file_name);
} // namespace fsgmpm

#endif
