#include <deal.II/base/exceptions.h>

#include <fsgmpm/base/plugin_registry.h>
#include <fsgmpm/scene/shape_factory.h>

namespace fsgmpm
{
  namespace ShapeFactory
  {
    namespace
    {
      struct Functions
      {
        Declare   declare;
        Create<2> create_2d;
        Create<3> create_3d;
      };

      PluginRegistry<Functions> &
      registry()
      {
        static PluginRegistry<Functions> shapes("body shape");
        return shapes;
      }
    } // namespace



    bool
    register_shape(const std::string &name,
                   const std::string &description,
                   const Declare     &declare,
                   const Create<2>   &create_2d,
                   const Create<3>   &create_3d)
    {
      AssertThrow(name != "membrane",
                  ExcMessage("The body shape name 'membrane' is reserved "
                             "for the inside of the scene's membrane."));
      AssertThrow(declare && create_2d && create_3d,
                  ExcMessage("Body shape '" + name
                             + "': the declare function and both create "
                               "functions are needed."));
      registry().add(name,
                     description,
                     Functions{declare, create_2d, create_3d});
      return true;
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



    template <int dim>
    std::unique_ptr<BodyShape<dim>>
    create(const std::string &name,
           ParameterHandler  &prm,
           const std::string &path)
    {
      const Functions                &f = registry().get(name, path + "/Shape");
      std::unique_ptr<BodyShape<dim>> shape;
      if constexpr (dim == 2)
        shape = f.create_2d(prm, path);
      else
        shape = f.create_3d(prm, path);
      AssertThrow(shape != nullptr,
                  ExcMessage("Body shape '" + name + "' created nothing for "
                             + path + "."));
      if (shape->parameters.empty())
        shape->parameters = path + "/Shape = " + name;
      return shape;
    }

    template std::unique_ptr<BodyShape<2>>
    create<2>(const std::string &, ParameterHandler &, const std::string &);
    template std::unique_ptr<BodyShape<3>>
    create<3>(const std::string &, ParameterHandler &, const std::string &);
  } // namespace ShapeFactory
} // namespace fsgmpm
