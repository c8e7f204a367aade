// Checks of command-line values that CLI11 does not make itself, shared by the subcommands. Each
// refuses the value before anything runs (exit 2, with the option's name), where CLI11 alone
// would read it as another value.
#pragma once

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace quadmc_cli {

// An unsigned 64-bit option (a seed, a stream): decimal digits only, at most 2^64 − 1. CLI11
// would read "-3" as 2^64 − 3 and clamp 2^64 and more to 2^64 − 1, so that two different seeds
// on the command line silently gave the same run.
inline CLI::Validator non_negative_integer() {
  return CLI::Validator(
      [](std::string& text) {
        const bool digits =
            !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        errno = 0;
        if (digits) (void)std::strtoull(text.c_str(), nullptr, 10);
        if (digits && errno != ERANGE) return std::string();
        return fmt::format("expected an integer K with 0 ≤ K ≤ 2^64 − 1 = {}, got {}", UINT64_MAX,
                           text);
      },
      "K ≥ 0");
}

// A real option value in [low, high] (`range` says so in words, e.g. "between 0 and 60"), and
// finite: CLI11's Range and NonNegativeNumber let NaN through (every comparison with NaN is
// false), so `--tolerance nan` reached the run and failed after the plan.
inline CLI::Validator finite_number(double low, double high, std::string range) {
  return CLI::Validator(
      [low, high, range](std::string& text) {
        char* end = nullptr;
        const double x = std::strtod(text.c_str(), &end);
        const bool whole = !text.empty() && end == text.c_str() + text.size();
        if (whole && std::isfinite(x) && x >= low && x <= high) return std::string();
        return fmt::format("expected a finite number {}, got {}", range, text);
      },
      range);
}

// A path option given explicitly: not empty. `--out ""` read as "not given" and wrote the default
// folder, which the user had not asked for.
inline CLI::Validator non_empty_path() {
  return CLI::Validator(
      [](std::string& text) {
        return text.empty() ? std::string("expected a path, got an empty one") : std::string();
      },
      "PATH");
}

}  // namespace quadmc_cli
