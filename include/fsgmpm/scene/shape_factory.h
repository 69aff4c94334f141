#ifndef fsgmpm_scene_shape_factory_h
#define fsgmpm_scene_shape_factory_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/particles/body_shape.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fsgmpm
{
  /**
   * Registry of the regions a body's `Shape` may name (besides `membrane`,
   * the inside of the scene's membrane), as MaterialFactory is for
   * materials: a shape registers itself by name with a function that
   * declares its entries in the body's subsection and, per dimension, one
   * that reads them and creates the shape. A program adds a shape in its
   * own source file with FSGMPM_REGISTER_SHAPE; the built-in box, column,
   * ellipse and polygon register the same way (scene/shapes.cc).
   */
  namespace ShapeFactory
  {
    /// Declares the shape's entries inside the body's subsection. Entries
    /// are shared by all shapes of the subsection, so a shape must not
    /// declare a name another shape declares (it may read it).
    using Declare = std::function<void(ParameterHandler &prm)>;
    /// Reads and validates the entries (the ParameterHandler is in the
    /// body's subsection; @p path, "Bodies/Body N", names it in messages).
    template <int dim>
    using Create
      = std::function<std::unique_ptr<BodyShape<dim>>(ParameterHandler  &prm,
                                                      const std::string &path)>;

    /// Adds a shape. Throws if the name is empty, holds '|' or ',', is
    /// taken or is "membrane". Returns true, to initialise a static.
    bool
    register_shape(const std::string &name,
                   const std::string &description,
                   const Declare     &declare,
                   const Create<2>   &create_2d,
                   const Create<3>   &create_3d);

    /// "box|column|..." for the `Shape` pattern (without membrane).
    std::string
    pattern();

    /// "name1: description1; ..." for the parameter documentation.
    std::string
    documentation();

    /// Declares the entries of every registered shape.
    void
    declare_parameters(ParameterHandler &prm);

    /// Creates the shape registered as @p name; the result's `parameters`
    /// names the body's shape entries when the shape left it empty.
    template <int dim>
    std::unique_ptr<BodyShape<dim>>
    create(const std::string &name,
           ParameterHandler  &prm,
           const std::string &path);
  } // namespace ShapeFactory
} // namespace fsgmpm

/**
 * Registers the class template @p classname (template <int dim>), which
 * has the static functions `declare_parameters(ParameterHandler &)` and
 * `create(ParameterHandler &, const std::string &path)` returning
 * std::unique_ptr<BodyShape<dim>>, as the body shape @p name. A shape that
 * exists in one dimension only throws from the other's create(). Use once,
 * at namespace scope of a .cc file.
 */
#define FSGMPM_REGISTER_SHAPE(classname, name, description)            \
  namespace                                                            \
  {                                                                    \
    const bool fsgmpm_shape_registered_##classname                     \
      = ::fsgmpm::ShapeFactory::register_shape(                        \
        name,                                                          \
        description,                                                   \
        [](::dealii::ParameterHandler &prm) {                          \
          classname<2>::declare_parameters(prm);                       \
        },                                                             \
        [](::dealii::ParameterHandler &prm, const std::string &path) { \
          return classname<2>::create(prm, path);                      \
        },                                                             \
        [](::dealii::ParameterHandler &prm, const std::string &path) { \
          return classname<3>::create(prm, path);                      \
        });                                                            \
  }

#endif
