#ifndef fsgmpm_io_monitor_file_h
#define fsgmpm_io_monitor_file_h

#include <cstdio>
#include <string>
#include <vector>

namespace fsgmpm
{
  /**
   * monitors.csv: a header row, then one row per monitored step at full
   * precision (%.17g). Each row goes out in one write and is flushed, so a
   * killed run leaves only complete rows. A non-finite value is written as
   * an empty field: the Eq. (30) ratios are undefined (infinite) while the
   * external work or force is zero; every other column is finite, since the
   * instability guard stops a run before it writes a non-finite state.
   */
  class MonitorFile
  {
  public:
    MonitorFile(const std::string              &file_name,
                const std::vector<std::string> &columns);
    /**
     * Continue an existing monitors.csv (a restart): it must have the same
     * header; it is cut back to its first @p bytes (the rows up to the
     * checkpoint) and appended to.
     */
    MonitorFile(const std::string              &file_name,
                const std::vector<std::string> &columns,
                const unsigned long             bytes);
    ~MonitorFile();

    /// Bytes in the file so far (everything written is flushed).
    unsigned long
    size() const;
    MonitorFile(const MonitorFile &) = delete;
    MonitorFile &
    operator=(const MonitorFile &)
      = delete;

    void
    write_row(const std::vector<double> &values);

  private:
    std::FILE   *file;
    unsigned int n_columns;
  };

  /// The header name of @p column with its SI @p unit (the monitors
  /// declare them: Monitors::units(), SceneMonitor::column_units()):
  /// "column[unit]", or "column" where @p unit is empty (counts, ratios).
  std::string
  monitor_column_header(const std::string &column, const std::string &unit);

  /// The column's name in a header name of monitors.csv, without its
  /// unit: "kinetic_energy[J/m]" -> "kinetic_energy" (for readers).
  std::string
  monitor_column_name(const std::string &header);

  /// Write summary.json (atomically) from ordered key/value pairs whose
  /// values are already JSON (numbers, quoted strings or objects).
  void
  write_json(const std::string                                      &file_name,
             const std::vector<std::pair<std::string, std::string>> &entries);

  /// Quote a string for JSON.
  std::string
  json_string(const std::string &s);

  /// A number for JSON at full precision (non-finite values become null).
  std::string
  json_number(const double x);
} // namespace fsgmpm

#endif
