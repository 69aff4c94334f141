#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/scene/parameter_path.h>

#include <sstream>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  void
  set_parameter(ParameterHandler  &prm,
                const std::string &path,
                const std::string &value)
  {
    std::vector<std::string> parts = Utilities::split_string_list(path, '/');
    AssertThrow(!parts.empty(),
                ExcMessage("--set needs \"Section/Sub/Name=value\"; got an "
                           "empty name."));
    const std::string name = parts.back();
    parts.pop_back();
    for (const auto &s : parts)
      prm.enter_subsection(s);
    const auto leave = [&] {
      for (unsigned int i = 0; i < parts.size(); ++i)
        prm.leave_subsection();
    };
    try
      {
        prm.set(name, value);
      }
    catch (ParameterHandler::ExcEntryUndeclared &)
      {
        leave();
        AssertThrow(false,
                    ExcMessage("--set: there is no parameter <" + path
                               + ">. Run fsgmpm --print-parameters for the "
                                 "full list."));
      }
    catch (ExceptionBase &e)
      {
        leave();
        std::ostringstream info;
        e.print_info(info);
        AssertThrow(false,
                    ExcMessage("--set: invalid value <" + value + "> for <"
                               + path + ">: " + Utilities::trim(info.str())));
      }
    leave();
  }
} // namespace fsgmpm
