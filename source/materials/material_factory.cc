#include <deal.II/base/exceptions.h>

#include <fsgmpm/base/plugin_registry.h>
#include <fsgmpm/materials/material_factory.h>

namespace fsgmpm
{
  namespace MaterialFactory
  {
    namespace
    {
      struct Functions
      {
        Declare declare;
        Create  create;
      };

      PluginRegistry<Functions> &
      registry()
      {
        static PluginRegistry<Functions> models("material model");
        return models;
      }
    } // namespace



    bool
    register_material(const std::string &name,
                      const std::string &description,
                      const Declare     &declare,
                      const Create      &create)
    {
      AssertThrow(declare && create,
                  ExcMessage("Material model '" + name
                             + "': both the declare and the create function "
                               "are needed."));
      registry().add(name, description, Functions{declare, create});
      return true;
    }



    std::vector<std::string>
    names()
    {
      return registry().names();
    }



    std::string
    pattern()
    {
      return registry().pattern();
    }



    std::string
    documentation()
    {
      return registry().documentation();
    }



    void
    declare_parameters(ParameterHandler &prm)
    {
      registry().for_each([&](const Functions &f) { f.declare(prm); });
    }



    std::unique_ptr<Material>
    create(const std::string &name,
           ParameterHandler  &prm,
           const double       density,
           const std::string &path)
    {
      auto material = registry()
                        .get(name, path + "/Material model")
                        .create(prm, density, path);
      AssertThrow(material != nullptr,
                  ExcMessage("Material model '" + name
                             + "' created nothing for " + path + "."));
      return material;
    }
  } // namespace MaterialFactory
} // namespace fsgmpm
