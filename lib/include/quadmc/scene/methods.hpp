// The methods a scene file may name, with what the planner needs to know about each: kind
// (deterministic rule or random), whether it is a tensor product in s > 1, the rule's order r,
// which sample counts it can use, which integrands it applies to, and which option keys it takes.
//
// Use it to validate a [[method]] table, to map a nominal N to the count a method really uses,
// and to print `quadmc list`. Not the place for the methods' code (rules/, sampling/,
// estimators/); the runner dispatches on `name`.
//
// N → grid mapping (docs/theory.md#conventions: N = evaluations, n = panels per axis). A tensor
// rule with p(n) points per axis uses p(n)^s evaluations: rectangles and midpoint p = n, trapezoid
// and Simpson p = n + 1 (Simpson: n even), Gauss–Legendre p = m·n, Romberg (s = 1 only) p = 2^k + 1
// with n = 2^k panels. The planner takes the largest n with p(n)^s ≤ N. All of it is exact
// integer arithmetic: pow(4096, 1/3.) = 15.999… would floor to the wrong n.
// Orders r (|error| = O(n^-r) = O(N^(-r/s)) on smooth f): [Burden & Faires, §4.3–4.5] (rectangles
// 1, midpoint/trapezoid 2, Simpson 4, m-point Gauss 2m, Romberg R(k,k) 2k + 2).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace quadmc {

enum class method_kind {
  deterministic_rule,  // one run per N; repetitions do not apply
  random,              // `repetitions` independent runs per N
};

// Which sample counts a method (or point set) can use; the plan maps N down to the nearest one.
enum class count_constraint {
  any,             // every N ≥ 1 (independent points, Latin hypercube)
  tensor_grid,     // a rule: p(n)^s points, see above
  perfect_power,   // jittered / unjittered: one point per cell of a k^s grid, N = k^s
  perfect_square,  // padded jittered: 2D strata k×k padded across dimension pairs, N = k²
};

// Which integrands a method can integrate; a mismatch is a skip with the reason, or an error
// when the scene pairs them explicitly (parse.hpp, key `integrands`).
enum class integrand_requirement {
  any,
  one_dimensional,  // Romberg; importance sampling with a 1D warp
  irradiance,       // the hemisphere / light-area estimators: rendering integrands only
};

struct method_info {
  std::string_view name;
  std::string_view description;  // one line
  method_kind kind;
  bool tensor_product;  // in s > 1 the rule is the tensor product of its 1D rule
  int order;            // r for rules with a fixed order; 0 = depends on options (Gauss 2m,
                        // Romberg 2k + 2) or not a rule
  count_constraint counts;
  integrand_requirement applies_to;
  std::span<const std::string_view> options;  // accepted keys of its [[method]] table
};

// A sampling pattern on [0,1)^s, for the methods that take a `point_set` option.
struct point_set_info {
  std::string_view name;
  std::string_view description;
  count_constraint counts;
};

// A warp for importance sampling (a 1D density on [0,1] sampled by inversion).
struct warp_info {
  std::string_view name;
  std::string_view description;
  std::string_view parameter;  // its one parameter
  double default_value;
};

std::span<const method_info> method_catalogue();
std::span<const point_set_info> point_set_catalogue();
std::span<const warp_info> warp_catalogue();

const method_info* find_method(std::string_view name) noexcept;  // nullptr when unknown
const point_set_info* find_point_set(std::string_view name) noexcept;
const warp_info* find_warp(std::string_view name) noexcept;

// Comma-separated names, for "expected one of …" messages and `quadmc list`.
std::string method_names();
std::string point_set_names();
std::string warp_names();

// base^exponent, or nullopt when it exceeds 2^64 − 1 (no floating point anywhere).
std::optional<std::uint64_t> checked_power(std::uint64_t base, unsigned exponent) noexcept;

// The largest q ≥ 0 with q^s ≤ N, exactly (s ≥ 1).
std::uint64_t integer_root(std::uint64_t N, unsigned s) noexcept;

// One tensor grid: n panels per axis, p points per axis, p^s evaluations.
struct tensor_grid {
  std::uint64_t panels = 0;           // n
  std::uint64_t points_per_axis = 0;  // p(n)
  std::uint64_t evaluations = 0;      // p(n)^s
  int order = 0;                      // r of this rule at this n (Romberg's depends on n)
};

// Points per axis of rule `method` with n panels (`m` = Gauss–Legendre nodes per panel).
std::uint64_t points_per_axis(const method_info& method, std::uint64_t n, std::uint64_t m);

// The grid with the largest n such that p(n)^s ≤ N, or nullopt when even the smallest grid
// (n = 1; Simpson and Romberg n = 2) exceeds N. Precondition: method.counts == tensor_grid.
std::optional<tensor_grid> largest_tensor_grid(const method_info& method, std::uint64_t N,
                                               unsigned s, std::uint64_t m);

// The grid with exactly n panels per axis, or nullopt when p(n)^s overflows 64 bits.
std::optional<tensor_grid> tensor_grid_with_panels(const method_info& method, std::uint64_t n,
                                                   unsigned s, std::uint64_t m);

// The count a point-set constraint gives for nominal N in s dimensions: k^s (perfect_power),
// k² (perfect_square, s ≥ 2; any N when s = 1), N (any), with `per_axis` = k (0 for `any`).
struct stratified_count {
  std::uint64_t per_axis = 0;
  std::uint64_t evaluations = 0;
};
stratified_count stratified_count_for(count_constraint counts, std::uint64_t N, unsigned s);

}  // namespace quadmc
