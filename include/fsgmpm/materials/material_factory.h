#ifndef fsgmpm_materials_material_factory_h
#define fsgmpm_materials_material_factory_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/materials/material.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fsgmpm
{
  /**
   * Registry of the constitutive models a body's `Material model` may name,
   * in the manner of ASPECT's plugins: a model registers itself by name,
   * with a function that declares its parameter subsection and one that
   * reads it and creates the model, so a program adds a material in its own
   * source file without editing the library. The built-in models register
   * the same way (FSGMPM_REGISTER_MATERIAL at the end of their .cc files).
   *
   * Registration runs during static initialisation, before main() and so
   * before any parameter is declared; the body's `Material model` pattern
   * lists every model registered by then.
   */
  namespace MaterialFactory
  {
    /// Declares the model's entries inside the body's subsection (its own
    /// subsection within it, by convention named like the model).
    using Declare = std::function<void(ParameterHandler &prm)>;
    /// Reads and validates the model's entries (the ParameterHandler is in
    /// the body's subsection); @p path names the body in error messages.
    using Create
      = std::function<std::unique_ptr<Material>(ParameterHandler  &prm,
                                                const double       density,
                                                const std::string &path)>;

    /// Adds a model. Throws if the name is empty, holds '|' or ',', or is
    /// taken. Returns true, so that it can initialise a static variable.
    bool
    register_material(const std::string &name,
                      const std::string &description,
                      const Declare     &declare,
                      const Create      &create);

    /// The registered names, sorted.
    std::vector<std::string>
    names();

    /// "name1|name2|..." for the `Material model` pattern.
    std::string
    pattern();

    /// "name1: description1; name2: ..." for the parameter documentation.
    std::string
    documentation();

    /// Declares the parameters of every registered model.
    void
    declare_parameters(ParameterHandler &prm);

    /// Creates the model registered as @p name (throws, listing the
    /// registered names, if there is none).
    std::unique_ptr<Material>
    create(const std::string &name,
           ParameterHandler  &prm,
           const double       density,
           const std::string &path);
  } // namespace MaterialFactory
} // namespace fsgmpm

/**
 * Registers @p classname, which has the static functions
 * `declare_parameters(ParameterHandler &)` and
 * `create(ParameterHandler &, double density, const std::string &path)`,
 * as the material model @p name. Use once, at namespace scope of a .cc file.
 */
#define FSGMPM_REGISTER_MATERIAL(classname, name, description)               \
  namespace                                                                  \
  {                                                                          \
    const bool fsgmpm_material_registered_##classname                        \
      = ::fsgmpm::MaterialFactory::register_material(                        \
        name,                                                                \
        description,                                                         \
        [](::dealii::ParameterHandler &prm) {                                \
          classname::declare_parameters(prm);                                \
        },                                                                   \
        [](::dealii::ParameterHandler &prm,                                  \
           const double                density,                              \
           const std::string &path) -> std::unique_ptr<::fsgmpm::Material> { \
          return classname::create(prm, density, path);                      \
        });                                                                  \
  }

#endif
