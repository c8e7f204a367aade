// Where `quadmc run` finds bench/plot.py, the script that draws a results folder's SVGs.
//
// Decided by where the running executable is, not by which file happens to exist:
//  - the executable CMake built, in its build folder: the script in the source tree (an edit to
//    bench/plot.py needs no rebuild);
//  - any other place, i.e. an installed quadmc (cmake --install, the Debian package): the
//    installed copy at the path the install rules put it, relative to the executable
//    ("../share/quadmc/plot.py" beside bin/quadmc), so an installed tree works under any prefix
//    (/usr, a home folder, a `dpkg -x` root) and never reads the source tree it was built from,
//    which may be gone or at another version.
// The executable is found through /proc/self/exe (Linux: the command is built for Debian); if that
// cannot be read, the source tree's script, as the build tree would use.
#pragma once

#include <filesystem>
#include <string_view>

namespace quadmc_cli {

std::filesystem::path plot_script_path();

// bench/gallery.py, the script that draws `quadmc gallery`'s PNGs: beside plot.py, by the same
// rule.
std::filesystem::path gallery_script_path();

// bench/render.py, the script that draws `quadmc render`'s PNGs: beside plot.py, by the same rule.
std::filesystem::path render_script_path();

// Checks before any computation that `script` exists and that Debian's python3 can import
// matplotlib: a missing plotting stack found after the run would throw away the whole
// computation. `remedy` ends the message ("or set plots = false in [output]"). Throws
// std::runtime_error with a one-line message.
void check_plotting(const std::filesystem::path& script, std::string_view remedy);

}  // namespace quadmc_cli
