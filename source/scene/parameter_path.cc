#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/scene/parameter_file_check.h>
#include <fsgmpm/scene/parameter_path.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cctype>
#include <functional>
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
        std::vector<std::string> paths;
        for (const auto &[p, value] : parameter_values(prm))
          paths.push_back(p);
        const std::string near = nearest_name(path, paths);
        AssertThrow(false,
                    ExcMessage("--set: there is no parameter <" + path + ">."
                               + (near.empty()
                                    ? std::string()
                                    : " Did you mean <" + near + ">?")
                               + " Run fsgmpm --print-parameters for the "
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



  std::string
  demangle_parameter_name(const std::string &s)
  {
    std::string out;
    for (unsigned int i = 0; i < s.size(); ++i)
      if (s[i] == '_' && i + 2 < s.size() + 0 && std::isxdigit(s[i + 1])
          && std::isxdigit(s[i + 2]))
        {
          out += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
          i += 2;
        }
      else
        out += s[i];
    return out;
  }



  boost::property_tree::ptree
  parameter_tree(const ParameterHandler &prm)
  {
    std::stringstream json;
    prm.print_parameters(json,
                         ParameterHandler::OutputStyle(
                           ParameterHandler::JSON
                           | ParameterHandler::KeepDeclarationOrder));
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(json, tree);
    return tree;
  }



  std::vector<std::pair<std::string, std::string>>
  parameter_values(const ParameterHandler &prm)
  {
    const auto                                       tree = parameter_tree(prm);
    std::vector<std::pair<std::string, std::string>> values;
    std::function<void(const boost::property_tree::ptree &,
                       const std::string &)>
      walk = [&](const boost::property_tree::ptree &node,
                 const std::string                 &prefix) {
        for (const auto &[name, child] : node)
          {
            const std::string path = prefix + demangle_parameter_name(name);
            if (child.count("value") == 1)
              values.emplace_back(path, child.get<std::string>("value"));
            else
              walk(child, path + "/");
          }
      };
    walk(tree, "");
    return values;
  }
} // namespace fsgmpm
