// The build's provenance from the values CMake compiles in (build_provenance.hpp).
#include "build_provenance.hpp"

#include "quadmc/core/simd_level.hpp"

// QUADMC_COMMIT: written at every build by cmake/quadmc_commit.cmake into the build folder.
#include "quadmc_commit.hpp"

#include <fmt/format.h>

namespace quadmc::bench {

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

}  // namespace quadmc::bench
