#ifndef fsgmpm_io_run_log_h
#define fsgmpm_io_run_log_h

#include <cstdio>
#include <memory>
#include <streambuf>
#include <string>

namespace fsgmpm
{
  /**
   * log.txt: what a run shows on the terminal, kept in its output
   * directory. While a RunLog exists, everything written to std::cout and
   * std::cerr still goes to the terminal and is also kept: in memory until
   * open() names the file (the warnings of the scene's setup come before the
   * output directory is known), then in the file, flushed whenever the
   * terminal is. The streams are restored when the RunLog is destroyed.
   */
  class RunLog
  {
  public:
    RunLog();
    ~RunLog();
    RunLog(const RunLog &) = delete;
    RunLog &
    operator=(const RunLog &)
      = delete;

    /// Write what was kept so far to @p file_name, then append to it. A
    /// continued run (@p append: a restart into the same directory) adds
    /// to the file; a new run replaces it. Throws, naming the file, if it
    /// cannot be opened.
    void
    open(const std::string &file_name, const bool append);

  private:
    class Tee;
    /// What was written before open().
    std::string          kept;
    std::FILE           *file = nullptr;
    std::unique_ptr<Tee> out_tee, err_tee;
    std::streambuf      *out_original, *err_original;
  };
} // namespace fsgmpm

#endif
