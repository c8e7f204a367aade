// The names of the generators a random_stream runs (core/rng.hpp).
#include "quadmc/core/rng.hpp"

#include "quadmc/core/errors.hpp"

#include <array>

namespace quadmc {
namespace {

// In rng_kind's order, the default first.
constexpr std::array<std::string_view, 2> names = {"philox4x32_10", "ars4x32_7"};

}  // namespace

std::string_view to_string(rng_kind generator) noexcept {
  return names[static_cast<std::size_t>(generator)];
}

rng_kind parse_rng_kind(std::string_view text, std::string_view parameter) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (text == names[i]) return static_cast<rng_kind>(i);
  }
  throw invalid_argument(parameter, fmt::format("\"{}\"", text),
                         fmt::format("one of {}", rng_kind_names()));
}

std::string_view rng_kind_names() noexcept {
  return "philox4x32_10, ars4x32_7";
}

}  // namespace quadmc
