// Errors raised by quadmc.
//
// Validate at the API boundary and quote the bad value (the habit of Boost.Math's policies:
// "a < b is required, but got a = %1%"). Every message names the parameter, the value given and
// what was expected, so a user can fix a scene file without reading our source. Hot loops never
// clamp silently; they either cannot receive bad input (validated before the loop) or report it.
#pragma once

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace quadmc {

// Bad input from a caller: a parameter out of its domain.
class invalid_argument : public std::invalid_argument {
 public:
  invalid_argument(std::string_view parameter, std::string_view value, std::string_view expected)
      : std::invalid_argument(
            fmt::format("invalid {} = {}: expected {}", parameter, value, expected)),
        parameter_(parameter) {}
  // For messages that do not fit the parameter/value/expected shape (e.g. scene files).
  explicit invalid_argument(const std::string& message) : std::invalid_argument(message) {}

  // A message of any shape about one parameter, which parameter() then names (so that a caller
  // can point at it, e.g. at a scene file's key).
  static invalid_argument about(std::string_view parameter, const std::string& message) {
    invalid_argument e(message);
    e.parameter_ = parameter;
    return e;
  }

  const std::string& parameter() const noexcept { return parameter_; }

 private:
  std::string parameter_;
};

// An integrand (or pdf) produced NaN or ±inf: the message carries the point that produced it.
// Its constructor is compiled once, in lib/src/core/errors.cpp: formatting the point's doubles
// with fmt::join instantiates fmt's whole floating-point writer, which every file of the hot loops
// that throw this would otherwise generate again (docs/design.md#build-time).
class non_finite_value : public std::domain_error {
 public:
  non_finite_value(std::string_view what_produced_it, std::span<const double> point, double value);
};

// Formats a value for an invalid_argument message with max_digits10 significant digits (17 for
// a double, 9 for a float, 21 for x87 long double) so that the value quoted is the value given,
// not a rounded neighbour.
template <class T>
std::string quote(const T& value) {
  if constexpr (std::is_floating_point_v<T>) {
    return fmt::format("{:.{}g}", value, std::numeric_limits<T>::max_digits10);
  } else {
    return fmt::format("{}", value);
  }
}

// Throws invalid_argument unless `condition` holds.
template <class T>
void require(bool condition, std::string_view parameter, const T& value,
             std::string_view expected) {
  if (!condition) [[unlikely]] {
    throw invalid_argument(parameter, quote(value), expected);
  }
}

inline void require_finite(double value, std::string_view parameter) {
  require(std::isfinite(value), parameter, value, "a finite number");
}

}  // namespace quadmc
