#ifndef fsgmpm_io_hdf5_setup_h
#define fsgmpm_io_hdf5_setup_h

#include <hdf5.h>

namespace fsgmpm
{
  namespace internal
  {
    /// The number of HDF5 API calls that failed so far in this process.
    inline unsigned long &
    hdf5_error_count()
    {
      static unsigned long count = 0;
      return count;
    }

    /// HDF5's automatic error handler: counts the failure (printing
    /// nothing; our messages say what matters).
    inline herr_t
    count_hdf5_error(hid_t, void *)
    {
      ++hdf5_error_count();
      return 0;
    }
  } // namespace internal

  /**
   * Call before the first HDF5 call of a writer or reader. HDF5's error
   * stack printing is replaced by a count of the failed calls
   * (Hdf5ErrorWatch). HDF5's exit handler is not installed: after a file
   * failed to close (a full disk), HDF5 1.10 crashes in it at exit, turning
   * a clear error message and exit status 1 into a segmentation fault.
   * Every file we open is closed explicitly.
   */
  inline void
  prepare_hdf5()
  {
    static const bool prepared = [] {
      H5dont_atexit();
      H5Eset_auto2(H5E_DEFAULT, internal::count_hdf5_error, nullptr);
      return true;
    }();
    (void)prepared;
  }

  /**
   * Whether any HDF5 call failed since this object was made. deal.II's
   * HDF5 wrappers check the return codes only in debug builds, and every
   * HDF5 call clears HDF5's error stack when it starts (so asking the stack
   * after a write sees only the last call's errors, not a failed H5Dwrite
   * before the close): the automatic error handler installed by
   * prepare_hdf5() counts every failure instead.
   */
  class Hdf5ErrorWatch
  {
  public:
    Hdf5ErrorWatch()
      : start(internal::hdf5_error_count())
    {}

    bool
    failed() const
    {
      return internal::hdf5_error_count() != start;
    }

  private:
    unsigned long start;
  };
} // namespace fsgmpm

#endif
