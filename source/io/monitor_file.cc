#include <deal.II/base/exceptions.h>

#include <fsgmpm/io/atomic_file.h>
#include <fsgmpm/io/monitor_file.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fsgmpm
{
  MonitorFile::MonitorFile(const std::string              &file_name,
                           const std::vector<std::string> &columns)
    : file(std::fopen(file_name.c_str(), "w"))
    , n_columns(columns.size())
  {
    AssertThrow(file != nullptr,
                dealii::ExcMessage("Cannot open <" + file_name
                                   + "> for writing."));
    std::string header;
    for (unsigned int i = 0; i < columns.size(); ++i)
      header += (i ? "," : "") + columns[i];
    header += "\n";
    std::fputs(header.c_str(), file);
    std::fflush(file);
  }

  MonitorFile::MonitorFile(const std::string              &file_name,
                           const std::vector<std::string> &columns,
                           const unsigned long             bytes)
    : file(nullptr)
    , n_columns(columns.size())
  {
    namespace fs = std::filesystem;
    std::string header, expected;
    for (unsigned int i = 0; i < columns.size(); ++i)
      expected += (i ? "," : "") + columns[i];
    {
      std::ifstream in(file_name);
      std::getline(in, header);
    }
    // A run written before the header had units continues under its own
    // header: the names are compared without their units.
    const auto bare = [](const std::string &line) {
      std::string        names, name;
      std::istringstream in(line);
      while (std::getline(in, name, ','))
        names += monitor_column_name(name) + ",";
      return names;
    };
    AssertThrow(bare(header) == bare(expected),
                dealii::ExcMessage(
                  "Cannot continue <" + file_name
                  + ">: it is missing or its columns differ from this "
                    "scene's (the restart needs the run's own monitors.csv)."));
    AssertThrow(fs::file_size(file_name) >= bytes,
                dealii::ExcMessage("Cannot continue <" + file_name
                                   + ">: it is shorter than at the checkpoint ("
                                   + std::to_string(fs::file_size(file_name))
                                   + " bytes, the checkpoint needs "
                                   + std::to_string(bytes) + ")."));
    // The rows written after the checkpoint are written again.
    fs::resize_file(file_name, bytes);
    file = std::fopen(file_name.c_str(), "a");
    AssertThrow(file != nullptr,
                dealii::ExcMessage("Cannot open <" + file_name
                                   + "> for writing."));
  }



  unsigned long
  MonitorFile::size() const
  {
    return static_cast<unsigned long>(std::ftell(file));
  }



  MonitorFile::~MonitorFile()
  {
    if (file)
      std::fclose(file);
  }

  void
  MonitorFile::write_row(const std::vector<double> &values)
  {
    Assert(values.size() == n_columns, dealii::ExcInternalError());
    std::string row;
    char        buffer[40];
    for (unsigned int i = 0; i < values.size(); ++i)
      {
        if (i)
          row += ',';
        // An undefined value (the Eq. (30) ratios before there is any
        // external work or force) is an empty field, never "inf" or "nan".
        if (!std::isfinite(values[i]))
          continue;
        std::snprintf(buffer, sizeof(buffer), "%.17g", values[i]);
        row += buffer;
      }
    row += '\n';
    std::fwrite(row.data(), 1, row.size(), file);
    std::fflush(file);
  }

  std::string
  monitor_column_header(const std::string &column, const std::string &unit)
  {
    return unit.empty() ? column : column + "[" + unit + "]";
  }



  std::string
  monitor_column_name(const std::string &header)
  {
    const auto open = header.find('[');
    return (open != std::string::npos && !header.empty()
            && header.back() == ']')
             ? header.substr(0, open)
             : header;
  }



  std::string
  json_string(const std::string &s)
  {
    std::string out = "\"";
    for (const char c : s)
      {
        if (c == '"' || c == '\\')
          out += '\\';
        if (c == '\n')
          {
            out += "\\n";
            continue;
          }
        out += c;
      }
    return out + "\"";
  }

  std::string
  json_number(const double x)
  {
    if (!std::isfinite(x))
      return "null";
    char buffer[40];
    std::snprintf(buffer, sizeof(buffer), "%.17g", x);
    return buffer;
  }

  void
  write_json(const std::string                                      &file_name,
             const std::vector<std::pair<std::string, std::string>> &entries)
  {
    write_file_atomically(file_name, [&](std::ostream &out) {
      out << "{\n";
      for (unsigned int i = 0; i < entries.size(); ++i)
        out << "  " << json_string(entries[i].first) << ": "
            << entries[i].second << (i + 1 < entries.size() ? ",\n" : "\n");
      out << "}\n";
    });
  }
} // namespace fsgmpm
