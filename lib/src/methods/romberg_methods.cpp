// Romberg extrapolation as a method (rules/romberg.hpp), in 1D only, under all three controls:
//   fixed      N → the largest 2^k + 1 ≤ N evaluations, exactly k halvings (no early stop);
//   budget     at most that many, stopping early when Romberg's own estimate reaches its default
//              relative tolerance (1e-12 of ∫|f|, after 4 levels at least);
//   tolerance  until the estimate |R(k, k) − R(k−1, k−1)| is at most the cell's absolute
//              tolerance, within the budget (budget.max_evaluations, else 2^24 + 1 evaluations).
// Its error estimate is reported in every case.
#include "families.hpp"

#include "quadmc/rules/jump_error_envelope.hpp"
#include "quadmc/rules/romberg.hpp"

#include <fmt/format.h>

#include <array>
#include <bit>
#include <memory>

namespace quadmc::methods {
namespace {

class romberg_method final : public method {
 public:
  using method::method;

  std::optional<std::string> incompatibility(const integrand_traits& f) const override {
    if (f.s == 1) return std::nullopt;
    return fmt::format("romberg is one-dimensional; the integrand has s = {}", f.s);
  }

  // n = 2^k panels with 2^k + 1 ≤ N nodes, k ≥ 1 (levels beyond romberg_max_levels are not
  // offered: a budget that large is spent on the largest table Romberg builds).
  sizing size_for(std::uint64_t N, std::size_t s) const override {
    if (s != 1) return {std::nullopt, fmt::format("romberg is one-dimensional (s = {})", s)};
    if (N < 3) return {std::nullopt, "N is below the smallest grid, 3^1 = 3 evaluations"};
    unsigned k = 1;
    while (k < romberg_max_levels && (std::uint64_t{1} << (k + 1)) + 1 <= N) ++k;
    const std::uint64_t n = std::uint64_t{1} << k;
    // R(k,k) eliminates the h^2 … h^2k terms of the Euler–Maclaurin expansion.
    return {cell_size{n + 1, n, n + 1, 2 * static_cast<int>(k) + 2}, {}};
  }

  theoretical_rate theory(const integrand_class& f) const override {
    return extrapolated_trapezoid_rate(f);
  }

  double error_envelope(const integrand_info& f, const cell_size& size) const override {
    if (!std::has_single_bit(size.per_axis)) {
      return std::numeric_limits<double>::quiet_NaN();
    }
    return romberg_jump_error_envelope(f, static_cast<unsigned>(std::countr_zero(size.per_axis)))
        .value_or(std::numeric_limits<double>::quiet_NaN());
  }

  repetition_result run(const method_cell& cell, const run_context&) const override {
    const auto levels = static_cast<unsigned>(std::countr_zero(cell.size.per_axis));
    romberg_options options;
    options.max_levels = levels;
    switch (cell.control) {
      case cell_control::fixed_size:
        options.relative_tolerance = 0.0;  // run exactly k halvings
        options.min_levels = levels;
        break;
      case cell_control::budget:
        options.min_levels = std::min(options.min_levels, levels);
        break;
      case cell_control::tolerance:
        options.relative_tolerance = 0.0;
        options.absolute_tolerance = cell.tolerance;
        options.min_levels = std::min(options.min_levels, levels);
        break;
    }
    const romberg_result r = romberg(cell.function, options);
    repetition_result out;
    out.value = r.value;
    out.evaluations = r.evaluations;
    out.error_estimate = r.error_estimate;
    return out;
  }
};

constexpr std::array<cell_control, 3> controls{cell_control::fixed_size, cell_control::budget,
                                               cell_control::tolerance};

const std::array<method_descriptor, 1> descriptors{{
    {"romberg",
     "Romberg extrapolation of the trapezoid rule on 2^k panels (1D only)",
     method_kind::deterministic,
     {},
     controls,
     [](const method_descriptor& d, option_reader&) -> std::unique_ptr<const method> {
       return std::make_unique<romberg_method>(d);
     }},
}};

}  // namespace

std::span<const method_descriptor> romberg_methods() noexcept {
  return descriptors;
}

}  // namespace quadmc::methods
