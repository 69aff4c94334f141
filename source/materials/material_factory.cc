#include <deal.II/base/exceptions.h>

#include <fsgmpm/materials/material_factory.h>

#include <map>

namespace fsgmpm
{
  namespace MaterialFactory
  {
    namespace
    {
      struct Entry
      {
        std::string description;
        Declare     declare;
        Create      create;
      };

      // A function-local static: registrations from other translation
      // units may run before this file's own static initialisation.
      std::map<std::string, Entry> &
      registry()
      {
        static std::map<std::string, Entry> models;
        return models;
      }
    } // namespace



    bool
    register_material(const std::string &name,
                      const std::string &description,
                      const Declare     &declare,
                      const Create      &create)
    {
      AssertThrow(!name.empty()
                    && name.find_first_of("|,") == std::string::npos,
                  ExcMessage("A material model's name must be non-empty and "
                             "hold neither '|' nor ','; got '"
                             + name + "'."));
      AssertThrow(registry().count(name) == 0,
                  ExcMessage("A material model named '" + name
                             + "' is already registered; choose another "
                               "name."));
      AssertThrow(declare && create,
                  ExcMessage("Material model '" + name
                             + "': both the declare and the create function "
                               "are needed."));
      registry()[name] = Entry{description, declare, create};
      return true;
    }



    std::vector<std::string>
    names()
    {
      std::vector<std::string> result;
      for (const auto &entry : registry())
        result.push_back(entry.first);
      return result;
    }



    std::string
    documentation()
    {
      std::string text;
      for (const auto &entry : registry())
        text += (text.empty() ? "" : "; ") + entry.first + ": "
                + entry.second.description;
      return text;
    }



    void
    declare_parameters(ParameterHandler &prm)
    {
      for (const auto &entry : registry())
        entry.second.declare(prm);
    }



    std::unique_ptr<Material>
    create(const std::string &name,
           ParameterHandler  &prm,
           const double       density,
           const std::string &path)
    {
      const auto entry = registry().find(name);
      if (entry == registry().end())
        {
          std::string known;
          for (const std::string &n : names())
            known += (known.empty() ? "" : ", ") + n;
          AssertThrow(false,
                      ExcMessage(path + "/Material model = " + name
                                 + " is not a registered material model; "
                                   "registered: "
                                 + known + "."));
        }
      auto material = entry->second.create(prm, density, path);
      AssertThrow(material != nullptr,
                  ExcMessage("Material model '" + name
                             + "' created nothing for " + path + "."));
      return material;
    }
  } // namespace MaterialFactory
} // namespace fsgmpm
