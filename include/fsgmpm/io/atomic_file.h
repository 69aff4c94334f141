#ifndef fsgmpm_io_atomic_file_h
#define fsgmpm_io_atomic_file_h

#include <fstream>
#include <functional>
#include <string>

namespace fsgmpm
{
  /**
   * Write a file atomically: @p write fills a stream on a temporary name in
   * the same directory, which is renamed to @p file_name only when complete,
   * so a reader (or a crash) never sees a half-written file.
   */
  void
  write_file_atomically(const std::string                         &file_name,
                        const std::function<void(std::ostream &)> &write);
} // namespace fsgmpm

#endif
