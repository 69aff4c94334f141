#ifndef fsgmpm_io_hdf5_setup_h
#define fsgmpm_io_hdf5_setup_h

#include <hdf5.h>

namespace fsgmpm
{
  /**
   * Call before the first HDF5 call of a writer or reader. HDF5's error
   * stack printing is turned off (our messages say what matters). HDF5's
   * exit handler is not installed: after a file failed to close (a full
   * disk), HDF5 1.10 crashes in it at exit, turning a clear error message
   * and exit status 1 into a segmentation fault. Every file we open is
   * closed explicitly.
   */
  inline void
  prepare_hdf5()
  {
    static const bool prepared = [] {
      H5dont_atexit();
      H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
      return true;
    }();
    (void)prepared;
  }
} // namespace fsgmpm

#endif
