#ifndef fsgmpm_io_run_output_h
#define fsgmpm_io_run_output_h

#include <deal.II/base/mpi.h>

#include <fsgmpm/grid/background_grid.h>
#include <fsgmpm/grid/nodal_fields.h>
#include <fsgmpm/io/particle_output.h>
#include <fsgmpm/io/xdmf_series.h>
#include <fsgmpm/membrane/membrane.h>
#include <fsgmpm/particles/particle_store.h>

#include <array>
#include <string>
#include <vector>

namespace fsgmpm
{
  /**
   * The field output of a run (Output subsection): the points, the grid and
   * the membrane as one file each per output time, in series that ParaView
   * opens as one (VTU files in PVD collections, or HDF5 files in XDMF
   * collections with Output/Format = hdf5). Every file is written under a
   * temporary name and renamed when complete, and the collection is
   * rewritten after each file, so a run stopped at any moment leaves
   * readable output.
   */
  template <int dim>
  class RunOutput
  {
  public:
    struct Settings
    {
      std::string directory;
      /// Output/Format = hdf5 (else VTU).
      bool hdf5 = false;
      /// Output/Membrane output = finite elements: the membrane through
      /// deal.II's DataOut (VTU only).
      bool membrane_finite_elements = false;
      bool write_particles          = true;
      bool write_grid               = false;
      /// MPI: the processes that write the points together, each its own
      /// (one HDF5 file per step through MPI-IO, or a PVTU record of one
      /// VTU piece per process); process 0 writes the membrane, the grid
      /// and the collections.
      MPI_Comm communicator = MPI_COMM_SELF;
    };

    /// The series written so far, for a checkpoint: the times of the
    /// particle, grid and membrane PVD series and the records of the
    /// particle and membrane XDMF series.
    struct State
    {
      std::array<std::vector<double>, 3> series_times;
      std::array<std::vector<double>, 2> xdmf_records;
    };

    explicit RunOutput(const Settings &settings);

    /// Remove the field output of an earlier run from the directory (a run
    /// that does not continue one).
    void
    remove_previous_output() const;

    /// Write the state at @p time (@p membrane may be null). Collective
    /// over Settings::communicator: every process passes the points it
    /// owns and @p nodes exact around them (for the points' vorticity and
    /// projected pressure); process 0 writes its @p membrane and the grid
    /// with @p grid_nodes if given (MPI: every node's mass and velocity as
    /// the process that counts it has them), else with @p nodes. The grid
    /// written is @p whole_grid if given (@p grid is then process 0's
    /// window of it, and @p grid_nodes are numbered in @p whole_grid).
    void
    write(const double               time,
          const ParticleStore<dim>  &particles,
          const BackgroundGrid<dim> &grid,
          const NodalFields<dim>    &nodes,
          const Membrane<dim>       *membrane,
          const NodalFields<dim>    *grid_nodes = nullptr,
          const BackgroundGrid<dim> *whole_grid = nullptr);

    State
    state() const;
    /// Continue the series of a checkpointed run: the collections as they
    /// were at the checkpoint; files written after it are written again
    /// under the same names.
    void
    restore(const State &state);

  private:
    /// MPI, VTU: this process's @p n_local points as its piece of the
    /// PVTU file @p record (collective); process 0 writes the record.
    void
    write_pieces(const std::string &record, const unsigned int n_local);

    /// After a restart: remove the numbered output files past the series
    /// of @p state (process 0).
    void
    remove_files_after(const State &state) const;

    Settings            settings;
    bool                parallel, root;
    ParticleOutput<dim> particle_output;
    PvdSeries           particle_series, grid_series, membrane_series;
    XdmfSeries          particle_xdmf, membrane_xdmf;
  };
} // namespace fsgmpm

#endif
