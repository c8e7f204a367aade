// Test support: restores the SIMD level a test found when it ends, however it ends, so that a test
// that walks every level (set_simd_level) leaves the next test on the level the process chose.
// One definition for every test file, so that the files of one test executable can be compiled
// together (tests/CMakeLists.txt, QUADMC_UNITY_TESTS).
#pragma once

#include "quadmc/core/simd_level.hpp"

namespace quadmc::test_support {

class simd_level_guard {
 public:
  simd_level_guard() : saved_(active_simd_level()) {}
  ~simd_level_guard() { set_simd_level(saved_); }
  simd_level_guard(const simd_level_guard&) = delete;
  simd_level_guard& operator=(const simd_level_guard&) = delete;

 private:
  simd_level saved_;
};

}  // namespace quadmc::test_support
