// The out-of-line part of errors.hpp.
#include "quadmc/core/errors.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <span>
#include <string_view>

namespace quadmc {

non_finite_value::non_finite_value(std::string_view what_produced_it, std::span<const double> point,
                                   double value)
    : std::domain_error(fmt::format("{} returned {} at x = ({})", what_produced_it, value,
                                    fmt::join(point, ", "))) {}

}  // namespace quadmc
