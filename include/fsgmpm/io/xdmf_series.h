#ifndef fsgmpm_io_xdmf_series_h
#define fsgmpm_io_xdmf_series_h

#include <deal.II/base/mpi.h>

#include <array>
#include <string>
#include <vector>

namespace fsgmpm
{
  /**
   * Output in HDF5 + XDMF (Output/Format = hdf5), readable by ParaView and
   * VisIt: one HDF5 file per output step, BASE_NNNNN.h5, with the node
   * positions (n x 3, z = 0 in 2D), the connectivity and one dataset per
   * field, and the collection BASE.xdmf that lists them in time. Both are
   * written atomically (temporary name, then rename); the HDF5 files use
   * deal.II's HDF5 wrappers.
   */
  class XdmfSeries
  {
  public:
    /// Cells of one kind: points (1 node each), line segments (2: cables)
    /// or triangles (3: 3D membranes).
    enum class CellType
    {
      vertex,
      line,
      triangle
    };

    struct Field
    {
      std::string name;
      /// 1 (scalar), 3 (vector) or 9 (a 3 x 3 tensor, row by row).
      unsigned int n_components = 1;
      /// Values at the cells instead of the nodes.
      bool on_cells = false;
      /// n_components values per node (or cell), node after node.
      std::vector<double> values;
    };

    /// With a @p communicator of several processes, write() is collective:
    /// every process passes its own vertices (the points it owns), and one
    /// file per step holds them all, rank after rank, written through
    /// MPI-IO (parallel HDF5); process 0 writes BASE.xdmf.
    XdmfSeries(const std::string &directory,
               const std::string &base_name,
               const MPI_Comm     communicator = MPI_COMM_SELF);

    /// Write the step at @p time: @p positions n x 3 (node after node),
    /// @p connectivity (nodes_per_cell numbers per cell; empty for
    /// vertices: cell i is node i), the fields; then rewrite BASE.xdmf.
    void
    write(const double                     time,
          const std::vector<double>       &positions,
          const CellType                   cell_type,
          const std::vector<unsigned int> &connectivity,
          const std::vector<Field>        &fields);

    /// (time, nodes, cells) of every step written, for a checkpoint.
    std::vector<double>
    records() const;

    /// Continue a series from records(): the steps written before a
    /// checkpoint (BASE.xdmf is rewritten by the next write()).
    void
    restore(const std::vector<double> &records);

  private:
    void
    write_xdmf() const;

    std::string directory, base_name;
    MPI_Comm    communicator;
    struct Record
    {
      double       time;
      unsigned int n_nodes, n_cells;
    };
    std::vector<Record> steps;
    CellType            cell_type = CellType::vertex;
    /// Names, components and centring of the fields (their values are in
    /// the HDF5 files).
    std::vector<Field> layout;
  };
} // namespace fsgmpm

#endif
