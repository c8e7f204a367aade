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

namespace quadmc_cli {

std::filesystem::path plot_script_path();

}  // namespace quadmc_cli
