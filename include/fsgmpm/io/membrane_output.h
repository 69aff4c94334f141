#ifndef fsgmpm_io_membrane_output_h
#define fsgmpm_io_membrane_output_h

#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/particles/particle_store.h>

#include <map>
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

  /**
   * Geotube monitors (issue 5, SPEC 6): height and width (max - min of the
   * membrane nodes), contact_width (extent of the nodes within
   * @p contact_tolerance of the lowest node), max_tension and mean_tension
   * (length-weighted), top_pressure and bottom_pressure (a least-squares line
   * of particle pressure against y over the central strip |x - x_c| <=
   * strip_width/2, evaluated at the membrane's top and bottom),
   * membrane_length, enclosed_area (2D), fluid_volume (sum of particle
   * volumes; per metre in 2D) and particles_outside, the last three over
   * the points of body @p fill_body only (the pressure strip too).
   */
  template <int dim>
  std::map<std::string, double>
  membrane_monitors(const Membrane<dim>      &membrane,
                    const ParticleStore<dim> &particles,
                    const double              contact_tolerance,
                    const double              strip_width,
                    const unsigned int        fill_body = 0);

  /// Names of the columns membrane_monitors() provides.
  const std::vector<std::string> &
  membrane_monitor_names();
} // namespace fsgmpm

#endif
