// The `quadmc` executable: the command of quadmc/command.hpp, with its drawing scripts found by
// where this executable is. Compiled once per executable (quadmc, bench/peers' quadmc_with_peers),
// since the build folder it compares itself with is its own.
//
// Decided by where the running executable is, not by which file happens to exist:
//  - the executable CMake built, in its build folder: the scripts of the source tree's bench/ (an
//    edit to bench/plot.py needs no rebuild);
//  - any other place, i.e. an installed quadmc (cmake --install, the Debian package): the
//    installed copies at the path the install rules put them, relative to the executable
//    ("../share/quadmc/" beside bin/quadmc), so an installed tree works under any prefix (/usr, a
//    home folder, a `dpkg -x` root) and never reads the source tree it was built from, which may
//    be gone or at another version.
// The executable is found through /proc/self/exe (Linux: the command is built for Debian); if that
// cannot be read, the source tree's scripts, as the build tree would use.
#include "quadmc/command.hpp"

#include <filesystem>
#include <system_error>

namespace {

namespace fs = std::filesystem;

fs::path script_folder() {
  const fs::path source = fs::path(QUADMC_SOURCE_PLOT_SCRIPT).parent_path();
  std::error_code ec;
  const fs::path executable = fs::canonical("/proc/self/exe", ec);
  if (ec) return source;
  const fs::path build_folder = fs::canonical(QUADMC_BUILD_TREE_DIR, ec);
  if (!ec && executable.parent_path() == build_folder) return source;
  return (executable.parent_path() / QUADMC_INSTALLED_PLOT_SCRIPT).lexically_normal().parent_path();
}

}  // namespace

int main(int argc, char** argv) {
  return quadmc::command_main(argc, argv, {"quadmc", script_folder()});
}
