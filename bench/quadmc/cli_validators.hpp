// Checks of command-line values that CLI11 does not make itself, shared by the subcommands.
#pragma once

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <string>

namespace quadmc_cli {

// An unsigned option (a seed) that refuses a minus sign: CLI11 would otherwise read "-3" into an
// unsigned as 2^64 − 3.
inline CLI::Validator non_negative_integer() {
  return CLI::Validator(
      [](std::string& text) {
        return text.find('-') == std::string::npos
                   ? std::string()
                   : fmt::format("expected an integer K ≥ 0, got {}", text);
      },
      "K ≥ 0");
}

}  // namespace quadmc_cli
