// Test-only: the nested Clenshaw–Curtis tables the sparse-grid tests build their grids on, named
// once for the files of the rules tests' unity build (tests/CMakeLists.txt, QUADMC_UNITY_TESTS).
#pragma once

#include "quadmc/rules/nested_rule.hpp"

namespace quadmc::testing {

inline const nested_rule& cc() {
  return nested_rule_table(nested_rule_kind::clenshaw_curtis);
}

}  // namespace quadmc::testing
