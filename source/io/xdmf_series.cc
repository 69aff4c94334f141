#include <deal.II/base/exceptions.h>
#include <deal.II/base/hdf5.h>
#include <deal.II/base/mpi.h>

#include <fsgmpm/io/hdf5_setup.h>
#include <fsgmpm/parallel/process_count.h>

#include <fsgmpm/io/atomic_file.h>
#include <fsgmpm/io/xdmf_series.h>

#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <sstream>

namespace fsgmpm
{
  using namespace dealii;

  namespace
  {
    unsigned int
    nodes_per_cell(const XdmfSeries::CellType type)
    {
      return type == XdmfSeries::CellType::vertex
               ? 1
               : (type == XdmfSeries::CellType::line ? 2 : 3);
    }

    std::string
    file_name(const std::string &base_name, const unsigned int index)
    {
      std::ostringstream name;
      name << base_name << "_" << std::setw(5) << std::setfill('0') << index
           << ".h5";
      return name.str();
    }

    /// A dataset of @p total_rows x @p columns values, of which @p values
    /// are the rows from @p offset on; false if HDF5 failed (deal.II's
    /// wrappers do not throw then; Hdf5ErrorWatch tells). In a file
    /// opened on several processes this is collective: every process
    /// writes its rows (or none) in one parallel write.
    template <typename Number>
    bool
    write_table(HDF5::File                &file,
                const std::string         &name,
                const std::vector<Number> &values,
                const unsigned int         columns,
                const bool                 parallel,
                const hsize_t              offset,
                const hsize_t              total_rows)
    {
      const hsize_t        rows = values.size() / columns;
      const Hdf5ErrorWatch errors;
      try
        {
          auto dataset = file.create_dataset<Number>(
            name,
            columns == 1 ? std::vector<hsize_t>{total_rows}
                         : std::vector<hsize_t>{total_rows, hsize_t(columns)});
          if (!parallel)
            dataset.write(values);
          else if (rows > 0)
            dataset.write_hyperslab(
              values,
              columns == 1 ? std::vector<hsize_t>{offset}
                           : std::vector<hsize_t>{offset, 0},
              columns == 1 ? std::vector<hsize_t>{rows}
                           : std::vector<hsize_t>{rows, hsize_t(columns)});
          else
            dataset.template write_none<Number>();
        }
      catch (...)
        {
          return false;
        }
      return !errors.failed();
    }
  } // namespace



  XdmfSeries::XdmfSeries(const std::string &directory,
                         const std::string &base_name,
                         const MPI_Comm     communicator)
    : directory(directory)
    , base_name(base_name)
    , communicator(communicator)
  {}



  void
  XdmfSeries::write(const double                     time,
                    const std::vector<double>       &positions,
                    const CellType                   type,
                    const std::vector<unsigned int> &connectivity,
                    const std::vector<Field>        &fields)
  {
    const bool parallel = Parallel::n_processes(communicator) > 1;
    const bool root
      = !parallel || Utilities::MPI::this_mpi_process(communicator) == 0;
    AssertThrow(!parallel || (type == CellType::vertex && connectivity.empty()),
                ExcMessage("Only points are written by several processes "
                           "into one HDF5 file (the membrane and the grid are "
                           "written by process 0)."));
    // This process's vertices are rows [offset, offset + n) of the file's.
    const unsigned long long n_local = positions.size() / 3;
    const auto [offset, total]
      = Parallel::offset_and_total(n_local, communicator);
    std::vector<unsigned int> cells = connectivity;
    if (type == CellType::vertex && cells.empty())
      for (unsigned long long i = 0; i < n_local; ++i)
        cells.push_back(offset + i);
    const unsigned int n_nodes = total;
    const unsigned int n_cells
      = parallel ? n_nodes : cells.size() / nodes_per_cell(type);
    // HDF5 datasets cannot be empty: a step without nodes is not written
    // (the same decision on every process: the totals are global).
    if (n_nodes == 0 || n_cells == 0)
      return;

    const std::string name = file_name(base_name, steps.size());
    const std::string path = directory + "/" + name;
    const std::string tmp  = path + ".tmp";
    prepare_hdf5();
    for (const auto &f : fields)
      AssertThrow(f.values.size()
                    == f.n_components
                         * (f.on_cells ? cells.size() / nodes_per_cell(type)
                                       : n_local),
                  ExcInternalError());
    {
      // An HDF5::File destroyed while an exception is in flight aborts the
      // program: write, close, then report.
      auto file
        = parallel
            ? std::make_unique<HDF5::File>(tmp,
                                           HDF5::File::FileAccessMode::create,
                                           communicator)
            : std::make_unique<HDF5::File>(tmp,
                                           HDF5::File::FileAccessMode::create);
      // Every table is written even after one failed: in parallel each is
      // a collective call that every process must make, or they would wait
      // for one another forever.
      bool ok
        = write_table(*file, "nodes", positions, 3, parallel, offset, total);
      ok = write_table(*file,
                       "cells",
                       cells,
                       nodes_per_cell(type),
                       parallel,
                       offset,
                       n_cells)
           && ok;
      for (const auto &f : fields)
        ok = write_table(*file,
                         f.name,
                         f.values,
                         f.n_components,
                         parallel,
                         offset,
                         f.on_cells ? n_cells : n_nodes)
             && ok;
      {
        // A full disk may show only when the file is closed.
        const Hdf5ErrorWatch errors;
        file.reset();
        ok = ok && !errors.failed();
      }
      if (parallel)
        ok = Utilities::MPI::min(int(ok), communicator) == 1;
      if (!ok && root)
        std::remove(tmp.c_str());
      AssertThrow(ok,
                  ExcMessage("Writing <" + path
                             + "> failed (is the disk full?)."));
    }
    // Every process has closed the file before process 0 renames it.
    bool renamed = !root || std::rename(tmp.c_str(), path.c_str()) == 0;
    if (parallel)
      renamed = Utilities::MPI::min(int(renamed), communicator) == 1;
    AssertThrow(renamed,
                ExcMessage("Cannot rename <" + tmp + "> to <" + path + ">."));

    steps.push_back({time, n_nodes, n_cells});
    cell_type = type;
    layout.clear();
    for (const auto &f : fields)
      layout.push_back({f.name, f.n_components, f.on_cells, {}});
    if (root)
      write_xdmf();
  }



  void
  XdmfSeries::write_xdmf() const
  {
    const char *topology
      = cell_type == CellType::vertex
          ? "Polyvertex"
          : (cell_type == CellType::line ? "Polyline" : "Triangle");
    write_file_atomically(
      directory + "/" + base_name + ".xdmf", [&](std::ostream &out) {
        out << "<?xml version=\"1.0\" ?>\n"
            << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
            << "<Xdmf Version=\"2.0\">\n<Domain>\n"
            << "<Grid Name=\"" << base_name
            << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
        out << std::setprecision(17);
        for (unsigned int s = 0; s < steps.size(); ++s)
          {
            const auto       &r  = steps[s];
            const std::string h5 = file_name(base_name, s);
            out << "<Grid Name=\"" << base_name << "\" GridType=\"Uniform\">\n"
                << "  <Time Value=\"" << r.time << "\"/>\n"
                << "  <Geometry GeometryType=\"XYZ\">\n"
                << "    <DataItem Dimensions=\"" << r.n_nodes
                << " 3\" NumberType=\"Float\" Precision=\"8\" "
                   "Format=\"HDF\">"
                << h5 << ":/nodes</DataItem>\n  </Geometry>\n"
                << "  <Topology TopologyType=\"" << topology
                << "\" NumberOfElements=\"" << r.n_cells
                << "\" NodesPerElement=\"" << nodes_per_cell(cell_type)
                << "\">\n    <DataItem Dimensions=\"" << r.n_cells << " "
                << nodes_per_cell(cell_type)
                << "\" NumberType=\"UInt\" Precision=\"4\" Format=\"HDF\">"
                << h5 << ":/cells</DataItem>\n  </Topology>\n";
            for (const auto &f : layout)
              {
                const unsigned int n = f.on_cells ? r.n_cells : r.n_nodes;
                out << "  <Attribute Name=\"" << f.name << "\" AttributeType=\""
                    << (f.n_components == 1
                          ? "Scalar"
                          : (f.n_components == 9 ? "Tensor" : "Vector"))
                    << "\" Center=\"" << (f.on_cells ? "Cell" : "Node")
                    << "\">\n    <DataItem Dimensions=\"" << n;
                if (f.n_components > 1)
                  out << " " << f.n_components;
                out << "\" NumberType=\"Float\" Precision=\"8\" "
                       "Format=\"HDF\">"
                    << h5 << ":/" << f.name << "</DataItem>\n  </Attribute>\n";
              }
            out << "</Grid>\n";
          }
        out << "</Grid>\n</Domain>\n</Xdmf>\n";
      });
  }



  std::vector<double>
  XdmfSeries::records() const
  {
    std::vector<double> r;
    for (const auto &s : steps)
      r.insert(r.end(), {s.time, double(s.n_nodes), double(s.n_cells)});
    return r;
  }



  void
  XdmfSeries::restore(const std::vector<double> &records)
  {
    AssertThrow(records.size() % 3 == 0,
                ExcMessage("The checkpoint's output series is damaged."));
    steps.clear();
    for (unsigned int k = 0; k < records.size(); k += 3)
      steps.push_back({records[k],
                       static_cast<unsigned int>(records[k + 1]),
                       static_cast<unsigned int>(records[k + 2])});
  }
} // namespace fsgmpm
