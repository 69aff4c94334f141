#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/io/vtu_arrays.h>

#include <zlib.h>

#include <cstdint>
#include <cstring>

namespace fsgmpm
{
  using namespace dealii;

  template <typename T>
  void
  write_vtu_binary_array(std::ostream         &out,
                         const std::string    &attributes,
                         const std::vector<T> &values)
  {
    const uLong        raw_size    = values.size() * sizeof(T);
    uLongf             packed_size = compressBound(raw_size);
    std::vector<Bytef> packed(packed_size);
    const int          status = compress2(packed.data(),
                                 &packed_size,
                                 reinterpret_cast<const Bytef *>(values.data()),
                                 raw_size,
                                 Z_DEFAULT_COMPRESSION);
    AssertThrow(status == Z_OK,
                ExcMessage("zlib could not compress a VTU output array."));
    AssertThrow(raw_size <= 0xffffffffu,
                ExcMessage("A VTU output array exceeds 4 GB; write HDF5 "
                           "instead (Output/Format = hdf5)."));
    const std::uint32_t        header[4] = {1,
                                            std::uint32_t(raw_size),
                                            std::uint32_t(raw_size),
                                            std::uint32_t(packed_size)};
    std::vector<unsigned char> header_bytes(sizeof(header));
    std::memcpy(header_bytes.data(), header, sizeof(header));
    out << "<DataArray " << attributes << " format=\"binary\">\n"
        << Utilities::encode_base64(header_bytes)
        << Utilities::encode_base64(
             std::vector<unsigned char>(packed.begin(),
                                        packed.begin() + packed_size))
        << "\n</DataArray>\n";
  }



  void
  write_vtu_header(std::ostream      &out,
                   const unsigned int n_points,
                   const unsigned int n_cells)
  {
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
           "version=\"0.1\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt32\" compressor=\"vtkZLibDataCompressor\">\n"
           "<UnstructuredGrid>\n"
        << "<Piece NumberOfPoints=\"" << n_points << "\" NumberOfCells=\""
        << n_cells << "\">\n<Points>\n";
  }

  template void
  write_vtu_binary_array<float>(std::ostream &,
                                const std::string &,
                                const std::vector<float> &);
  template void
  write_vtu_binary_array<double>(std::ostream &,
                                 const std::string &,
                                 const std::vector<double> &);
  template void
  write_vtu_binary_array<std::int32_t>(std::ostream &,
                                       const std::string &,
                                       const std::vector<std::int32_t> &);
  template void
  write_vtu_binary_array<std::int64_t>(std::ostream &,
                                       const std::string &,
                                       const std::vector<std::int64_t> &);
  template void
  write_vtu_binary_array<std::uint8_t>(std::ostream &,
                                       const std::string &,
                                       const std::vector<std::uint8_t> &);
} // namespace fsgmpm
