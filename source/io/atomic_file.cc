#include <deal.II/base/exceptions.h>

#include <fsgmpm/io/atomic_file.h>

#include <cstdio>
#include <unistd.h>

namespace fsgmpm
{
  void
  write_file_atomically(const std::string                         &file_name,
                        const std::function<void(std::ostream &)> &write)
  {
    const std::string tmp
      = file_name + ".tmp." + std::to_string(static_cast<long>(getpid()));
    {
      std::ofstream out(tmp);
      AssertThrow(out.good(),
                  dealii::ExcMessage("Cannot write the file <" + tmp + ">."));
      write(out);
      out.flush();
      if (!out.good())
        {
          out.close();
          std::remove(tmp.c_str());
          AssertThrow(false,
                      dealii::ExcMessage("Writing <" + file_name
                                         + "> failed (is the disk full?)."));
        }
    }
    AssertThrow(std::rename(tmp.c_str(), file_name.c_str()) == 0,
                dealii::ExcMessage("Cannot rename <" + tmp + "> to <"
                                   + file_name + ">."));
  }
} // namespace fsgmpm
