#ifndef fsgmpm_io_particle_output_h
#define fsgmpm_io_particle_output_h

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/nodal_fields.h>
#include <fsgmpm/io/xdmf_series.h>
#include <fsgmpm/particles/particle_store.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace fsgmpm
{
  /**
   * Output of the material points: one VTU file (or one piece per MPI
   * process and a .pvtu record), or a step of an HDF5 + XDMF series. The
   * store is not deal.II's ParticleHandler, and deal.II's DataOutBase
   * writes every field as Float32 scalars or vectors, so the points are
   * written here: one vertex cell per point, the stress as one 3 x 3
   * tensor (sigma_zz of plane strain included; ParaView's tensor
   * filters and glyphs take it whole), the integer fields (material_id,
   * body_id, free_surface, yielding) as Int32, the rest as Float32.
   */
  template <int dim>
  class ParticleOutput
  {
  public:
    /// The fields of a point that come from the nodal values around it:
    /// the vorticity and the pressure of the projected stress.
    using NodalPointFields = std::array<double, 2>;

    /// One array of point data: n_components (1, 3 or 9) values per
    /// point, point after point.
    struct Field
    {
      std::string         name;
      unsigned int        n_components = 1;
      bool                integer      = false;
      std::vector<double> values;
    };

    /// Collect the fields from the current state of @p particles; with
    /// @p grid and @p nodes also nodal_point_fields() of each point (MPI:
    /// the nodal values are exact around the points a process owns), zero
    /// vorticity and the point's own pressure without.
    void
    build_patches(const ParticleStore<dim>  &particles,
                  const BackgroundGrid<dim> *grid  = nullptr,
                  const NodalFields<dim>    *nodes = nullptr);

    /// Point @p p's vorticity omega_z = dv_y/dx - dv_x/dy of the nodal
    /// velocity field in its cell (constant on a linear simplex; paper
    /// Fig. 12), and the pressure of the projected stress there: the mean
    /// of its dim normal components (in 2D the in-plane mean, as the grid
    /// sees no sigma_zz; for a fluid it is the pressure). With the nodal
    /// stress projection, s_j = volume_stress_j / support_volume_j
    /// interpolated to the point, what the grid integrates (the points'
    /// own pressures carry a sub-cell pattern the projection does not
    /// see);
    /// with the points' own stresses (Eq. 3), the point's.
    static NodalPointFields
    nodal_point_fields(const BackgroundGrid<dim> &grid,
                       const NodalFields<dim>    &nodes,
                       const ParticleStore<dim>  &particles,
                       const unsigned int         p);

    /// The collected points as a compressed binary VTU file.
    void
    write_vtu(std::ostream &out) const;

    /// The .pvtu record naming the @p pieces (the VTU files of the
    /// processes); the fields declared are this process's.
    void
    write_pvtu_record(std::ostream                   &out,
                      const std::vector<std::string> &pieces) const;

    /// The collected points as a step of an HDF5 + XDMF series
    /// (Output/Format = hdf5): the same fields as the VTU files.
    void
    write_xdmf(XdmfSeries &series, const double time) const;

    /// The point data in the order written.
    const std::vector<Field> &
    get_fields() const
    {
      return fields;
    }

  private:
    /// The positions, padded to three coordinates.
    std::vector<double> positions;
    std::vector<Field>  fields;
  };

  /**
   * Writes numbered VTU files and keeps the PVD collection of all of them
   * up to date (both written atomically).
   */
  class PvdSeries
  {
  public:
    /// Files BASE_NNNNN@p extension (".vtu", or ".pvtu": the record of one
    /// piece per MPI process).
    PvdSeries(const std::string &directory,
              const std::string &base_name,
              const std::string &extension = ".vtu");

    /// File name (without directory) for the next output and records it.
    std::string
    next_file(const double time);

    /// Continue a series from times(): the files written before a
    /// checkpoint, each under the extension it has on disk (a serial run's
    /// .vtu files continued by several processes, or the other way round).
    void
    restore(const std::vector<double> &times);

    /// Rewrite the .pvd file.
    void
    write_pvd() const;

    /// The times of the files written so far (a restart re-creates the
    /// series by calling next_file() with them).
    std::vector<double>
    times() const
    {
      std::vector<double> t;
      for (const auto &r : records)
        t.push_back(r.first);
      return t;
    }

  private:
    std::string                                 directory, base_name, extension;
    std::vector<std::pair<double, std::string>> records;
  };
} // namespace fsgmpm

#endif
