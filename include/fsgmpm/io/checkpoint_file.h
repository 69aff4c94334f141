#ifndef fsgmpm_io_checkpoint_file_h
#define fsgmpm_io_checkpoint_file_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace dealii
{
  namespace HDF5
  {
    class File;
  }
} // namespace dealii

namespace fsgmpm
{
  /**
   * One checkpoint: named arrays of doubles and unsigned ints and named
   * strings in an HDF5 file (deal.II's HDF5 wrappers). Doubles are stored
   * bit for bit (native double), so a run restarted from a checkpoint
   * continues exactly as the uninterrupted run.
   *
   * Writing is atomic: the data go to "STEM.h5.tmp", which commit() renames
   * to "STEM_HASH.h5", HASH the 64-bit FNV-1a hash of the file's bytes; a
   * run killed while writing leaves the previous checkpoint intact, and a
   * reader refuses a truncated or changed file before HDF5 parses it.
   */
  class CheckpointWriter
  {
  public:
    /// @p stem: the file's path without the hash and ".h5".
    explicit CheckpointWriter(const std::string &stem);
    ~CheckpointWriter();

    void
    put(const std::string &name, const std::vector<double> &data);
    void
    put(const std::string &name, const std::vector<unsigned int> &data);
    void
    put(const std::string &name, const std::string &text);
    void
    put(const std::string &name, const double value)
    {
      put(name, std::vector<double>{value});
    }

    /// Arrays of deal.II points, tensors or symmetric tensors of doubles,
    /// stored as their contiguous doubles.
    template <typename T>
    void
    put_tensors(const std::string &name, const std::vector<T> &data);

    /// Arrays of small integers (ids, flags) as unsigned ints.
    template <typename Int>
    void
    put_integers(const std::string &name, const std::vector<Int> &data)
    {
      put(name, std::vector<unsigned int>(data.begin(), data.end()));
    }

    /// Write the list of entries, close the file and rename it to its
    /// final name, which is returned.
    std::string
    commit();

  private:
    /// Write a dataset, or close and remove the file and throw.
    template <typename Container>
    void
    write_or_fail(const std::string &name, const Container &data);

    std::string                         stem, tmp_name;
    std::unique_ptr<dealii::HDF5::File> file;
    std::string                         entries;
  };



  /**
   * Reads a checkpoint written by CheckpointWriter. The constructor checks
   * the file's bytes against the hash in its name, then reads every entry;
   * it throws an ExcMessage naming the file if it is damaged or unreadable.
   */
  class CheckpointReader
  {
  public:
    /// With more than one process in @p communicator, process 0 reads
    /// the file and sends its entries to the others (which throw the same
    /// exception if it cannot be read).
    explicit CheckpointReader(const std::string &file_name,
                              const MPI_Comm     communicator = MPI_COMM_SELF);

    bool
    has(const std::string &name) const;

    const std::vector<double> &
    doubles(const std::string &name) const;
    const std::vector<unsigned int> &
    uints(const std::string &name) const;
    const std::string &
    text(const std::string &name) const;
    double
    scalar(const std::string &name) const;

    template <typename T>
    std::vector<T>
    tensors(const std::string &name) const;

    template <typename Int>
    std::vector<Int>
    integers(const std::string &name) const
    {
      const auto &v = uints(name);
      return std::vector<Int>(v.begin(), v.end());
    }

  private:
    /// Checks the hash and reads every entry of the file.
    void
    read();

    std::string                                      file_name;
    std::map<std::string, std::vector<double>>       double_data;
    std::map<std::string, std::vector<unsigned int>> uint_data;
    std::map<std::string, std::string>               text_data;
  };



  template <typename T>
  void
  CheckpointWriter::put_tensors(const std::string    &name,
                                const std::vector<T> &data)
  {
    static_assert(sizeof(T) % sizeof(double) == 0
                    && std::is_trivially_copyable<T>::value,
                  "put_tensors takes arrays of tensors of doubles");
    std::vector<double> flat(data.size() * sizeof(T) / sizeof(double));
    if (!data.empty())
      std::memcpy(flat.data(), data.data(), data.size() * sizeof(T));
    put(name, flat);
  }



  template <typename T>
  std::vector<T>
  CheckpointReader::tensors(const std::string &name) const
  {
    static_assert(sizeof(T) % sizeof(double) == 0
                    && std::is_trivially_copyable<T>::value,
                  "tensors() reads arrays of tensors of doubles");
    const auto    &flat = doubles(name);
    constexpr auto n    = sizeof(T) / sizeof(double);
    AssertThrow(flat.size() % n == 0,
                dealii::ExcMessage(
                  "The checkpoint <" + file_name + "> is damaged: its entry <"
                  + name + "> has " + std::to_string(flat.size())
                  + " values, not a multiple of " + std::to_string(n) + "."));
    std::vector<T> data(flat.size() / n);
    if (!data.empty())
      std::memcpy(data.data(), flat.data(), flat.size() * sizeof(double));
    return data;
  }
} // namespace fsgmpm

#endif
