/**
 * fsgmpm: coupled FEM-MPM solver for fluid-soil-geomembrane interaction.
 *
 *   fsgmpm [scene.prm] [--set "Section/Sub/Name=value"]... [--restart DIR]
 *   fsgmpm --help | --print-parameters [scene.prm] | --version
 *
 * The whole command line and the scene are validated (and the grid and
 * bodies built) before anything is written.
 */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/base/version.h>
#include <fsgmpm/default_scene.h>
#include <fsgmpm/io/run_log.h>
#include <fsgmpm/run/interruption.h>
#include <fsgmpm/scene/parameter_file_check.h>
#include <fsgmpm/scene/parameter_path.h>
#include <fsgmpm/scene/parameters.h>
#include <fsgmpm/simulator.h>
#include <fsgmpm/source_dir.h>

#include <boost/property_tree/ptree.hpp>

#include <cstdio>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;

  const char *usage
    = "Usage: fsgmpm [scene.prm] [--set \"Section/Sub/Name=value\"]... "
      "[--restart DIR]\n"
      "       fsgmpm --print-parameters [scene.prm] [--set ...]\n"
      "       fsgmpm --help | --version\n"
      "\n"
      "Runs the scene described by the parameter file (without one, the\n"
      "built-in default scene prm/default_dam_break.prm: a coarse collapse\n"
      "of a water column, real water, about half a minute).\n"
      "Output (VTU/PVD, monitors.csv, summary.json) goes to Output/Directory.\n"
      "\n"
      "  --set \"Path/Name=value\"  override one parameter after reading the\n"
      "                           file, e.g. --set \"Simulation/End "
      "time=0.1\"\n"
      "  --restart DIR            continue the run whose output is in DIR\n"
      "                           from its newest intact checkpoint\n"
      "                           (Output/Checkpoint interval > 0), with the\n"
      "                           same scene; it writes on into DIR\n"
      "  --print-parameters       print every parameter with its current "
      "value,\n"
      "                           default, allowed range and documentation\n"
      "  --help                   this text\n"
      "  --version                print the version\n"
      "\n"
      "Exit status: 0 finished (end time, step limit, at rest or converged),\n"
      "1 bad input or error, 3 the run became unstable (see the diagnosis and\n"
      "summary.json), 130 or 143 stopped by SIGINT or SIGTERM after its step\n"
      "(a checkpoint written where enabled; termination interrupted).\n";

  /// Apply one --set override; errors name the full path.
  void
  apply_override(ParameterHandler &prm, const std::string &arg)
  {
    const auto eq = arg.find('=');
    AssertThrow(eq != std::string::npos && eq > 0,
                ExcMessage("--set needs \"Section/Sub/Name=value\"; got <" + arg
                           + ">."));
    fsgmpm::set_parameter(prm,
                          Utilities::trim(arg.substr(0, eq)),
                          Utilities::trim(arg.substr(eq + 1)));
  }

  /// Print every parameter as a valid prm file: documentation, default and
  /// allowed values as comments above each "set" line with the current value.
  void
  print_parameter_manual(const ParameterHandler &prm, std::ostream &out)
  {
    const boost::property_tree::ptree tree = fsgmpm::parameter_tree(prm);
    std::function<void(const boost::property_tree::ptree &, unsigned int)> print
      = [&](const boost::property_tree::ptree &node, unsigned int depth) {
          const std::string indent(2 * depth, ' ');
          for (const auto &[name, child] : node)
            {
              const std::string key = fsgmpm::demangle_parameter_name(name);
              if (child.count("value") == 1)
                {
                  out << indent << "# "
                      << child.get<std::string>("documentation") << "\n"
                      << indent << "# Default: "
                      << child.get<std::string>("default_value")
                      << "; allowed: "
                      << child.get<std::string>("pattern_description") << "\n"
                      << indent << "set " << key << " = "
                      << child.get<std::string>("value") << "\n\n";
                }
              else
                {
                  out << indent << "subsection " << key << "\n";
                  print(child, depth + 1);
                  out << indent << "end\n\n";
                }
            }
        };
    print(tree, 0);
  }

  /// The run's input into its output directory, so that it explains
  /// itself: parameters.prm (every entry with its resolved value, as
  /// --print-parameters writes it; it runs as a scene file) and
  /// command_line.txt (the version and the command). Each is written to a
  /// temporary name and renamed, so that no half-written file is left.
  void
  write_run_input(ParameterHandler            &prm,
                  const std::string           &command,
                  const std::filesystem::path &dir)
  {
    namespace fs = std::filesystem;
    if (Utilities::MPI::job_supports_mpi()
        && Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    fs::create_directories(dir);
    const auto write = [&](const std::string                         &name,
                           const std::function<void(std::ostream &)> &body) {
      const fs::path target = dir / name;
      const fs::path tmp    = dir / (name + ".tmp");
      {
        std::ofstream out(tmp);
        AssertThrow(out,
                    ExcMessage("Output/Directory: cannot write <" + tmp.string()
                               + ">."));
        body(out);
        AssertThrow(out,
                    ExcMessage("Output/Directory: writing <" + tmp.string()
                               + "> failed."));
      }
      fs::rename(tmp, target);
    };
    write("parameters.prm",
          [&](std::ostream &out) { print_parameter_manual(prm, out); });
    write("command_line.txt", [&](std::ostream &out) {
      out << "fsgmpm " << fsgmpm::version_string() << "\n" << command << "\n";
    });
  }

  /// The argument quoted for a POSIX shell.
  std::string
  shell_quoted(const std::string &text)
  {
    std::string quoted = "'";
    for (const char c : text)
      quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
  }

  /// Output/Report: doc/scripts/plot.py of the source tree plots the
  /// finished run's monitors into DIR/report.png. What the script says
  /// goes to standard error (and log.txt); a failure is a warning, since
  /// the run's results are complete without the picture.
  void
  write_report(const std::filesystem::path &dir)
  {
    const std::filesystem::path script
      = std::filesystem::path(fsgmpm::source_directory) / "doc" / "scripts"
        / "plot.py";
    const std::filesystem::path png = dir / "report.png";
    if (!std::filesystem::exists(script))
      {
        std::cerr << "fsgmpm: warning: Output/Report: no " << script.string()
                  << " (the source tree this program was built from); no "
                     "report written."
                  << std::endl;
        return;
      }
    const std::string command = "/usr/bin/python3 " + shell_quoted(script) + " "
                                + shell_quoted(dir) + " -o " + shell_quoted(png)
                                + " 2>&1";
    std::FILE  *pipe = popen(command.c_str(), "r");
    std::string said;
    if (pipe != nullptr)
      {
        char buffer[512];
        while (std::fgets(buffer, sizeof(buffer), pipe) != nullptr)
          said += buffer;
      }
    const int status = pipe != nullptr ? pclose(pipe) : -1;
    std::cerr << said;
    if (status == 0 && std::filesystem::exists(png))
      std::cerr << "fsgmpm: report written to " << png.string() << std::endl;
    else
      std::cerr << "fsgmpm: warning: Output/Report: " << script.string()
                << " failed; no report written (it needs "
                   "python3-matplotlib)."
                << std::endl;
  }

  template <int dim>
  int
  run_scene(ParameterHandler  &prm,
            const std::string &restart_directory,
            const std::string &command,
            fsgmpm::RunLog    *run_log)
  {
    fsgmpm::Simulator<dim> simulator(prm);
    if (!restart_directory.empty())
      simulator.restart(restart_directory);
    // After the scene has been validated and built: nothing is written for
    // a run that cannot start.
    // The run's directory (a restart continues in the one it names).
    const std::filesystem::path dir
      = simulator.get_parameters().output_directory;
    write_run_input(prm, command, dir);
    // log.txt from the start (the setup's warnings), continued on a restart.
    if (run_log != nullptr)
      run_log->open(dir / "log.txt", !restart_directory.empty());
    // From here on SIGTERM and SIGINT stop the run after its step, with
    // its checkpoint and summary.json written.
    fsgmpm::Interruption::install_handlers();
    const fsgmpm::Termination termination = simulator.run();
    prm.enter_subsection("Output");
    const bool report = prm.get_bool("Report");
    prm.leave_subsection();
    if (report && run_log != nullptr)
      write_report(dir);
    if (termination == fsgmpm::Termination::interrupted)
      return fsgmpm::Interruption::exit_status(
        simulator.get_interrupt_signal());
    return termination == fsgmpm::Termination::unstable
             ? 3
             : (termination == fsgmpm::Termination::error ? 1 : 0);
  }
} // namespace



/// True if mpirun/mpiexec (Open MPI, MPICH, Intel MPI) or srun (PMI, PMIx)
/// started this process.
bool
started_by_mpi_launcher()
{
  for (const char *name :
       {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(name) != nullptr)
      return true;
  return false;
}



/// After an error: with several MPI processes the others may wait in a
/// collective call for this one, so the whole job is stopped.
int
error_exit()
{
  if (dealii::Utilities::MPI::job_supports_mpi()
      && dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    MPI_Abort(MPI_COMM_WORLD, 1);
  return 1;
}



int
main(int argc, char **argv)
{
  // MPI only when started by an MPI launcher: a singleton MPI_Init starts
  // a daemon and costs more than a second per run. The threads of the
  // processes share the cores of the machine.
  std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
  if (started_by_mpi_launcher())
    mpi
      = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(argc, argv);
  // What the terminal shows, kept for the run's log.txt (the first process
  // writes it); it outlives the error messages below.
  std::unique_ptr<fsgmpm::RunLog> run_log;
  if (!mpi || dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    run_log = std::make_unique<fsgmpm::RunLog>();
  try
    {
      std::string              prm_file;
      std::vector<std::string> overrides;
      std::string              restart_directory;
      bool                     print_parameters = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--help" || arg == "-h")
            {
              std::cout << usage;
              return 0;
            }
          else if (arg == "--version")
            {
              std::cout << "fsgmpm " << fsgmpm::version_string() << std::endl;
              return 0;
            }
          else if (arg == "--print-parameters")
            print_parameters = true;
          else if (arg == "--set")
            {
              AssertThrow(i + 1 < argc,
                          ExcMessage("--set needs an argument "
                                     "\"Section/Sub/Name=value\"."));
              overrides.push_back(argv[++i]);
            }
          else if (arg == "--restart")
            {
              AssertThrow(i + 1 < argc && argv[i + 1][0] != '-',
                          ExcMessage("--restart needs the output directory "
                                     "of the run to continue."));
              restart_directory = argv[++i];
              AssertThrow(std::filesystem::is_directory(restart_directory),
                          ExcMessage("--restart " + restart_directory
                                     + ": no such directory."));
            }
          else if (arg.rfind("--set=", 0) == 0)
            overrides.push_back(arg.substr(6));
          else if (arg.rfind("-", 0) == 0)
            {
              AssertThrow(false,
                          ExcMessage("Unknown option <" + arg
                                     + ">. Run fsgmpm --help."));
            }
          else
            {
              AssertThrow(prm_file.empty(),
                          ExcMessage("Only one parameter file may be given; "
                                     "got <"
                                     + prm_file + "> and <" + arg + ">."));
              prm_file = arg;
            }
        }

      ParameterHandler prm;
      fsgmpm::Parameters<2>::declare_parameters(prm);
      if (!prm_file.empty())
        {
          AssertThrow(std::filesystem::is_regular_file(prm_file),
                      ExcMessage("Cannot open the parameter file <" + prm_file
                                 + ">."));
          {
            // Structure first (typos, a missing end), with what to fix.
            std::ifstream file(prm_file);
            fsgmpm::check_parameter_file(prm, file, prm_file);
          }
          prm.parse_input(prm_file);
        }
      else
        prm.parse_input_from_string(fsgmpm::default_scene_prm);
      for (const auto &o : overrides)
        apply_override(prm, o);

      if (print_parameters)
        {
          print_parameter_manual(prm, std::cout);
          return 0;
        }

      const unsigned int dim = fsgmpm::get_dimension(prm);
      // The command as a shell would take it back: each argument quoted.
      std::string command;
      for (int i = 0; i < argc; ++i)
        command += (i > 0 ? " " : "") + shell_quoted(argv[i]);
      return dim == 2
               ? run_scene<2>(prm, restart_directory, command, run_log.get())
               : run_scene<3>(prm, restart_directory, command, run_log.get());
    }
  catch (dealii::ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      std::cerr << "fsgmpm: error: " << dealii::Utilities::trim(info.str())
                << std::endl;
      return error_exit();
    }
  catch (std::exception &e)
    {
      std::cerr << "fsgmpm: error: " << e.what() << std::endl;
      return error_exit();
    }
  catch (...)
    {
      std::cerr << "fsgmpm: error: unknown exception" << std::endl;
      return error_exit();
    }
}
