// The `quadmc` command (run, plan, list, compare, points, gallery, render) as one library call, so
// that a program of its own runs it with its integrands and methods registered beside the built-in
// ones: `mybench run my.toml`, `mybench list` (bench/examples/own_integrand/, README "Your own
// points, rules and integrands"). CMake target quadmc::command of the installed package.
//
// A program adds its families first (functions/catalogue.hpp add_integrands, methods/registry.hpp
// add_methods), then returns command_main's exit status from its main. The exit statuses,
// messages and outputs are the command's (bench/quadmc/command.cpp), with `name` in place of
// "quadmc" at the start of each message line and in --help. Under mpirun the command shares a
// run's cells between the ranks where quadmc was built with MPI (then the CMake package finds MPI
// for quadmc::command).
#pragma once

#include <filesystem>
#include <string>
#include <utility>

namespace quadmc {

struct command_options {
  std::string name = "quadmc";  // the program's name in its messages and --help
  // The folder of the drawing scripts (plot.py, gallery.py, render.py); where they are missing,
  // a run with plots, the gallery and render images are refused before any work.
  std::filesystem::path scripts;
};

// Runs the command line `argv` (argv[0] is the program) and returns the process's exit status.
// Call it once per process, from main: it installs the signal handling of an interruptible run
// (report/interruption.hpp) and, under mpirun, starts and finishes MPI.
int command_main(int argc, char** argv, const command_options& options);

#ifdef QUADMC_COMMAND_SCRIPTS
// For a program that links quadmc::command, whose CMake target defines QUADMC_COMMAND_SCRIPTS as
// the folder of the installed package's scripts: the command under the program's own name.
inline int command_main(int argc, char** argv, std::string name) {
  return command_main(argc, argv, command_options{std::move(name), QUADMC_COMMAND_SCRIPTS});
}
#endif

}  // namespace quadmc
