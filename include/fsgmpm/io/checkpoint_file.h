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
   *
   * With several processes in the communicator the file is one, written
   * collectively through MPI-IO (parallel HDF5): put() stores data that
   * every process holds alike (process 0 writes it), put_rows() a table
   * whose rows are split over the processes (the material points), each
   * process writing its own rows after those of the processes before it.
   * No process gathers the others' rows. Every call is collective.
   */
  class CheckpointWriter
  {
  public:
    /// @p stem: the file's path without the hash and ".h5" (the same on
    /// every process of @p communicator).
    explicit CheckpointWriter(const std::string &stem,
                              const MPI_Comm     communicator = MPI_COMM_SELF);
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

    /**
     * A table of @p columns values per row whose rows are split over the
     * processes: @p local holds this process's rows. Every table of one
     * checkpoint has the same rows per process, or none at all (an unused
     * array, such as the affine velocities without APIC).
     */
    void
    put_rows(const std::string         &name,
             const std::vector<double> &local,
             const unsigned int         columns = 1);
    void
    put_rows(const std::string               &name,
             const std::vector<unsigned int> &local,
             const unsigned int               columns = 1);

    /// put_rows() for arrays of tensors of doubles, one row per tensor.
    template <typename T>
    void
    put_tensor_rows(const std::string &name, const std::vector<T> &local)
    {
      put_rows(name, flatten(local), sizeof(T) / sizeof(double));
    }

    /// put_rows() for arrays of small integers (ids, flags).
    template <typename Int>
    void
    put_integer_rows(const std::string &name, const std::vector<Int> &local)
    {
      put_rows(name, std::vector<unsigned int>(local.begin(), local.end()));
    }

    /// Write the list of entries, close the file and rename it to its
    /// final name, which is returned (on every process).
    std::string
    commit();

  private:
    /// The contiguous doubles of an array of tensors.
    template <typename T>
    static std::vector<double>
    flatten(const std::vector<T> &data);

    /// Write a dataset of @p total values, of which this process writes
    /// @p local from @p offset on; or close and remove the file and throw
    /// (on every process alike).
    template <typename Number>
    void
    write_or_fail(const std::string         &name,
                  const std::vector<Number> &local,
                  const unsigned long long   offset,
                  const unsigned long long   total);

    /// put() of replicated data: process 0 writes it.
    template <typename Number>
    void
    put_replicated(const char                 kind,
                   const std::string         &name,
                   const std::vector<Number> &data);

    template <typename Number>
    void
    put_split(const char                 kind,
              const std::string         &name,
              const std::vector<Number> &local,
              const unsigned int         columns);

    /// Close and remove the temporary file, then throw @p message.
    [[noreturn]] void
    fail(const std::string &message);

    std::string                         stem, tmp_name;
    MPI_Comm                            communicator;
    bool                                parallel, root;
    std::unique_ptr<dealii::HDF5::File> file;
    std::string                         entries;
    /// The rows each process holds in the tables of put_rows() (empty
    /// before the first).
    std::vector<unsigned int> rows_per_process;
  };



  /**
   * Reads a checkpoint written by CheckpointWriter. The constructor checks
   * the file's bytes against the hash in its name, then reads every entry;
   * it throws an ExcMessage naming the file if it is damaged or unreadable.
   *
   * With several processes in the communicator the file is read
   * collectively (parallel HDF5), and of each table of put_rows() a process
   * reads only some rows: those it wrote, if the checkpoint was written by
   * as many processes (rows_as_written()), otherwise an even share. A
   * serial reader reads all rows.
   */
  class CheckpointReader
  {
  public:
    /// Every process of @p communicator throws the same exception if the
    /// file cannot be read.
    explicit CheckpointReader(const std::string &file_name,
                              const MPI_Comm     communicator = MPI_COMM_SELF);

    bool
    has(const std::string &name) const;

    /// Whether this process holds only some rows of the tables written by
    /// put_rows() (several processes read the checkpoint).
    bool
    rows_split() const
    {
      return split;
    }

    /// Whether each process holds the rows it wrote: the checkpoint was
    /// written by as many processes as read it.
    bool
    rows_as_written() const
    {
      return as_written;
    }

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
    /// Checks the hash of the file's bytes (on process 0 of a parallel
    /// read); throws if it differs.
    void
    check_hash() const;

    /// Reads every entry of the file.
    void
    read();

    std::string                                      file_name;
    MPI_Comm                                         communicator;
    bool                                             split      = false;
    bool                                             as_written = true;
    std::map<std::string, std::vector<double>>       double_data;
    std::map<std::string, std::vector<unsigned int>> uint_data;
    std::map<std::string, std::string>               text_data;
  };



  template <typename T>
  void
  CheckpointWriter::put_tensors(const std::string    &name,
                                const std::vector<T> &data)
  {
    put(name, flatten(data));
  }



  template <typename T>
  std::vector<double>
  CheckpointWriter::flatten(const std::vector<T> &data)
  {
    static_assert(sizeof(T) % sizeof(double) == 0
                    && std::is_trivially_copyable<T>::value,
                  "put_tensors takes arrays of tensors of doubles");
    std::vector<double> flat(data.size() * sizeof(T) / sizeof(double));
    if (!data.empty())
      std::memcpy(flat.data(), data.data(), data.size() * sizeof(T));
    return flat;
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
