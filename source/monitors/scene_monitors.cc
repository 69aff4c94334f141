#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/base/parameter_parsing.h>
#include <fsgmpm/monitors/monitor_factory.h>
#include <fsgmpm/monitors/scene_monitors.h>

#include <algorithm>

namespace fsgmpm
{
  template <int dim>
  void
  SceneMonitors<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Monitors");
    prm.declare_entry(
      "Scene monitors",
      "",
      Patterns::MultipleSelection(MonitorFactory::pattern()),
      "Extra columns of monitors.csv, in the order given: the name of a "
      "registered scene monitor gives all its columns, one of its "
      "quantities (the names in parentheses) its own column (body_mass and "
      "body_kinetic_energy: one per body, body_mass_0, body_mass_1, ...). "
      "Registered: "
        + MonitorFactory::documentation());
    prm.declare_entry("Container body",
                      "0",
                      Patterns::Integer(0),
                      "Index of the body the membrane holds (the fill), for "
                      "the container and geotube columns.");
    prm.declare_entry("Wall position",
                      "auto",
                      Patterns::Anything(),
                      "x of the wall the column stands against (m); auto: "
                      "the mesh's smallest x.");
    prm.declare_entry("Base position",
                      "auto",
                      Patterns::Anything(),
                      "y of the base (m); auto: the mesh's smallest y.");
    MonitorFactory::declare_parameters(prm);
    prm.leave_subsection();
  }



  template <int dim>
  SceneMonitors<dim>::SceneMonitors(ParameterHandler  &prm,
                                    const Point<dim>  &lower,
                                    const Point<dim>  &cell_size,
                                    const unsigned int n_bodies,
                                    const bool         has_membrane)
  {
    prm.enter_subsection("Monitors");
    MonitorSetup<dim> setup;
    setup.lower_corner   = lower;
    setup.cell_size      = cell_size;
    setup.n_bodies       = n_bodies;
    setup.has_membrane   = has_membrane;
    setup.container_body = prm.get_integer("Container body");
    AssertThrow(setup.container_body < n_bodies,
                ExcMessage("Monitors/Container body is "
                           + std::to_string(setup.container_body)
                           + ", but there "
                           + (n_bodies == 1
                                ? "is 1 body"
                                : "are " + std::to_string(n_bodies) + " bodies")
                           + " (Bodies/Number of bodies); give the index of "
                             "the body the membrane holds."));
    setup.wall_x = parse_auto_or_double(prm.get("Wall position"),
                                        lower[0],
                                        "Monitors/Wall position");
    setup.base_y = parse_auto_or_double(prm.get("Base position"),
                                        lower[1],
                                        "Monitors/Base position");

    for (const auto &name :
         Utilities::split_string_list(prm.get("Scene monitors"), ','))
      {
        if (name.empty())
          continue;
        const std::string monitor_name = MonitorFactory::monitor_of(name);
        unsigned int      m            = 0;
        while (m < monitors.size() && monitors[m].first != monitor_name)
          ++m;
        if (m == monitors.size())
          {
            monitors.emplace_back(monitor_name,
                                  MonitorFactory::create<dim>(monitor_name,
                                                              prm,
                                                              setup));
            n_columns.push_back(monitors.back().second->column_names().size());
            AssertThrow(!monitors.back().second->needs_membrane()
                          || has_membrane,
                        ExcMessage("Monitors/Scene monitors: " + name
                                   + " (scene monitor " + monitor_name
                                   + ") needs a membrane, but "
                                     "Membrane/Enabled is false."));
          }
        const SceneMonitor<dim> &monitor = *monitors[m].second;
        const auto               all     = monitor.column_names();
        const auto               units   = monitor.column_units();
        AssertThrow(units.size() == all.size(),
                    ExcMessage("Scene monitor " + monitor_name + " gives "
                               + std::to_string(units.size())
                               + " units for its " + std::to_string(all.size())
                               + " columns (column_units() must give one "
                                 "per column, empty for a number)."));
        for (const auto &column :
             name == monitor_name ? all : monitor.columns_of(name))
          {
            const auto j = std::find(all.begin(), all.end(), column);
            AssertThrow(j != all.end(),
                        ExcMessage("Scene monitor " + monitor_name
                                   + ": the column " + column + " of " + name
                                   + " is not among its columns."));
            columns.push_back(column);
            column_units.push_back(units[j - all.begin()]);
            source.emplace_back(m, j - all.begin());
          }
      }
    prm.leave_subsection();
  }



  template <int dim>
  std::string
  SceneMonitors<dim>::not_distributed() const
  {
    std::string names;
    for (const auto &m : monitors)
      if (!m.second->values_are_maxima()
          && !m.second->combines_over_processes())
        names += (names.empty() ? "" : ", ") + m.first;
    return names;
  }



  template <int dim>
  bool
  SceneMonitors<dim>::needs_membrane() const
  {
    for (const auto &m : monitors)
      if (m.second->needs_membrane())
        return true;
    return false;
  }



  template <int dim>
  std::vector<double>
  SceneMonitors<dim>::evaluate(const ParticleStore<dim> &particles,
                               const Membrane<dim>      *membrane,
                               const MPI_Comm            communicator) const
  {
    const MonitorContext<dim>        context{particles, membrane, communicator};
    std::vector<std::vector<double>> values;
    for (unsigned int i = 0; i < monitors.size(); ++i)
      {
        const auto &m = monitors[i];
        AssertThrow(!m.second->needs_membrane() || membrane != nullptr,
                    ExcMessage("Scene monitor " + m.first
                               + " needs a membrane (Membrane/Enabled)."));
        values.push_back(m.second->evaluate(context));
        AssertThrow(values.back().size() == n_columns[i],
                    ExcMessage("Scene monitor " + m.first + " gave "
                               + std::to_string(values.back().size())
                               + " values for its "
                               + std::to_string(n_columns[i]) + " columns."));
      }
    std::vector<double> row;
    row.reserve(source.size());
    for (const auto &s : source)
      row.push_back(values[s.first][s.second]);
    return row;
  }



  template <int dim>
  const SceneMonitor<dim> &
  SceneMonitors<dim>::get(const std::string &name) const
  {
    const auto m
      = std::find_if(monitors.begin(), monitors.end(), [&](const auto &entry) {
          return entry.first == name;
        });
    if (m == monitors.end())
      {
        std::string selected;
        for (const auto &entry : monitors)
          selected += (selected.empty() ? "" : ", ") + entry.first;
        AssertThrow(false,
                    ExcMessage("The scene monitor " + name
                               + " is not selected in Monitors/Scene "
                                 "monitors (selected: "
                               + (selected.empty() ? "none" : selected)
                               + ")."));
      }
    return *m->second;
  }

  template class SceneMonitors<2>;
  template class SceneMonitors<3>;
} // namespace fsgmpm
