// Running python_module_speed.py and reading its lines; what and why: python_module_speed.hpp.
#include "python_module_speed.hpp"

#include "shell_output.hpp"

#include <fmt/format.h>

#include <map>
#include <optional>
#include <sstream>
#include <utility>

namespace quadmc::peers {

const python_timing* python_module_study::find(const std::string& group,
                                               const std::string& key) const {
  for (const python_timing& t : timings) {
    if (t.group == group && t.key == key) return &t;
  }
  return nullptr;
}

python_module_study measure_python_module(const std::string& python, const std::string& script,
                                          const std::string& module_dir, int rounds,
                                          std::uint64_t seed) {
  python_module_study out;
  if (module_dir.empty()) {
    out.skipped =
        "the Python module is not built in this build (QUADMC_PYTHON=OFF, or pybind11-dev or "
        "python3-numpy missing when it was configured)";
    return out;
  }
  // stderr joins stdout: a failing script's one line is then the reason printed.
  const std::string command =
      fmt::format("PYTHONPATH='{}' '{}' '{}' {} {} 2>&1", module_dir, python, script, rounds, seed);
  const std::optional<shell_output> run = run_shell(command);
  if (!run) {
    out.skipped = "cannot start " + python;
    return out;
  }
  if (!run->failure.empty()) {
    out.skipped = run->failure;
    return out;
  }
  const std::string& text = run->text;
  std::istringstream lines(text);
  constexpr std::string_view versions_prefix = "# versions: ";
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(versions_prefix, 0) == 0) {
      out.versions = line.substr(versions_prefix.size());
      continue;
    }
    std::istringstream fields(line);
    python_timing t;
    if (fields >> t.group >> t.key >> t.s >> t.n >> t.median >> t.min >> t.max >> t.rounds >>
        t.cores) {
      out.timings.push_back(std::move(t));
    } else {
      out.timings.clear();
      out.skipped = "unreadable line of python_module_speed.py: " + line;
      return out;
    }
  }
  return out;
}

python_row_names names_of(const python_timing& t) {
  // The script's keys as peers.csv names them (python_module_speed.py says what each runs).
  static const std::map<std::string, python_row_names> names{
      {"quadmc_points", {"quadmc.points sobol lms_shift", "quadmc", "(points only)"}},
      {"scipy_points", {"scipy Sobol scrambled random(N)", "scipy", "(points only)"}},
      {"numpy_ones", {"numpy.ones (N; s)", "numpy", "(points only)"}},
      {"integrate_catalogue", {"quadmc.integrate catalogue f", "quadmc", "genz_gaussian"}},
      {"integrate_numpy", {"quadmc.integrate numpy f", "numpy", "genz_gaussian"}},
      {"integrate_ones", {"quadmc.integrate numpy ones", "numpy", "ones"}},
      {"numpy_all", {"numpy f in one call", "numpy", "genz_gaussian"}},
      {"numpy_batches", {"numpy f in calls of 2^14", "numpy", "genz_gaussian"}},
      {"catalogue_batches", {"catalogue f in calls of 2^14", "quadmc", "genz_gaussian"}}};
  const auto it = names.find(t.key);
  if (it == names.end()) return {t.key, "python", "(unknown)"};
  return it->second;
}

}  // namespace quadmc::peers
