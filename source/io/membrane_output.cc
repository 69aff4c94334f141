#include <fsgmpm/io/atomic_file.h>
#include <fsgmpm/io/membrane_output.h>
#include <fsgmpm/io/vtu_arrays.h>
#include <fsgmpm/io/xdmf_series.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <iomanip>

namespace fsgmpm
{
  namespace
  {
    /// Length ratio (2D) or the square root of the area ratio (3D) of
    /// element @p e to its rest size.
    template <int dim>
    double
    element_stretch(const Membrane<dim> &membrane, const unsigned int e)
    {
      const double ratio = membrane.element_size(e) / membrane.rest_size[e];
      return dim == 2 ? ratio : std::sqrt(ratio);
    }

    template <int dim>
    std::vector<double>
    padded(const std::vector<Tensor<1, dim>> &values)
    {
      std::vector<double> out;
      out.reserve(3 * values.size());
      for (const auto &v : values)
        for (unsigned int d = 0; d < 3; ++d)
          out.push_back(d < dim ? v[d] : 0.);
      return out;
    }
  } // namespace



  template <int dim>
  void
  write_membrane_xdmf(const Membrane<dim> &membrane,
                      XdmfSeries          &series,
                      const double         time)
  {
    std::vector<unsigned int> cells;
    for (const auto &el : membrane.elements)
      cells.insert(cells.end(), el.begin(), el.end());
    std::vector<double> stretch(membrane.n_elements());
    for (unsigned int e = 0; e < membrane.n_elements(); ++e)
      stretch[e] = element_stretch(membrane, e);
    std::vector<Tensor<1, dim>> positions(membrane.position.begin(),
                                          membrane.position.end());
    series.write(time,
                 padded(positions),
                 dim == 2 ? XdmfSeries::CellType::line
                          : XdmfSeries::CellType::triangle,
                 cells,
                 {{"tension", 1, true, membrane.tension},
                  {"stretch", 1, true, stretch},
                  {"velocity", 3, false, padded(membrane.velocity)}});
  }



  template <int dim>
  void
  write_membrane_vtu(const Membrane<dim> &membrane, const std::string &file)
  {
    write_file_atomically(file, [&](std::ostream &out) {
      const unsigned int nn = membrane.n_nodes(), ne = membrane.n_elements();
      std::vector<std::int64_t> connectivity, offsets;
      for (const auto &el : membrane.elements)
        {
          connectivity.insert(connectivity.end(), el.begin(), el.end());
          offsets.push_back(connectivity.size());
        }
      std::vector<double> stretch(ne);
      for (unsigned int e = 0; e < ne; ++e)
        stretch[e] = element_stretch(membrane, e);
      std::vector<Tensor<1, dim>> positions(membrane.position.begin(),
                                            membrane.position.end());
      write_vtu_header(out, nn, ne);
      write_vtu_binary_array(out,
                             "type=\"Float64\" NumberOfComponents=\"3\"",
                             padded(positions));
      out << "</Points>\n<Cells>\n";
      write_vtu_binary_array(out,
                             "type=\"Int64\" Name=\"connectivity\"",
                             connectivity);
      write_vtu_binary_array(out, "type=\"Int64\" Name=\"offsets\"", offsets);
      // VTK_LINE, VTK_TRIANGLE
      write_vtu_binary_array(out,
                             "type=\"UInt8\" Name=\"types\"",
                             std::vector<std::uint8_t>(ne, dim == 2 ? 3 : 5));
      out << "</Cells>\n<CellData Scalars=\"tension\">\n";
      write_vtu_binary_array(out,
                             "type=\"Float64\" Name=\"tension\"",
                             membrane.tension);
      write_vtu_binary_array(out, "type=\"Float64\" Name=\"stretch\"", stretch);
      out << "</CellData>\n<PointData Vectors=\"velocity\">\n";
      write_vtu_binary_array(out,
                             "type=\"Float64\" Name=\"velocity\" "
                             "NumberOfComponents=\"3\"",
                             padded(membrane.velocity));
      out << "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    });
  }



  template <int dim>
  void
  write_membrane_shape_csv(const Membrane<dim> &membrane,
                           const std::string   &file)
  {
    write_file_atomically(file, [&](std::ostream &out) {
      out << (dim == 2 ? "x,y\n" : "x,y,z\n") << std::setprecision(17);
      for (const auto &p : membrane.ordered_nodes())
        {
          for (unsigned int d = 0; d < dim; ++d)
            out << (d ? "," : "") << p[d];
          out << '\n';
        }
    });
  }



#define FSGMPM_INSTANTIATE(dim)                                      \
  template void write_membrane_vtu<dim>(const Membrane<dim> &,       \
                                        const std::string &);        \
  template void write_membrane_xdmf<dim>(const Membrane<dim> &,      \
                                         XdmfSeries &,               \
                                         const double);              \
  template void write_membrane_shape_csv<dim>(const Membrane<dim> &, \
                                              const std::string &);
  FSGMPM_INSTANTIATE(2)
  FSGMPM_INSTANTIATE(3)
#undef FSGMPM_INSTANTIATE
} // namespace fsgmpm
