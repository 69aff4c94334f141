#ifndef fsgmpm_io_vtu_arrays_h
#define fsgmpm_io_vtu_arrays_h

#include <ostream>
#include <string>
#include <vector>

namespace fsgmpm
{
  /**
   * One DataArray of a VTU file, zlib-compressed and base64-encoded as
   * deal.II's DataOut writes its arrays (one block: a header of four
   * 32-bit numbers, then the compressed bytes), so that ParaView and
   * doc/scripts/read_vtu.py read every file of a run alike. @p attributes
   * are the element's attributes before format="binary", e.g.
   * `type="Float32" Name="pressure"`. T is float, double, std::int32_t,
   * std::int64_t or std::uint8_t, matching the type named there.
   */
  template <typename T>
  void
  write_vtu_binary_array(std::ostream         &out,
                         const std::string    &attributes,
                         const std::vector<T> &values);

  /// The opening of a compressed VTU file up to <Points> of a piece of
  /// @p n_points points and @p n_cells cells.
  void
  write_vtu_header(std::ostream      &out,
                   const unsigned int n_points,
                   const unsigned int n_cells);
} // namespace fsgmpm

#endif
