// What `quadmc --version` prints: the version from CMake's project(VERSION), the git commit the
// command was built from, the compiler and build type, the SIMD levels this CPU and build support
// with the one in use, and the plot script a run would use (plot_script.hpp).
//
// Use it for --version only. The same values go into every results folder through
// quadmc::bench::build_provenance() (bench/common/build_provenance.hpp), so a folder and the
// binary that wrote it can be matched. Not the library's version for find_package
// (lib/CMakeLists.txt writes quadmcConfigVersion.cmake for that).
#pragma once

#include <string>

namespace quadmc_cli {

// One field per line, the first "quadmc <version>" (the GNU convention), then "key: value"
// lines. Throws quadmc::invalid_argument for a bad QUADMC_SIMD (core/simd_level.hpp).
std::string version_text();

}  // namespace quadmc_cli
