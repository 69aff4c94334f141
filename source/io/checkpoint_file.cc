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

    /// Write a dataset; false if HDF5 failed. deal.II's HDF5 wrappers do
    /// not throw when HDF5 fails to create or write a dataset (HDF5's error
    /// stack tells), and an HDF5::File destroyed while an exception is in
    /// flight aborts the program: so this reports, and the caller closes
    /// the file before it throws.
    template <typename Container>
    bool
    write_dataset_checked(HDF5::File        &file,
                          const std::string &name,
                          const Container   &data)
    {
      try
        {
          file.write_dataset(name, data);
        }
      catch (...)
        {
          return false;
        }
      return H5Eget_num(H5E_DEFAULT) == 0;
    }
  } // namespace



  CheckpointWriter::CheckpointWriter(const std::string &stem)
    : stem(stem)
    , tmp_name(stem + ".h5.tmp")
  {
    std::filesystem::remove(tmp_name);
    prepare_hdf5();
    try
      {
        file = std::make_unique<HDF5::File>(tmp_name,
                                            HDF5::File::FileAccessMode::create);
      }
    catch (...)
      {
        AssertThrow(false,
                    ExcMessage("Cannot create the checkpoint file <" + tmp_name
                               + ">."));
      }
  }



  CheckpointWriter::~CheckpointWriter()
  {
    // Not committed (an exception while writing): leave no partial file.
    if (file)
      {
        file.reset();
        std::error_code ignored;
        std::filesystem::remove(tmp_name, ignored);
      }
  }



  template <typename Container>
  void
  CheckpointWriter::write_or_fail(const std::string &name,
                                  const Container   &data)
  {
    if (write_dataset_checked(*file, dataset_name(name), data))
      return;
    // Close and remove the partial file before throwing (see above).
    file.reset();
    std::error_code ignored;
    std::filesystem::remove(tmp_name, ignored);
    AssertThrow(false,
                ExcMessage("Writing <" + name + "> to the checkpoint <"
                           + tmp_name
                           + "> failed (is the disk full?). The previous "
                             "checkpoints are kept."));
  }



  void
  CheckpointWriter::put(const std::string         &name,
                        const std::vector<double> &data)
  {
    entries += "d " + name + " " + std::to_string(data.size()) + "\n";
    // HDF5 datasets cannot be empty: an empty array is only listed.
    if (!data.empty())
      write_or_fail(name, data);
  }



  void
  CheckpointWriter::put(const std::string               &name,
                        const std::vector<unsigned int> &data)
  {
    entries += "u " + name + " " + std::to_string(data.size()) + "\n";
    if (!data.empty())
      write_or_fail(name, data);
  }



  void
  CheckpointWriter::put(const std::string &name, const std::string &text)
  {
    entries += "s " + name + " " + std::to_string(text.size()) + "\n";
    if (!text.empty())
      write_or_fail(name, bytes_of(text));
  }



  std::string
  CheckpointWriter::commit()
  {
    write_or_fail("checkpoint_entries", bytes_of(entries));
    file.reset(); // H5Fclose: everything is in the file
    // The hash of the file's bytes goes into its name, so that a reader
    // checks the file before HDF5 parses it (deal.II's HDF5 wrappers do not
    // survive a damaged file).
    const std::string name = stem + "_" + hex(file_hash(tmp_name)) + ".h5";
    std::filesystem::rename(tmp_name, name);
    return name;
  }



  CheckpointReader::CheckpointReader(const std::string &file_name,
                                     const MPI_Comm     communicator)
    : file_name(file_name)
  {
    if (Parallel::n_processes(communicator) == 1)
      {
        read();
        return;
      }
    // Process 0 reads the file and sends its entries (or why it cannot be
    // read) to the others: HDF5 locks a file that one process has open.
    std::string error;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      try
        {
          read();
        }
      catch (const ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          error = Utilities::trim(info.str());
        }
    error = Utilities::MPI::broadcast(communicator, error);
    AssertThrow(error.empty(), ExcMessage(error));
    double_data = Utilities::MPI::broadcast(communicator, double_data);
    uint_data   = Utilities::MPI::broadcast(communicator, uint_data);
    text_data   = Utilities::MPI::broadcast(communicator, text_data);
  }



  void
  CheckpointReader::read()
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

    // HDF5 would print its error stack for an unreadable file; the message
    // below says what matters.
    prepare_hdf5();
    // The file lives outside the try: an HDF5::File destroyed while an
    // exception is in flight aborts the program.
    std::unique_ptr<HDF5::File> file_pointer;
    bool                        readable = true;
    try
      {
        file_pointer
          = std::make_unique<HDF5::File>(file_name,
                                         HDF5::File::FileAccessMode::open);
        HDF5::File &file       = *file_pointer;
        const auto  list_bytes = file.open_dataset("checkpoint_entries")
                                  .read<std::vector<unsigned int>>();
        std::istringstream list(
          std::string(list_bytes.begin(), list_bytes.end()));
        std::string line;
        while (std::getline(list, line))
          {
            const auto first = line.find(' '), last = line.rfind(' ');
            const char kind = line[0];
            const auto name = line.substr(first + 1, last - first - 1);
            const auto size = std::stoul(line.substr(last + 1));
            if (kind == 'd')
              {
                auto &v = double_data[name];
                if (size > 0)
                  v = file.open_dataset(dataset_name(name))
                        .read<std::vector<double>>();
                AssertThrow(v.size() == size, ExcInternalError());
              }
            else
              {
                std::vector<unsigned int> v;
                if (size > 0)
                  v = file.open_dataset(dataset_name(name))
                        .read<std::vector<unsigned int>>();
                AssertThrow(v.size() == size, ExcInternalError());
                if (kind == 'u')
                  uint_data[name] = std::move(v);
                else
                  text_data[name].assign(v.begin(), v.end());
              }
          }
      }
    catch (...)
      {
        readable = false;
      }
    file_pointer.reset();
    AssertThrow(readable,
                ExcMessage("Cannot read the checkpoint <" + file_name
                           + ">: HDF5 cannot read it back."));
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
