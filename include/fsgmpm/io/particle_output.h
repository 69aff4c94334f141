#ifndef fsgmpm_io_particle_output_h
#define fsgmpm_io_particle_output_h

#include <deal.II/base/data_out_base.h>

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/nodal_fields.h>
#include <fsgmpm/io/xdmf_series.h>
#include <fsgmpm/particles/particle_store.h>

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
    /// Build the patches from the current state of @p particles; with
    /// @p grid and @p nodes also the vorticity (z component of curl v) of
    /// the nodal velocities of each point's cell (paper Fig. 12), zero
    /// without.
    void
    /// With @p vorticity (one value per point, e.g. computed where the
    /// nodal velocities are), that is written instead.
    build_patches(const ParticleStore<dim>  &particles,
                  const BackgroundGrid<dim> *grid      = nullptr,
                  const NodalFields<dim>    *nodes     = nullptr,
                  const std::vector<double> *vorticity = nullptr);

    /// The vorticity omega_z = dv_y/dx - dv_x/dy of the nodal velocity
    /// field in cell @p c (constant on a linear simplex).
    static double
    vorticity(const BackgroundGrid<dim> &grid,
              const NodalFields<dim>    &nodes,
              const unsigned int         c);

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
  };

  /**
   * Writes numbered VTU files and keeps the PVD collection of all of them
   * up to date (both written atomically).
   */
  class PvdSeries
  {
  public:
    PvdSeries(const std::string &directory, const std::string &base_name);

    /// File name (without directory) for the next output and records it.
    std::string
    next_file(const double time);

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
    std::string                                 directory, base_name;
    std::vector<std::pair<double, std::string>> records;
  };
} // namespace fsgmpm

#endif
