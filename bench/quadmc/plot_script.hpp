// Where the command finds its drawing scripts: bench/plot.py (a results folder's SVGs),
// bench/gallery.py and bench/render.py, all in one folder that command_main sets from
// command_options::scripts (quadmc/command.hpp) before any subcommand runs.
//
// The `quadmc` executable decides the folder by where it is (bench/quadmc/main.cpp): its build
// folder → the source tree's bench/; anywhere else (an installed quadmc) → the installed copies
// relative to the executable. A program built on quadmc::command gets the installed package's
// folder from its CMake target (QUADMC_COMMAND_SCRIPTS).
#pragma once

#include <filesystem>
#include <string_view>

namespace quadmc_cli {

void set_script_folder(std::filesystem::path folder);

std::filesystem::path plot_script_path();     // <folder>/plot.py
std::filesystem::path gallery_script_path();  // <folder>/gallery.py
std::filesystem::path render_script_path();   // <folder>/render.py

// Checks before any computation that `script` exists and that Debian's python3 can import
// matplotlib: a missing plotting stack found after the run would throw away the whole
// computation. `remedy` ends the message ("or set plots = false in [output]"). Throws
// std::runtime_error with a one-line message.
void check_plotting(const std::filesystem::path& script, std::string_view remedy);

}  // namespace quadmc_cli
