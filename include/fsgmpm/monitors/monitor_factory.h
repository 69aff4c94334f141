#ifndef fsgmpm_monitors_monitor_factory_h
#define fsgmpm_monitors_monitor_factory_h

#include <deal.II/base/parameter_handler.h>

#include <fsgmpm/monitors/scene_monitor.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fsgmpm
{
  /**
   * Registry of the scene monitors that Monitors/Scene monitors may name, as
   * MaterialFactory is for materials and ShapeFactory for body shapes: a
   * monitor registers itself by name, with the quantities it also answers
   * to (the column names of the older selection, e.g. front_position), a
   * function that declares its entries in subsection Monitors and, per
   * dimension, one that builds it. A program adds a monitor in its own
   * source file with FSGMPM_REGISTER_MONITOR; the built-in ones register
   * the same way (source/monitors/).
   */
  namespace MonitorFactory
  {
    /// Declares the monitor's entries (the ParameterHandler is in
    /// subsection Monitors).
    using Declare = std::function<void(ParameterHandler &prm)>;
    /// Reads the entries (in subsection Monitors) and builds the monitor.
    template <int dim>
    using Create = std::function<
      std::unique_ptr<SceneMonitor<dim>>(ParameterHandler        &prm,
                                         const MonitorSetup<dim> &setup)>;

    /// Adds a monitor selectable as @p name and as each of @p quantities.
    /// Throws if a name is empty, holds '|' or ',', or is taken by another
    /// monitor or its quantities. Returns true, to initialise a static.
    bool
    register_monitor(const std::string              &name,
                     const std::string              &description,
                     const std::vector<std::string> &quantities,
                     const Declare                  &declare,
                     const Create<2>                &create_2d,
                     const Create<3>                &create_3d);

    /// The registered monitors' names, sorted.
    std::vector<std::string>
    names();

    /// "name1|quantity1|...": every name Scene monitors accepts.
    std::string
    pattern();

    /// "name1 (its quantities): description1; ..." for the documentation.
    std::string
    documentation();

    /// Declares the entries of every registered monitor.
    void
    declare_parameters(ParameterHandler &prm);

    /// The monitor that @p name selects: itself if it is a monitor's name,
    /// else the monitor that registered it as a quantity. Throws, listing
    /// the registered names, if there is none.
    std::string
    monitor_of(const std::string &name);

    /// Builds the monitor registered as @p name.
    template <int dim>
    std::unique_ptr<SceneMonitor<dim>>
    create(const std::string       &name,
           ParameterHandler        &prm,
           const MonitorSetup<dim> &setup);
  } // namespace MonitorFactory
} // namespace fsgmpm

/**
 * Registers the class template @p classname (template <int dim>, derived
 * from SceneMonitor<dim>, constructible from (ParameterHandler &, const
 * MonitorSetup<dim> &)) as the scene monitor @p name, with its static
 * declare_parameters() and quantities() (SceneMonitor's empty ones unless
 * it has its own). Use once, at namespace scope of a .cc file.
 */
#define FSGMPM_REGISTER_MONITOR(classname, name, description) \
  namespace                                                   \
  {                                                           \
    const bool fsgmpm_monitor_registered_##classname          \
      = ::fsgmpm::MonitorFactory::register_monitor(           \
        name,                                                 \
        description,                                          \
        classname<2>::quantities(),                           \
        [](::dealii::ParameterHandler &prm) {                 \
          classname<2>::declare_parameters(prm);              \
        },                                                    \
        [](::dealii::ParameterHandler      &prm,              \
           const ::fsgmpm::MonitorSetup<2> &setup)            \
          -> std::unique_ptr<::fsgmpm::SceneMonitor<2>> {     \
          return std::make_unique<classname<2>>(prm, setup);  \
        },                                                    \
        [](::dealii::ParameterHandler      &prm,              \
           const ::fsgmpm::MonitorSetup<3> &setup)            \
          -> std::unique_ptr<::fsgmpm::SceneMonitor<3>> {     \
          return std::make_unique<classname<3>>(prm, setup);  \
        });                                                   \
  }

#endif
