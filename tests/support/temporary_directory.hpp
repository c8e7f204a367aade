// Test support: a folder of the test's own below the system's temporary folder, named
// <prefix>_<tick>_<random> so that tests running in parallel never share one, and removed with
// everything in it when the test ends. It starts absent (for the code under test to create, as
// a run creates its results folder) or empty.
#pragma once

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <string_view>
#include <system_error>

namespace quadmc::test_support {

struct temporary_directory {
  enum class start { absent, empty };

  explicit temporary_directory(std::string_view prefix, start at = start::absent) {
    const auto tick = std::chrono::steady_clock::now().time_since_epoch().count();
    path = std::filesystem::temp_directory_path() /
           fmt::format("{}_{}_{}", prefix, tick, std::random_device{}());
    if (at == start::empty) std::filesystem::create_directories(path);
  }
  ~temporary_directory() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  temporary_directory(const temporary_directory&) = delete;
  temporary_directory& operator=(const temporary_directory&) = delete;

  std::filesystem::path path;
};

}  // namespace quadmc::test_support
