// The plot script of the build tree or of an installed quadmc (plot_script.hpp).
#include "plot_script.hpp"

#include "quadmc/report/results_folder.hpp"

#include "quadmc/report/subprocess.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace quadmc_cli {

namespace fs = std::filesystem;
using quadmc::child_output;
using quadmc::subprocess_status;

fs::path plot_script_path() {
  std::error_code ec;
  const fs::path executable = fs::canonical("/proc/self/exe", ec);
  if (ec) return QUADMC_SOURCE_PLOT_SCRIPT;
  const fs::path build_folder = fs::canonical(QUADMC_BUILD_TREE_DIR, ec);
  if (!ec && executable.parent_path() == build_folder) return QUADMC_SOURCE_PLOT_SCRIPT;
  return (executable.parent_path() / QUADMC_INSTALLED_PLOT_SCRIPT).lexically_normal();
}

fs::path gallery_script_path() {
  return plot_script_path().parent_path() / "gallery.py";
}

fs::path render_script_path() {
  return plot_script_path().parent_path() / "render.py";
}

void check_plotting(const fs::path& script, std::string_view remedy) {
  const std::string python = quadmc::plot_command_line(script, "").front();
  std::error_code ec;
  if (!fs::is_regular_file(script, ec)) {
    throw std::runtime_error(fmt::format("plots need the plot script {}, which is missing ({})",
                                         script.string(), remedy));
  }
  if (::access(python.c_str(), X_OK) != 0) {
    throw std::runtime_error(fmt::format(
        "plots need Python with matplotlib, but {} cannot be run ({}): install python3 and "
        "python3-matplotlib (./run.sh deps) {}",
        python, std::strerror(errno), remedy));
  }
  if (subprocess_status({python, "-c", "import matplotlib"}, child_output::none) != 0) {
    throw std::runtime_error(
        fmt::format("plots need matplotlib, but `{} -c 'import matplotlib'` failed: install "
                    "python3-matplotlib (./run.sh deps) {}",
                    python, remedy));
  }
}

}  // namespace quadmc_cli
