#ifndef fsgmpm_io_membrane_output_h
#define fsgmpm_io_membrane_output_h

#include <fsgmpm/membrane/membrane.h>

#include <string>

namespace fsgmpm
{
  /// VTU of the membrane: its elements (lines in 2D, triangles in 3D) with
  /// the tension (N/m) and current/rest length ratio as cell data and the
  /// node velocity as point data. Written atomically.
  class XdmfSeries;

  template <int dim>
  void
  write_membrane_vtu(const Membrane<dim> &membrane, const std::string &file);

  /// The membrane's step in HDF5 + XDMF (Output/Format = hdf5): the same
  /// fields as the VTU (tension and stretch per element, node velocity).
  template <int dim>
  void
  write_membrane_xdmf(const Membrane<dim> &membrane,
                      XdmfSeries          &series,
                      const double         time);

  /// The node positions in element order as CSV "x,y" (2D) or "x,y,z",
  /// written atomically (the final shape of a geotube).
  template <int dim>
  void
  write_membrane_shape_csv(const Membrane<dim> &membrane,
                           const std::string   &file);

} // namespace fsgmpm

#endif
