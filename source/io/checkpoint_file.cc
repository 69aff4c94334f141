#include <deal.II/base/hdf5.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <fsgmpm/io/hdf5_setup.h>
#include <fsgmpm/parallel/process_count.h>

#include <fsgmpm/io/checkpoint_file.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>

namespace fsgmpm
{
  namespace
  {
    using namespace dealii;

    /// FNV-1a (64 bit) over a byte range, continued from @p hash.
    std::uint64_t
    fnv1a(const void *data, const std::size_t n, std::uint64_t hash)
    {
      const auto *bytes = static_cast<const unsigned char *>(data);
      for (std::size_t i = 0; i < n; ++i)
        {
          hash ^= bytes[i];
          hash *= 1099511628211ull;
        }
      return hash;
    }

    constexpr std::uint64_t fnv_offset = 14695981039346656037ull;

    /// FNV-1a of a whole file's bytes.
    std::uint64_t
    file_hash(const std::string &file_name)
    {
      std::ifstream     in(file_name, std::ios::binary);
      std::vector<char> buffer(1 << 20);
      std::uint64_t     hash = fnv_offset;
      while (in)
        {
          in.read(buffer.data(), buffer.size());
          hash = fnv1a(buffer.data(), in.gcount(), hash);
        }
      return hash;
    }

    std::string
    hex(const std::uint64_t x)
    {
      char buffer[20];
      std::snprintf(buffer, sizeof(buffer), "%016llx", (unsigned long long)x);
      return buffer;
    }

    std::vector<unsigned int>
    bytes_of(const std::string &text)
    {
      return std::vector<unsigned int>(text.begin(), text.end());
    }

    /// HDF5 reads '/' as a group path: the datasets have flat names.
    std::string
    dataset_name(std::string name)
    {
      for (char &c : name)
        if (c == '/')
          c = '.';
      return name;
    }

    /// Write @p local as the values from @p offset on of a dataset of
    /// @p total values; false if HDF5 failed. deal.II's HDF5 wrappers do
    /// not throw when HDF5 fails to create or write a dataset
    /// (Hdf5ErrorWatch tells), and an HDF5::File destroyed while an exception
    /// is in flight aborts the program: so this reports, and the caller closes
    /// the file before it throws. In a file opened on several processes
    /// this is collective: every process writes its part (or none).
    template <typename Number>
    bool
    write_dataset_checked(HDF5::File                &file,
                          const std::string         &name,
                          const std::vector<Number> &local,
                          const bool                 parallel,
                          const hsize_t              offset,
                          const hsize_t              total)
    {
      const Hdf5ErrorWatch errors;
      try
        {
          auto dataset = file.create_dataset<Number>(name, {total});
          if (!parallel)
            dataset.write(local);
          else if (!local.empty())
            dataset.write_hyperslab(local, {offset}, {hsize_t(local.size())});
          else
            dataset.template write_none<Number>();
        }
      catch (...)
        {
          return false;
        }
      return !errors.failed();
    }

    /// This process's values [first, first + count) of a dataset (all of
    /// them in a serial read); collective in a parallel one.
    template <typename Number>
    std::vector<Number>
    read_part(HDF5::File        &file,
              const std::string &name,
              const bool         parallel,
              const hsize_t      first,
              const hsize_t      count)
    {
      auto dataset = file.open_dataset(name);
      if (!parallel)
        return dataset.read<std::vector<Number>>();
      if (count == 0)
        {
          dataset.read_none<Number>();
          return {};
        }
      return dataset.read_hyperslab<std::vector<Number>>({first}, {count});
    }

    std::string
    message_of(const ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      return Utilities::trim(info.str());
    }
  } // namespace



  CheckpointWriter::CheckpointWriter(const std::string &stem,
                                     const MPI_Comm     communicator)
    : stem(stem)
    , tmp_name(stem + ".h5.tmp")
    , communicator(communicator)
    , parallel(Parallel::n_processes(communicator) > 1)
    , root(!parallel || Utilities::MPI::this_mpi_process(communicator) == 0)
  {
    std::error_code ignored;
    if (root)
      std::filesystem::remove(tmp_name, ignored);
    prepare_hdf5();
    const Hdf5ErrorWatch errors;
    bool                 created = true;
    try
      {
        file = parallel ? std::make_unique<HDF5::File>(
                 tmp_name, HDF5::File::FileAccessMode::create, communicator)
                        : std::make_unique<HDF5::File>(
                          tmp_name, HDF5::File::FileAccessMode::create);
      }
    catch (...)
      {
        created = false;
      }
    created = created && !errors.failed();
    if (parallel)
      created = Utilities::MPI::min(int(created), communicator) == 1;
    if (!created)
      fail("Cannot create the checkpoint file <" + tmp_name
           + ">: is its directory writable"
           + (parallel ? std::string(", and on a file system that every "
                                     "process shares?")
                       : std::string("?")));
  }



  CheckpointWriter::~CheckpointWriter()
  {
    // Not committed: an exception from outside this class while the file
    // was open (this class closes it before it throws). deal.II's HDF5
    // objects abort the program if they are destroyed while an exception
    // is in flight (closing is collective with MPI), so the file is left
    // open, and the partial file removed.
    if (file)
      {
        if (std::uncaught_exceptions() > 0)
          (void)file.release();
        else
          file.reset();
        std::error_code ignored;
        if (root)
          std::filesystem::remove(tmp_name, ignored);
      }
  }



  void
  CheckpointWriter::fail(const std::string &message)
  {
    // Close (collectively) and remove the partial file before throwing,
    // and before any process may abort the others on this error.
    file.reset();
    std::error_code ignored;
    if (root)
      std::filesystem::remove(tmp_name, ignored);
    if (parallel)
      MPI_Barrier(communicator);
    AssertThrow(false, ExcMessage(message));
    std::abort(); // not reached: AssertThrow throws
  }



  template <typename Number>
  void
  CheckpointWriter::write_or_fail(const std::string         &name,
                                  const std::vector<Number> &local,
                                  const unsigned long long   offset,
                                  const unsigned long long   total)
  {
    AssertThrow(file,
                ExcMessage("Writing <" + name + "> to the checkpoint <"
                           + tmp_name + ">: its writer failed before."));
    bool ok = write_dataset_checked(
      *file, dataset_name(name), local, parallel, offset, total);
    // One process's failure is everyone's: the next write is collective.
    if (parallel)
      ok = Utilities::MPI::min(int(ok), communicator) == 1;
    if (!ok)
      fail("Writing <" + name + "> to the checkpoint <" + tmp_name
           + "> failed (is the disk full?). The previous checkpoints are "
             "kept.");
  }



  template <typename Number>
  void
  CheckpointWriter::put_replicated(const char                 kind,
                                   const std::string         &name,
                                   const std::vector<Number> &data)
  {
    // Process 0's data are written (another process may hold none: the
    // output series are process 0's).
    unsigned long long size = data.size();
    if (parallel)
      size = Utilities::MPI::broadcast(communicator, size);
    entries
      += std::string(1, kind) + " " + name + " " + std::to_string(size) + "\n";
    // HDF5 datasets cannot be empty: an empty array is only listed.
    if (size > 0)
      write_or_fail(name, root ? data : std::vector<Number>(), 0, size);
  }



  template <typename Number>
  void
  CheckpointWriter::put_split(const char                 kind,
                              const std::string         &name,
                              const std::vector<Number> &local,
                              const unsigned int         columns)
  {
    Assert(columns > 0 && local.size() % columns == 0, ExcInternalError());
    const auto [offset, total]
      = Parallel::offset_and_total(local.size(), communicator);
    std::vector<unsigned int> rows{
      static_cast<unsigned int>(local.size() / columns)};
    if (parallel)
      rows = Utilities::MPI::all_gather(communicator, rows[0]);
    // Every table has the same rows on each process (or none at all).
    if (total > 0)
      {
        if (rows_per_process.empty())
          rows_per_process = rows;
        // The same on every process (rows are gathered): all fail alike.
        if (rows != rows_per_process)
          fail("Internal error: the checkpoint's table <" + name
               + "> has other rows per process than the tables before it "
                 "(every table of the points has one row per point). "
                 "Please report this.");
      }
    entries += std::string(1, kind) + " " + name + " " + std::to_string(total)
               + " " + std::to_string(columns) + "\n";
    if (total > 0)
      write_or_fail(name, local, offset, total);
  }



  void
  CheckpointWriter::put(const std::string         &name,
                        const std::vector<double> &data)
  {
    put_replicated('d', name, data);
  }



  void
  CheckpointWriter::put(const std::string               &name,
                        const std::vector<unsigned int> &data)
  {
    put_replicated('u', name, data);
  }



  void
  CheckpointWriter::put(const std::string &name, const std::string &text)
  {
    put_replicated('s', name, bytes_of(text));
  }



  void
  CheckpointWriter::put_rows(const std::string         &name,
                             const std::vector<double> &local,
                             const unsigned int         columns)
  {
    put_split('D', name, local, columns);
  }



  void
  CheckpointWriter::put_rows(const std::string               &name,
                             const std::vector<unsigned int> &local,
                             const unsigned int               columns)
  {
    put_split('U', name, local, columns);
  }



  std::string
  CheckpointWriter::commit()
  {
    put("checkpoint/rows_per_process", rows_per_process);
    write_or_fail("checkpoint_entries",
                  root ? bytes_of(entries) : std::vector<unsigned int>(),
                  0,
                  entries.size());
    {
      // H5Fclose: everything is in the file (a full disk may show only
      // here).
      const Hdf5ErrorWatch errors;
      file.reset();
      bool ok = !errors.failed();
      if (parallel)
        ok = Utilities::MPI::min(int(ok), communicator) == 1;
      if (!ok)
        fail("Closing the checkpoint <" + tmp_name
             + "> failed (is the disk full?). The previous checkpoints are "
               "kept.");
    }
    // The hash of the file's bytes goes into its name, so that a reader
    // checks the file before HDF5 parses it (deal.II's HDF5 wrappers do not
    // survive a damaged file). Process 0 reads the file and renames it.
    std::string name, error;
    if (root)
      {
        name = stem + "_" + hex(file_hash(tmp_name)) + ".h5";
        std::error_code failed;
        std::filesystem::rename(tmp_name, name, failed);
        if (failed)
          error = "Cannot rename the checkpoint <" + tmp_name + "> to <" + name
                  + ">: " + failed.message() + ".";
      }
    if (parallel)
      {
        name  = Utilities::MPI::broadcast(communicator, name);
        error = Utilities::MPI::broadcast(communicator, error);
      }
    AssertThrow(error.empty(), ExcMessage(error));
    return name;
  }



  CheckpointReader::CheckpointReader(const std::string &file_name,
                                     const MPI_Comm     communicator)
    : file_name(file_name)
    , communicator(communicator)
  {
    const bool parallel = Parallel::n_processes(communicator) > 1;
    // Process 0 checks the file's bytes and tells the others.
    std::string error;
    if (!parallel || Utilities::MPI::this_mpi_process(communicator) == 0)
      try
        {
          check_hash();
        }
      catch (const ExceptionBase &e)
        {
          error = message_of(e);
        }
    if (parallel)
      error = Utilities::MPI::broadcast(communicator, error);
    AssertThrow(error.empty(), ExcMessage(error));
    read();
  }



  void
  CheckpointReader::check_hash() const
  {
    // The name ends in _HASH.h5, the hash of the file's bytes.
    const auto underscore = file_name.rfind('_');
    const auto dot        = file_name.rfind(".h5");
    AssertThrow(underscore != std::string::npos && dot != std::string::npos
                  && dot > underscore,
                ExcMessage("<" + file_name
                           + "> is not named as an fsgmpm checkpoint "
                             "(checkpoint_STEP_HASH.h5)."));
    const std::string named
      = file_name.substr(underscore + 1, dot - underscore - 1);
    const std::string found = hex(file_hash(file_name));
    AssertThrow(named == found,
                ExcMessage("Cannot read the checkpoint <" + file_name
                           + ">: it is damaged (truncated or changed; the "
                             "hash of its bytes is "
                           + found + ", its name says " + named + ")."));
  }



  void
  CheckpointReader::read()
  {
    const bool         parallel  = Parallel::n_processes(communicator) > 1;
    const unsigned int n_readers = Parallel::n_processes(communicator);
    const unsigned int me
      = parallel ? Utilities::MPI::this_mpi_process(communicator) : 0;
    // HDF5 would print its error stack for an unreadable file; the message
    // below says what matters.
    prepare_hdf5();
    // The file lives outside the try: an HDF5::File destroyed while an
    // exception is in flight aborts the program. Each entry is read by
    // every process (collective calls); whether it could be is agreed on
    // before the next, so that no process waits for one that gave up.
    std::unique_ptr<HDF5::File> file_pointer;
    std::string                 failed_entry;
    const auto agree = [&](bool ok, const Hdf5ErrorWatch &errors) {
      ok = ok && !errors.failed();
      return parallel ? Utilities::MPI::min(int(ok), communicator) == 1 : ok;
    };
    bool readable = true;
    {
      const Hdf5ErrorWatch errors;
      try
        {
          file_pointer
            = parallel
                ? std::make_unique<HDF5::File>(file_name,
                                               HDF5::File::FileAccessMode::open,
                                               communicator)
                : std::make_unique<HDF5::File>(
                  file_name, HDF5::File::FileAccessMode::open);
        }
      catch (...)
        {
          readable = false;
        }
      readable = agree(readable, errors);
    }

    struct Entry
    {
      char          kind;
      std::string   name;
      unsigned long size, columns;
    };
    std::vector<Entry> list;
    if (readable)
      {
        failed_entry = "checkpoint_entries";
        const Hdf5ErrorWatch errors;
        try
          {
            const auto bytes = file_pointer->open_dataset("checkpoint_entries")
                                 .read<std::vector<unsigned int>>();
            std::istringstream lines(std::string(bytes.begin(), bytes.end()));
            std::string        line;
            while (std::getline(lines, line))
              {
                std::istringstream words(line);
                Entry              e{' ', "", 0, 1};
                words >> e.kind >> e.name >> e.size;
                if (e.kind == 'D' || e.kind == 'U')
                  words >> e.columns;
                AssertThrow(!words.fail() && e.columns > 0, ExcInternalError());
                list.push_back(e);
              }
          }
        catch (...)
          {
            readable = false;
          }
        readable = agree(readable, errors);
      }

    // The rows each process wrote (checkpoints of older versions: one
    // process wrote all).
    std::vector<unsigned long> written_rows;
    for (const auto &e : list)
      if (readable && e.name == "checkpoint/rows_per_process" && e.size > 0)
        {
          failed_entry = e.name;
          const Hdf5ErrorWatch errors;
          try
            {
              const auto v = read_part<unsigned int>(
                *file_pointer, dataset_name(e.name), parallel, 0, e.size);
              written_rows.assign(v.begin(), v.end());
            }
          catch (...)
            {
              readable = false;
            }
          readable = agree(readable, errors);
        }
    as_written = written_rows.size() == n_readers;
    for (const auto &e : list)
      if (e.kind == 'D' || e.kind == 'U')
        split = parallel;

    for (const auto &e : list)
      {
        if (!readable)
          break;
        // This process's part: all values, or of a table of rows those it
        // wrote, or an even share of the rows.
        hsize_t first = 0, count = e.size;
        if (parallel && (e.kind == 'D' || e.kind == 'U'))
          {
            const unsigned long rows = e.size / e.columns;
            unsigned long       begin, end;
            if (as_written && rows > 0)
              {
                begin = std::accumulate(written_rows.begin(),
                                        written_rows.begin() + me,
                                        0ul);
                end   = begin + written_rows[me];
              }
            else
              {
                begin = rows * me / n_readers;
                end   = rows * (me + 1) / n_readers;
              }
            first = begin * e.columns;
            count = (end - begin) * e.columns;
          }
        failed_entry = e.name;
        const Hdf5ErrorWatch errors;
        try
          {
            AssertThrow(e.size % e.columns == 0, ExcInternalError());
            if (e.kind == 'd' || e.kind == 'D')
              {
                auto &v = double_data[e.name];
                if (e.size > 0)
                  v = read_part<double>(*file_pointer,
                                        dataset_name(e.name),
                                        parallel,
                                        first,
                                        count);
                AssertThrow(v.size() == count, ExcInternalError());
              }
            else
              {
                std::vector<unsigned int> v;
                if (e.size > 0)
                  v = read_part<unsigned int>(*file_pointer,
                                              dataset_name(e.name),
                                              parallel,
                                              first,
                                              count);
                AssertThrow(v.size() == count, ExcInternalError());
                if (e.kind == 's')
                  text_data[e.name].assign(v.begin(), v.end());
                else
                  uint_data[e.name] = std::move(v);
              }
          }
        catch (...)
          {
            readable = false;
          }
        readable = agree(readable, errors);
      }
    file_pointer.reset();
    AssertThrow(
      readable,
      ExcMessage(
        "Cannot read the checkpoint <" + file_name + ">: HDF5 cannot read "
        + (failed_entry.empty() ? "it" : "its entry <" + failed_entry + ">")
        + " back"
        + (parallel ? " (is its directory on a file system that "
                      "every process shares?)."
                    : ".")));
  }



  bool
  CheckpointReader::has(const std::string &name) const
  {
    return double_data.count(name) + uint_data.count(name)
             + text_data.count(name)
           > 0;
  }



  namespace
  {
    template <typename Map>
    const typename Map::mapped_type &
    lookup(const Map &map, const std::string &name, const std::string &file)
    {
      const auto it = map.find(name);
      AssertThrow(it != map.end(),
                  ExcMessage("The checkpoint <" + file + "> has no entry <"
                             + name
                             + ">: it was written by another version of "
                               "fsgmpm or for another scene."));
      return it->second;
    }
  } // namespace



  const std::vector<double> &
  CheckpointReader::doubles(const std::string &name) const
  {
    return lookup(double_data, name, file_name);
  }



  const std::vector<unsigned int> &
  CheckpointReader::uints(const std::string &name) const
  {
    return lookup(uint_data, name, file_name);
  }



  const std::string &
  CheckpointReader::text(const std::string &name) const
  {
    return lookup(text_data, name, file_name);
  }



  double
  CheckpointReader::scalar(const std::string &name) const
  {
    const auto &v = doubles(name);
    AssertThrow(v.size() == 1,
                ExcMessage("The checkpoint <" + file_name + ">: the entry <"
                           + name + "> is not a single value."));
    return v[0];
  }
} // namespace fsgmpm
