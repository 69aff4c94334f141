#ifndef fsgmpm_io_particle_output_h
#define fsgmpm_io_particle_output_h

#include <deal.II/base/data_out_base.h>

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
   * VTU output of the material points. The store is not deal.II's
   * ParticleHandler, so it provides its own patches (one vertex each) to
   * DataOutInterface<0,dim>.
   */
  template <int dim>
  class ParticleOutput : public DataOutInterface<0, dim>
  {
  public:
    /// The fields of a point that come from the nodal values around it:
    /// the vorticity and the pressure of the projected stress.
    using NodalPointFields = std::array<double, 2>;

    /// Build the patches from the current state of @p particles; with
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

    /// The patches as a step of an HDF5 + XDMF series (Output/Format =
    /// hdf5): the same fields as the VTU files, velocity as a 3-vector.
    void
    write_xdmf(XdmfSeries &series, const double time) const;

  private:
    const std::vector<DataOutBase::Patch<0, dim>> &
    get_patches() const override
    {
      return patches;
    }
    std::vector<std::string>
    get_dataset_names() const override;
    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
    get_nonscalar_data_ranges() const override;

    std::vector<DataOutBase::Patch<0, dim>> patches;
    /// Whether the points keep their initial positions (a displacement
    /// field follows the others).
    bool with_displacement = false;
    /// Whether the points keep their plastic state (plastic_strain and
    /// yielding fields).
    bool with_plasticity = false;
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
