// What the programs of bench/ were built from, for the results they write: the quadmc version
// (CMake's project(VERSION)), the git commit (cmake/quadmc_commit.cmake: "unknown" without git or
// outside a checkout, "-dirty" with local changes), the compiler and build type, and the SIMD
// levels this CPU and build support with the one in use (core/simd_level.hpp).
//
// Use it wherever a bench/ program writes a results folder or page (`quadmc run`'s meta.csv and
// README header, `quadmc --version`, quadmc_peers' meta.csv and README), so that every table
// names the code that made it in the same words. Not for the library: a library user fills
// quadmc::provenance (report/provenance.hpp) from its own build.
#pragma once

#include "quadmc/report/provenance.hpp"

namespace quadmc::bench {

// Throws quadmc::invalid_argument for a bad QUADMC_SIMD (core/simd_level.hpp), as every command
// does before any work.
quadmc::provenance build_provenance();

}  // namespace quadmc::bench
