#include <deal.II/base/exceptions.h>

#include <fsgmpm/base/plugin_registry.h>
#include <fsgmpm/monitors/monitor_factory.h>

#include <map>

namespace fsgmpm
{
  namespace MonitorFactory
  {
    namespace
    {
      struct Functions
      {
        std::vector<std::string> quantities;
        Declare                  declare;
        Create<2>                create_2d;
        Create<3>                create_3d;
      };

      PluginRegistry<Functions> &
      registry()
      {
        static PluginRegistry<Functions> monitors("scene monitor");
        return monitors;
      }

      /// Every name Scene monitors accepts -> the monitor it selects.
      std::map<std::string, std::string> &
      selectable()
      {
        static std::map<std::string, std::string> names;
        return names;
      }
    } // namespace



    bool
    register_monitor(const std::string              &name,
                     const std::string              &description,
                     const std::vector<std::string> &quantities,
                     const Declare                  &declare,
                     const Create<2>                &create_2d,
                     const Create<3>                &create_3d)
    {
      AssertThrow(declare && create_2d && create_3d,
                  ExcMessage("Scene monitor '" + name
                             + "': the declare function and both create "
                               "functions are needed."));
      // A monitor's name and quantities share one selection: none may be
      // another monitor's.
      std::vector<std::string> names = {name};
      for (const auto &q : quantities)
        if (q != name)
          names.push_back(q);
      for (const auto &n : names)
        {
          AssertThrow(!n.empty() && n.find_first_of("|,") == std::string::npos,
                      ExcMessage("Scene monitor '" + name
                                 + "': a quantity's name must be non-empty "
                                   "and hold neither '|' nor ','; got '"
                                 + n + "'."));
          const auto taken = selectable().find(n);
          AssertThrow(taken == selectable().end(),
                      ExcMessage("Scene monitor '" + name + "': the name '" + n
                                 + "' is already taken by the scene monitor '"
                                 + taken->second + "'; choose another."));
        }
      registry().add(name,
                     description,
                     Functions{quantities, declare, create_2d, create_3d});
      for (const auto &n : names)
        selectable()[n] = name;
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
      std::string text;
      for (const auto &entry : selectable())
        text += (text.empty() ? "" : "|") + entry.first;
      return text;
    }



    std::string
    documentation()
    {
      std::string text;
      for (const auto &name : registry().names())
        {
          const auto &q = registry().get(name, "").quantities;
          std::string listed;
          for (const auto &n : q)
            listed += (listed.empty() ? "" : ", ") + n;
          text += (text.empty() ? "" : "; ") + name
                  + (listed.empty() ? "" : " (" + listed + ")");
        }
      return text + ". " + registry().documentation();
    }



    void
    declare_parameters(ParameterHandler &prm)
    {
      registry().for_each([&](const Functions &f) { f.declare(prm); });
    }



    std::string
    monitor_of(const std::string &name)
    {
      const auto entry = selectable().find(name);
      if (entry == selectable().end())
        {
          std::string known;
          for (const auto &n : registry().names())
            known += (known.empty() ? "" : ", ") + n;
          std::string columns;
          for (const auto &e : selectable())
            if (e.first != e.second)
              columns += (columns.empty() ? "" : ", ") + e.first;
          AssertThrow(false,
                      ExcMessage("Monitors/Scene monitors = " + name
                                 + " is neither a registered scene monitor "
                                   "nor one of their columns; registered "
                                   "monitors: "
                                 + known + "; columns: " + columns + "."));
        }
      return entry->second;
    }



    template <int dim>
    std::unique_ptr<SceneMonitor<dim>>
    create(const std::string       &name,
           ParameterHandler        &prm,
           const MonitorSetup<dim> &setup)
    {
      const Functions &f = registry().get(name, "Monitors/Scene monitors");
      std::unique_ptr<SceneMonitor<dim>> monitor;
      if constexpr (dim == 2)
        monitor = f.create_2d(prm, setup);
      else
        monitor = f.create_3d(prm, setup);
      AssertThrow(monitor != nullptr,
                  ExcMessage("Scene monitor '" + name + "' built nothing."));
      return monitor;
    }

    template std::unique_ptr<SceneMonitor<2>>
    create<2>(const std::string &, ParameterHandler &, const MonitorSetup<2> &);
    template std::unique_ptr<SceneMonitor<3>>
    create<3>(const std::string &, ParameterHandler &, const MonitorSetup<3> &);
  } // namespace MonitorFactory
} // namespace fsgmpm
