// What `quadmc --version` prints and every results folder records (meta.csv and the README
// header, report/provenance.hpp): the version from CMake's project(VERSION), the git commit the
// command was built from (cmake/quadmc_commit.cmake: "unknown" without git or outside a checkout,
// "-dirty" with local changes), the compiler and build type, and the SIMD levels this CPU and
// build support with the one in use.
//
// Use build_provenance() for a results folder and version_text() for --version: both come from
// the same values, so a folder and the binary that wrote it can be matched. Not the library's
// version for find_package (lib/CMakeLists.txt writes quadmcConfigVersion.cmake for that).
#pragma once

#include "quadmc/report/provenance.hpp"

#include <string>

namespace quadmc_cli {

// Throws quadmc::invalid_argument for a bad QUADMC_SIMD (core/simd_level.hpp), as every command
// does before any work.
quadmc::provenance build_provenance();

// The --version text, one field per line, the first "quadmc <version>" (the GNU convention), then
// the commit, the compiler, the SIMD levels and the plot script a run would use (plot_script.hpp).
std::string version_text();

}  // namespace quadmc_cli
