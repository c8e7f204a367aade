// `quadmc --version` and the provenance of a results folder (version.hpp).
#include "version.hpp"

#include "plot_script.hpp"
#include "quadmc/core/simd_level.hpp"

// QUADMC_COMMIT: written at every build by cmake/quadmc_commit.cmake into the build folder.
#include "quadmc_commit.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace quadmc_cli {

quadmc::provenance build_provenance() {
  quadmc::provenance p;
  p.version = QUADMC_VERSION;
  p.commit = QUADMC_COMMIT;
  p.compiler = fmt::format("{} ({})", QUADMC_COMPILER, QUADMC_BUILD_TYPE);
  for (const quadmc::simd_level level : quadmc::available_simd_levels()) {
    p.simd_levels_available.emplace_back(quadmc::to_string(level));
  }
  p.simd_level = quadmc::to_string(quadmc::active_simd_level());
  return p;
}

std::string version_text() {
  const quadmc::provenance p = build_provenance();
  return fmt::format(
      "quadmc {}\n"
      "commit: {}\n"
      "compiler: {}\n"
      "SIMD levels available: {} (in use: {}; QUADMC_SIMD to choose)\n"
      "plot script: {}\n",
      p.version, p.commit, p.compiler, fmt::join(p.simd_levels_available, " "), p.simd_level,
      plot_script_path().string());
}

}  // namespace quadmc_cli
