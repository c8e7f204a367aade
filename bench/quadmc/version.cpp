// `quadmc --version` (version.hpp).
#include "version.hpp"

#include "build_provenance.hpp"
#include "plot_script.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace quadmc_cli {

std::string version_text() {
  const quadmc::provenance p = quadmc::bench::build_provenance();
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
