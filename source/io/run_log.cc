#include <deal.II/base/exceptions.h>

#include <fsgmpm/io/run_log.h>

#include <iostream>

namespace fsgmpm
{
  /// A stream buffer that passes everything on to the terminal's buffer
  /// and keeps a copy in the RunLog.
  class RunLog::Tee : public std::streambuf
  {
  public:
    Tee(std::streambuf *terminal, RunLog &log)
      : terminal(terminal)
      , log(log)
    {}

  protected:
    int_type
    overflow(int_type c) override
    {
      if (traits_type::eq_int_type(c, traits_type::eof()))
        return traits_type::not_eof(c);
      const char ch = traits_type::to_char_type(c);
      keep(&ch, 1);
      return terminal->sputc(ch);
    }

    std::streamsize
    xsputn(const char *s, std::streamsize n) override
    {
      keep(s, n);
      return terminal->sputn(s, n);
    }

    int
    sync() override
    {
      if (log.file != nullptr)
        std::fflush(log.file);
      return terminal->pubsync();
    }

  private:
    void
    keep(const char *s, const std::streamsize n)
    {
      if (log.file != nullptr)
        std::fwrite(s, 1, n, log.file);
      else
        log.kept.append(s, n);
    }

    std::streambuf *terminal;
    RunLog         &log;
  };



  RunLog::RunLog()
    : out_tee(std::make_unique<Tee>(std::cout.rdbuf(), *this))
    , err_tee(std::make_unique<Tee>(std::cerr.rdbuf(), *this))
    , out_original(std::cout.rdbuf(out_tee.get()))
    , err_original(std::cerr.rdbuf(err_tee.get()))
  {}



  RunLog::~RunLog()
  {
    std::cout.flush();
    std::cerr.flush();
    std::cout.rdbuf(out_original);
    std::cerr.rdbuf(err_original);
    if (file != nullptr)
      std::fclose(file);
  }



  void
  RunLog::open(const std::string &file_name, const bool append)
  {
    std::FILE *f = std::fopen(file_name.c_str(), append ? "a" : "w");
    AssertThrow(f != nullptr,
                dealii::ExcMessage("Output/Directory: cannot write the log <"
                                   + file_name + ">."));
    std::fwrite(kept.data(), 1, kept.size(), f);
    std::fflush(f);
    kept.clear();
    file = f;
  }
} // namespace fsgmpm
