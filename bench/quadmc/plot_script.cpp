// The plot script of the build tree or of an installed quadmc (plot_script.hpp).
#include "plot_script.hpp"

#include <system_error>

namespace quadmc_cli {

namespace fs = std::filesystem;

fs::path plot_script_path() {
  std::error_code ec;
  const fs::path executable = fs::canonical("/proc/self/exe", ec);
  if (ec) return QUADMC_SOURCE_PLOT_SCRIPT;
  const fs::path build_folder = fs::canonical(QUADMC_BUILD_TREE_DIR, ec);
  if (!ec && executable.parent_path() == build_folder) return QUADMC_SOURCE_PLOT_SCRIPT;
  return (executable.parent_path() / QUADMC_INSTALLED_PLOT_SCRIPT).lexically_normal();
}

}  // namespace quadmc_cli
