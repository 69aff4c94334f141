/**
 * Fork server for tests/scenes/fuzz_input.py: runs the fsgmpm command line
 * (the main() of source/app/main.cc, compiled in here under another name)
 * once per request, each time in a child process forked from this one.
 *
 * Starting fsgmpm costs about 0.3 s, nearly all of it the dynamic linker
 * binding the symbols of deal.II and its dependencies; a forked child
 * inherits the bound libraries, so a fuzzing case costs only its own run
 * (milliseconds) and thousands of cases fit in a minute. Each case still
 * is a process of its own: fresh memory from main() on, its own exit
 * status, signal or hang.
 *
 * Protocol (stdin, one item a line): the timeout in seconds, the working
 * directory, the number n of arguments, then n arguments. The child writes
 * its stdout and stderr to stdout.txt and stderr.txt in the working
 * directory. Reply (stdout, one line): "exit <status>", "signal <number>" or
 * "timeout" (the child was killed).
 */

// The headers of main.cc first, so that the macro below renames only its
// main().
#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/default_scene.h>
#include <fsgmpm/scene/parameters.h>
#include <fsgmpm/simulator.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <filesystem>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#define main fsgmpm_main
#include "../../source/app/main.cc"
#undef main

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

int
main()
{
  std::string line;
  while (std::getline(std::cin, line))
    {
      const double timeout = std::stod(line);
      std::string  cwd;
      std::getline(std::cin, cwd);
      std::getline(std::cin, line);
      std::vector<std::string> args(std::stoul(line));
      for (auto &a : args)
        std::getline(std::cin, a);
      std::cout.flush();
      std::cerr.flush();

      const pid_t pid = fork();
      if (pid < 0)
        {
          std::cout << "error fork failed" << std::endl;
          continue;
        }
      if (pid == 0)
        {
          if (chdir(cwd.c_str()) != 0)
            _exit(125);
          const int flags = O_WRONLY | O_CREAT | O_TRUNC;
          const int in    = open("/dev/null", O_RDONLY);
          const int out   = open("stdout.txt", flags, 0644);
          const int err   = open("stderr.txt", flags, 0644);
          if (in < 0 || out < 0 || err < 0)
            _exit(125);
          dup2(in, 0);
          dup2(out, 1);
          dup2(err, 2);
          close(in);
          close(out);
          close(err);
          std::vector<char *> argv;
          static char         name[] = "fsgmpm";
          argv.push_back(name);
          for (auto &a : args)
            argv.push_back(a.data());
          argv.push_back(nullptr);
          std::exit(
            fsgmpm_main(static_cast<int>(argv.size()) - 1, argv.data()));
        }

      const auto start  = std::chrono::steady_clock::now();
      int        status = 0;
      bool       killed = false;
      while (waitpid(pid, &status, WNOHANG) == 0)
        {
          const std::chrono::duration<double> elapsed
            = std::chrono::steady_clock::now() - start;
          if (elapsed.count() > timeout)
            {
              kill(pid, SIGKILL);
              waitpid(pid, &status, 0);
              killed = true;
              break;
            }
          usleep(500);
        }
      if (killed)
        std::cout << "timeout" << std::endl;
      else if (WIFEXITED(status))
        std::cout << "exit " << WEXITSTATUS(status) << std::endl;
      else if (WIFSIGNALED(status))
        std::cout << "signal " << WTERMSIG(status) << std::endl;
      else
        std::cout << "error unknown status " << status << std::endl;
    }
  return 0;
}
