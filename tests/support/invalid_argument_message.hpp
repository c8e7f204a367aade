// Test support: the message of the quadmc::invalid_argument a call throws, for tests that check
// which parameter a refusal names and what it expects. One definition for every test file, so
// that the files of one test executable can be compiled together (tests/CMakeLists.txt,
// QUADMC_UNITY_TESTS).
#pragma once

#include "quadmc/core/errors.hpp"

#include <string>

namespace quadmc::test_support {

// What `build()` throws as quadmc::invalid_argument, or "no exception" (which no expected message
// contains, so a call that should have thrown fails the test's find()).
template <class F>
std::string message_of(F&& build) {
  try {
    build();
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "no exception";
}

}  // namespace quadmc::test_support
