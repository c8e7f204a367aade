// The folder of the drawing scripts, as command_main sets it (plot_script.hpp).
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
#include <utility>

namespace quadmc_cli {

namespace fs = std::filesystem;
using quadmc::child_output;
using quadmc::subprocess_status;

namespace {
fs::path& script_folder() {
  static fs::path folder;
  return folder;
}
}  // namespace

void set_script_folder(fs::path folder) {
  script_folder() = std::move(folder);
}

fs::path plot_script_path() {
  return script_folder() / "plot.py";
}

fs::path gallery_script_path() {
  return script_folder() / "gallery.py";
}

fs::path render_script_path() {
  return script_folder() / "render.py";
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
