// The method, point-set and warp tables of methods.hpp, and the exact N → grid arithmetic.
#include "quadmc/scene/methods.hpp"

#include "quadmc/core/errors.hpp"

#include <array>
#include <cmath>
#include <limits>

namespace quadmc {

namespace {

using sv = std::string_view;

// Option keys per family of methods. `repetitions` is accepted by the rules too: the plan then
// says that it is ignored (a rule is deterministic), rather than rejecting a scene that sets a
// repetition count once for a list of methods.
// `accumulator`: how a tensor rule sums its terms (core/summation.hpp, enum summation).
constexpr std::array<sv, 6> rule_options{"name",        "label",  "integrands",
                                         "repetitions", "panels", "accumulator"};
constexpr std::array<sv, 7> gauss_options{"name",   "label", "integrands", "repetitions",
                                          "panels", "m",     "accumulator"};
constexpr std::array<sv, 4> romberg_options{"name", "label", "integrands", "repetitions"};
constexpr std::array<sv, 4> random_options{"name", "label", "integrands", "repetitions"};
constexpr std::array<sv, 6> importance_options{"name",        "label", "integrands",
                                               "repetitions", "warp",  "point_set"};
constexpr std::array<sv, 5> estimator_options{"name", "label", "integrands", "repetitions",
                                              "point_set"};

using mk = method_kind;
using cc = count_constraint;
using ir = integrand_requirement;

constexpr std::array<method_info, 16> methods{{
    {"left_rectangle", "composite left-endpoint rectangle rule, O(h)", mk::deterministic_rule, true,
     1, cc::tensor_grid, ir::any, rule_options},
    {"right_rectangle", "composite right-endpoint rectangle rule, O(h)", mk::deterministic_rule,
     true, 1, cc::tensor_grid, ir::any, rule_options},
    {"midpoint", "composite midpoint rule, O(h^2)", mk::deterministic_rule, true, 2,
     cc::tensor_grid, ir::any, rule_options},
    {"trapezoid", "composite trapezoid rule, O(h^2)", mk::deterministic_rule, true, 2,
     cc::tensor_grid, ir::any, rule_options},
    {"simpson", "composite Simpson rule (n even), O(h^4)", mk::deterministic_rule, true, 4,
     cc::tensor_grid, ir::any, rule_options},
    {"gauss_legendre", "composite m-point Gauss-Legendre rule, O(h^2m)", mk::deterministic_rule,
     true, 0, cc::tensor_grid, ir::any, gauss_options},
    {"romberg", "Romberg extrapolation of the trapezoid rule on 2^k panels (1D only)",
     mk::deterministic_rule, false, 0, cc::tensor_grid, ir::one_dimensional, romberg_options},
    {"plain_mc", "plain Monte Carlo with independent uniform points", mk::random, false, 0, cc::any,
     ir::any, random_options},
    {"jittered", "jittered (stratified) sampling, one random point per cell, N = k^s", mk::random,
     false, 0, cc::perfect_power, ir::any, random_options},
    {"unjittered", "one point at the centre of each cell of a randomly shifted k^s grid",
     mk::random, false, 0, cc::perfect_power, ir::any, random_options},
    {"padded_jittered", "k x k jittered 2D strata padded across dimension pairs, N = k^2",
     mk::random, false, 0, cc::perfect_square, ir::any, random_options},
    {"latin_hypercube", "Latin hypercube sampling (McKay et al. 1979)", mk::random, false, 0,
     cc::any, ir::any, random_options},
    {"importance", "importance sampling with a 1D warp (s = 1)", mk::random, false, 0, cc::any,
     ir::one_dimensional, importance_options},
    {"irradiance_hemisphere_uniform", "irradiance, directions uniform on the hemisphere",
     mk::random, false, 0, cc::any, ir::irradiance, estimator_options},
    {"irradiance_hemisphere_cosine", "irradiance, cosine-weighted hemisphere directions",
     mk::random, false, 0, cc::any, ir::irradiance, estimator_options},
    {"irradiance_light_area", "irradiance, points uniform on the light's area", mk::random, false,
     0, cc::any, ir::irradiance, estimator_options},
}};

constexpr std::array<point_set_info, 5> point_sets{{
    {"independent", "independent uniform points", cc::any},
    {"jittered", "one random point per cell of a k^s grid", cc::perfect_power},
    {"unjittered", "cell centres of a randomly shifted k^s grid", cc::perfect_power},
    {"padded_jittered", "k x k jittered strata padded across dimension pairs", cc::perfect_square},
    {"latin_hypercube", "Latin hypercube", cc::any},
}};

constexpr std::array<warp_info, 2> warps{{
    {"power", "p(x) = (k+1) x^k on [0,1], -1 < k <= 1e5", "exponent", 1.0},
    {"exponential", "p(x) = l e^(l x) / (e^l - 1) on [0,1], 0 < |l| <= 700", "rate", 1.0},
}};

template <class Table>
auto find_in(const Table& table, std::string_view name) noexcept -> decltype(&table[0]) {
  for (const auto& entry : table) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

template <class Table>
std::string names_of(const Table& table) {
  std::string out;
  for (const auto& entry : table) {
    if (!out.empty()) out += ", ";
    out += entry.name;
  }
  return out;
}

}  // namespace

std::span<const method_info> method_catalogue() {
  return methods;
}
std::span<const point_set_info> point_set_catalogue() {
  return point_sets;
}
std::span<const warp_info> warp_catalogue() {
  return warps;
}

const method_info* find_method(std::string_view name) noexcept {
  return find_in(methods, name);
}
const point_set_info* find_point_set(std::string_view name) noexcept {
  return find_in(point_sets, name);
}
const warp_info* find_warp(std::string_view name) noexcept {
  return find_in(warps, name);
}

std::string method_names() {
  return names_of(methods);
}
std::string point_set_names() {
  return names_of(point_sets);
}
std::string warp_names() {
  return names_of(warps);
}

std::optional<std::uint64_t> checked_power(std::uint64_t base, unsigned exponent) noexcept {
  std::uint64_t result = 1;
  for (unsigned i = 0; i < exponent; ++i) {
    if (base != 0 && result > std::numeric_limits<std::uint64_t>::max() / base) {
      return std::nullopt;
    }
    result *= base;
  }
  return result;
}

std::uint64_t integer_root(std::uint64_t N, unsigned s) noexcept {
  if (s <= 1 || N <= 1) return s == 0 ? 0 : N;
  // pow() gives a guess within a few units of the root; the exact power test then walks it to
  // the right integer, so rounding in pow (4096^(1/3) = 15.999…) cannot move the answer.
  auto q = static_cast<std::uint64_t>(std::pow(static_cast<double>(N), 1.0 / s));
  auto fits = [&](std::uint64_t c) {
    const auto p = checked_power(c, s);
    return p.has_value() && *p <= N;
  };
  while (q > 0 && !fits(q)) --q;
  while (fits(q + 1)) ++q;
  return q;
}

std::uint64_t points_per_axis(const method_info& method, std::uint64_t n, std::uint64_t m) {
  const std::string_view name = method.name;
  if (name == "trapezoid" || name == "simpson" || name == "romberg") return n + 1;
  if (name == "gauss_legendre") return m * n;
  return n;  // rectangles, midpoint: one node per panel
}

namespace {

int order_at(const method_info& method, std::uint64_t n, std::uint64_t m) {
  if (method.name == "gauss_legendre") return static_cast<int>(2 * m);
  if (method.name == "romberg") {
    // n = 2^k panels: R(k,k) eliminates the h^2 … h^2k terms of the Euler–Maclaurin expansion.
    int k = 0;
    while ((std::uint64_t{1} << k) < n) ++k;
    return 2 * k + 2;
  }
  return method.order;
}

}  // namespace

std::optional<tensor_grid> tensor_grid_with_panels(const method_info& method, std::uint64_t n,
                                                   unsigned s, std::uint64_t m) {
  require(method.counts == count_constraint::tensor_grid, "method", method.name,
          "a tensor-product rule");
  const std::uint64_t p = points_per_axis(method, n, m);
  const auto evaluations = checked_power(p, s);
  if (!evaluations) return std::nullopt;
  return tensor_grid{n, p, *evaluations, order_at(method, n, m)};
}

std::optional<tensor_grid> largest_tensor_grid(const method_info& method, std::uint64_t N,
                                               unsigned s, std::uint64_t m) {
  require(method.counts == count_constraint::tensor_grid, "method", method.name,
          "a tensor-product rule");
  require(m >= 1, "m", m, "at least 1 node per panel");
  const std::uint64_t q = integer_root(N, s);  // the most points per axis that fit
  std::uint64_t n = 0;
  const std::string_view name = method.name;
  if (name == "trapezoid") {
    n = q >= 2 ? q - 1 : 0;
  } else if (name == "simpson") {
    n = q >= 3 ? ((q - 1) / 2) * 2 : 0;  // even n, n + 1 ≤ q
  } else if (name == "romberg") {
    if (q >= 3) {
      n = 2;
      while (2 * n + 1 <= q) n *= 2;
    }
  } else if (name == "gauss_legendre") {
    n = q / m;
  } else {
    n = q;
  }
  if (n == 0) return std::nullopt;
  return tensor_grid_with_panels(method, n, s, m);
}

stratified_count stratified_count_for(count_constraint counts, std::uint64_t N, unsigned s) {
  switch (counts) {
    case count_constraint::perfect_power: {
      const std::uint64_t k = integer_root(N, s);
      return {k, *checked_power(k, s)};
    }
    case count_constraint::perfect_square: {
      if (s == 1) return {N, N};
      const std::uint64_t k = integer_root(N, 2);
      return {k, k * k};
    }
    case count_constraint::any:
    case count_constraint::tensor_grid:
      break;
  }
  return {0, N};
}

}  // namespace quadmc
