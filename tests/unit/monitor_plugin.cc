// Scene monitors are plug-ins, as materials and body shapes are:
// a program registers its own monitor in its own source file with
// FSGMPM_REGISTER_MONITOR and selects it by name in Monitors/Scene
// monitors, beside the built-in ones. This file registers "total_mass", the
// mass of one body or of all, read from its own subsection. A block of
// water dropped for 20 ms must write the column total_mass in monitors.csv,
// in the place the selection gives it, equal to rho V in every row (the
// block fills whole cells; measured equal to the last bit in all 1653 rows,
// asserted to 1e-14 relative) and to the built-in body_mass_0 beside it.
// An unknown name is refused with the registered names in the message, a
// monitor that is not selected cannot be looked up, and bad registrations
// are refused.

#include <gtest/gtest.h>

#include <fsgmpm/io/monitor_file.h>
#include <fsgmpm/monitors/monitor_factory.h>
#include <fsgmpm/simulator.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "test_utilities.h"

namespace fsgmpm
{
  namespace
  {
    template <int dim>
    class TotalMass : public SceneMonitor<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Total mass");
        prm.declare_entry("Body",
                          "all",
                          Patterns::Anything(),
                          "The body to weigh, or all.");
        prm.leave_subsection();
      }

      TotalMass(ParameterHandler &prm, const MonitorSetup<dim> &setup)
      {
        prm.enter_subsection("Total mass");
        const std::string text = prm.get("Body");
        prm.leave_subsection();
        if (text != "all")
          {
            body = Utilities::string_to_int(text);
            AssertThrow(body >= 0 && body < int(setup.n_bodies),
                        ExcMessage("Monitors/Total mass/Body must be all or "
                                   "a body's index."));
          }
      }

      std::vector<std::string>
      column_names() const override
      {
        return {"total_mass"};
      }

      // A plug-in declares its columns' units as the shipped monitors do.
      std::vector<std::string>
      column_units() const override
      {
        return {dim == 2 ? "kg/m" : "kg"};
      }

      std::vector<double>
      evaluate(const MonitorContext<dim> &context) const override
      {
        double mass = 0;
        for (unsigned int p = 0; p < context.particles.size(); ++p)
          if (body < 0 || int(context.particles.body_id[p]) == body)
            mass += context.particles.mass[p];
        return {mass};
      }

      int body = -1;
    };
  } // namespace

  FSGMPM_REGISTER_MONITOR(TotalMass,
                          "total_mass",
                          "mass of a body or of all (kg; per metre in 2D)")

  namespace
  {
    std::string
    block_drop(const std::string &monitors)
    {
      return R"(
subsection Simulation
  set End time = 0.02
  set Gravity  = 0, -9.81
end
subsection Grid
  set Lower corner        = 0, 0
  set Upper corner        = 1, 0.6
  set Subdivisions        = 20, 12
  set Boundary conditions = 0: roller, 1: roller, 2: roller, 3: free
end
subsection Bodies
  subsection Body 0
    set Shape              = box
    set Box lower corner   = 0.3, 0.05
    set Box upper corner   = 0.7, 0.25
    set Particles per cell = 4
    set Density            = 1000
    set Material model     = Newtonian fluid
  end
end
subsection Monitors
  set Scene monitors = )"
             + monitors + R"(
  subsection Total mass
    set Body = 0
  end
end
subsection Output
  set Directory       = output_monitor_plugin
  set Write particles = false
  set Quiet           = true
end
)";
    }

    std::vector<std::string>
    split(const std::string &line)
    {
      std::vector<std::string> items;
      std::stringstream        in(line);
      for (std::string item; std::getline(in, item, ',');)
        items.push_back(item);
      return items;
    }
  } // namespace

  TEST(MonitorPlugin, RegisteredMonitorWritesItsColumn)
  {
    const auto names = MonitorFactory::names();
    for (const std::string name : {"total_mass",
                                   "bodies",
                                   "container",
                                   "dam_break",
                                   "deposit",
                                   "geotube"})
      EXPECT_NE(std::find(names.begin(), names.end(), name), names.end())
        << name;

    auto prm
      = test_tools::make_parameters(block_drop("front_position, total_mass, "
                                               "body_mass"));
    Simulator<2> sim(*prm);
    EXPECT_EQ(sim.get_scene_monitor_names(),
              (std::vector<std::string>{"front_position",
                                        "total_mass",
                                        "body_mass_0"}));
    // Looked up by name, as the class the test registered.
    const auto *monitor = dynamic_cast<const TotalMass<2> *>(
      &sim.get_scene_monitor("total_mass"));
    ASSERT_NE(monitor, nullptr);
    EXPECT_EQ(monitor->body, 0);
    EXPECT_NE(&sim.get_scene_monitor("dam_break"), nullptr);
    EXPECT_THROW(sim.get_scene_monitor("geotube"), ExceptionBase);
    EXPECT_THROW(sim.get_scene_monitor_value("height"), ExceptionBase);

    EXPECT_EQ(sim.run(), Termination::end_time);
    const double exact = 1000 * 0.4 * 0.2;
    EXPECT_NEAR(sim.get_scene_monitor_value("total_mass") / exact, 1., 1e-14);

    std::ifstream in("output_monitor_plugin/monitors.csv");
    ASSERT_TRUE(in) << "no monitors.csv";
    std::string line;
    std::getline(in, line);
    // The header names carry the units the monitors declare
    // ("front_position[m]"), the plug-in's too.
    auto header = split(line);
    EXPECT_EQ(header[0], "time[s]");
    EXPECT_NE(std::find(header.begin(), header.end(), "kinetic_energy[J/m]"),
              header.end())
      << line;
    EXPECT_NE(std::find(header.begin(), header.end(), "front_position[m]"),
              header.end())
      << line;
    EXPECT_EQ(header.back(), "body_mass_0[kg/m]");
    EXPECT_NE(std::find(header.begin(), header.end(), "total_mass[kg/m]"),
              header.end())
      << line;
    for (auto &name : header)
      name = monitor_column_name(name);
    const auto column = std::find(header.begin(), header.end(), "total_mass");
    ASSERT_NE(column, header.end()) << line;
    const unsigned int k = column - header.begin();
    // The selection's order: front_position before, body_mass_0 after.
    EXPECT_EQ(header[k - 1], "front_position");
    ASSERT_EQ(header.back(), "body_mass_0");
    unsigned int rows  = 0;
    double       worst = 0;
    while (std::getline(in, line))
      {
        const auto   row  = split(line);
        const double mass = std::stod(row[k]);
        worst             = std::max(worst, std::abs(mass / exact - 1));
        EXPECT_EQ(mass, std::stod(row.back()));
        ++rows;
      }
    std::cout << "[ measured ] total_mass in " << rows
              << " rows of monitors.csv: largest relative difference from "
                 "rho V = "
              << exact << " kg/m: " << worst << std::endl;
    EXPECT_GT(rows, 10u);
    EXPECT_LE(worst, 1e-14);
  }

  TEST(MonitorPlugin, UnknownNamesAndBadRegistrations)
  {
    // An unknown name is refused when the prm is read, with the registered
    // names in the message.
    try
      {
        test_tools::make_parameters(block_drop("front_position, no_such"));
        ADD_FAILURE() << "an unknown scene monitor was accepted";
      }
    catch (const ExceptionBase &e)
      {
        const std::string message = e.what();
        std::cout << "[ message ] "
                  << message.substr(std::min(message.find("Additional"),
                                             message.size()),
                                    300)
                  << " ..." << std::endl;
        for (const std::string name : {"no_such", "total_mass", "dam_break"})
          EXPECT_NE(message.find(name), std::string::npos) << name;
      }
    try
      {
        MonitorFactory::monitor_of("no_such");
        ADD_FAILURE() << "monitor_of(no_such) returned";
      }
    catch (const ExceptionBase &e)
      {
        const std::string message = e.what();
        std::cout << "[ message ] "
                  << message.substr(std::min(message.find("Additional"),
                                             message.size()),
                                    300)
                  << " ..." << std::endl;
        for (const std::string name : {"no_such", "total_mass", "geotube"})
          EXPECT_NE(message.find(name), std::string::npos) << name;
      }
    EXPECT_EQ(MonitorFactory::monitor_of("front_position"), "dam_break");
    EXPECT_EQ(MonitorFactory::monitor_of("total_mass"), "total_mass");

    // A membrane monitor in a scene without a membrane.
    auto prm = test_tools::make_parameters(block_drop("height"));
    EXPECT_THROW(Simulator<2> sim(*prm), ExceptionBase);

    const auto declare = [](ParameterHandler &) {};
    const auto create2 = [](ParameterHandler &, const MonitorSetup<2> &)
      -> std::unique_ptr<SceneMonitor<2>> { return nullptr; };
    const auto create3 = [](ParameterHandler &, const MonitorSetup<3> &)
      -> std::unique_ptr<SceneMonitor<3>> { return nullptr; };
    // A taken monitor name, a taken quantity, bad characters.
    for (const auto &[name, quantity] :
         std::vector<std::pair<std::string, std::string>>{
           {"total_mass", "x"},
           {"other", "front_position"},
           {"front_position", "y"},
           {"a|b", "z"},
           {"", "w"},
           {"other", "a,b"}})
      EXPECT_THROW(MonitorFactory::register_monitor(
                     name, "refused", {quantity}, declare, create2, create3),
                   ExceptionBase)
        << "'" << name << "', '" << quantity << "'";
  }
} // namespace fsgmpm
