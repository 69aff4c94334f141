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

  /**
   * The unit of a column of monitors.csv, as its header writes it
   * ("name[unit]"): SI, per metre of thickness in 2D (energies J/m, masses
   * kg/m, the points' areas m^2), of the whole body in 3D (J, kg, m^3).
   * Membrane tensions are N/m in both. Empty for counts and ratios (step,
   * lost_particles, dr_energy_ratio, ...) and for a column the table does
   * not know (a plug-in monitor's).
   */
  std::string
  monitor_column_unit(const std::string &column, const unsigned int dim);

  /// The header name of @p column: "column[unit]", or "column" without a
  /// unit.
  std::string
  monitor_column_header(const std::string &column, const unsigned int dim);

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
