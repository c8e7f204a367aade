// The point-set table of point_set_catalogue.hpp: each entry's estimators are instantiated here,
// once per set, by point_set_entry_for<P>.
#include "quadmc/estimators/point_set_catalogue.hpp"

#include "quadmc/core/batching.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/integer_powers.hpp"
#include "quadmc/estimators/importance_sampling.hpp"
#include "quadmc/estimators/irradiance_estimators.hpp"
#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/estimators/periodized_monte_carlo.hpp"
#include "quadmc/estimators/sample_values.hpp"
#include "quadmc/sampling/cmj_points.hpp"
#include "quadmc/sampling/halton_points.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/interlaced_sobol_points.hpp"
#include "quadmc/sampling/inversion_warps.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/latin_hypercube_points.hpp"
#include "quadmc/sampling/padded_jittered_points.hpp"
#include "quadmc/sampling/padded_sobol_points.hpp"
#include "quadmc/sampling/periodizing_transforms.hpp"
#include "quadmc/sampling/pmj02_points.hpp"
#include "quadmc/sampling/point_file.hpp"
#include "quadmc/sampling/rank1_lattice_points.hpp"
#include "quadmc/sampling/rank1_lattice_sequence.hpp"
#include "quadmc/sampling/sobol_points.hpp"
#include "quadmc/sampling/stratum_grid.hpp"
#include "quadmc/sampling/unjittered_points.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace quadmc {

namespace {

// A warp W on [0,1] carried to the interval [a, b]: X = a + (b − a)W(U), p_X = p_W/(b − a).
template <class W>
class interval_warp {
 public:
  interval_warp(W w, double a, double b) : w_(std::move(w)), a_(a), width_(b - a) {}
  std::size_t input_dimension() const noexcept { return 1; }
  std::size_t output_dimension() const noexcept { return 1; }
  void sample(std::span<const double> u, std::span<double> x) const noexcept {
    x[0] = a_ + width_ * w_.sample(u[0]);
  }
  double pdf(std::span<const double> x) const noexcept {
    return w_.pdf((x[0] - a_) / width_) / width_;
  }

 private:
  W w_;
  double a_;
  double width_;
};

// How an entry builds its concrete set: visit(s, n, options, stream, fn) calls fn with the set,
// so every estimator below is compiled once per concrete type (no virtual call per point).
template <class P>
struct plain_set {
  template <class Fn>
  static decltype(auto) visit(std::size_t s, std::uint64_t n, const point_set_options&,
                              const sample_stream& st, Fn&& fn) {
    return fn(P(s, n, st.seed, st.stream, st.rng));
  }
};

// Independent points: point i is the same whatever N, so the set extends.
template <class P>
struct extensible_plain_set : plain_set<P> {
  static constexpr coefficient_transform coefficients = coefficient_transform::none;
  template <class Fn>
  static decltype(auto) visit_extensible(std::size_t s, std::uint64_t n, const point_set_options& o,
                                         const sample_stream& st, Fn&& fn) {
    return plain_set<P>::visit(s, n, o, st, std::forward<Fn>(fn));
  }
};

constexpr std::array<randomization, 5> sobol_randomizations{
    randomization::owen, randomization::fast_owen, randomization::lms_shift, randomization::shift,
    randomization::none};
// Sobol's, less "none": unrandomized, every pair would be the same two coordinates.
constexpr std::array<randomization, 4> padded_sobol_randomizations{
    randomization::owen, randomization::fast_owen, randomization::lms_shift, randomization::shift};
constexpr std::array<randomization, 3> halton_randomizations{
    randomization::owen, randomization::permutation, randomization::none};
constexpr std::array<randomization, 2> lattice_randomizations{randomization::shift,
                                                              randomization::none};

constexpr std::string_view name_of(randomization r) noexcept {
  switch (r) {
    case randomization::none:
      return "none";
    case randomization::shift:
      return "shift";
    case randomization::lms_shift:
      return "lms_shift";
    case randomization::owen:
      return "owen";
    case randomization::fast_owen:
      return "fast_owen";
    case randomization::permutation:
      return "permutation";
  }
  return "?";
}

// A set's randomizations as the values of its `randomization` key, in the same order.
template <std::size_t N>
constexpr std::array<std::string_view, N> names_of(const std::array<randomization, N>& rs) {
  std::array<std::string_view, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = name_of(rs[i]);
  return out;
}
constexpr auto sobol_randomization_names = names_of(sobol_randomizations);
constexpr auto padded_sobol_randomization_names = names_of(padded_sobol_randomizations);
constexpr auto halton_randomization_names = names_of(halton_randomizations);
constexpr auto lattice_randomization_names = names_of(lattice_randomizations);
// Sobol's interlacing factors α, as the decimal texts of the integer key (point_set_option).
constexpr std::array<std::string_view, max_interlacing> interlacing_names{"1", "2", "3"};
// The randomizations an interlaced net (α > 1) has: those whose theory carries over to the
// interlaced points (docs/theory.md#interlaced-nets). fast_owen has no rate even for α = 1, and
// lms_shift's equivalence with Owen's scramble is not carried to interlaced nets here.
constexpr std::array<randomization, 3> interlaced_randomizations{
    randomization::owen, randomization::shift, randomization::none};
// In the order of enum periodization, which periodization_named relies on.
constexpr std::array<std::string_view, 7> periodization_names{"none",
                                                              "baker",
                                                              c0_transform::name,
                                                              c1_transform::name,
                                                              c1sin_transform::name,
                                                              c2sin_transform::name,
                                                              c3sin_transform::name};
// The ones that weight the points (is_weighted): no equal-weight points to give.
constexpr std::array<std::string_view, 5> weighted_periodization_names{
    c0_transform::name, c1_transform::name, c1sin_transform::name, c2sin_transform::name,
    c3sin_transform::name};

periodization periodization_named(std::string_view name) {
  for (std::size_t i = 0; i < periodization_names.size(); ++i) {
    if (periodization_names[i] == name) return static_cast<periodization>(i);
  }
  return periodization::none;
}

// Each set's keys, in the order of its options_from's values.
constexpr std::array<point_set_option, 4> sobol_options{{
    {"randomization",
     "\"owen\" (default: nested uniform scrambling), \"fast_owen\" (Burley's hash, not exactly "
     "nested), \"lms_shift\" (linear matrix scramble + digital shift), \"shift\" (digital shift), "
     "\"none\" (deterministic, one run per cell); the label gets \"_<randomization>\"",
     sobol_randomization_names,
     {}},
    {"allow_any_n",
     "true: use each N as it is (no net unless N = 2^m); default false: N maps to the largest "
     "2^m <= N; the label gets \"_any_n\"",
     {},
     "_any_n"},
    {"drop_first_point",
     "true: start at point 1, not the origin (the anti-pattern); the label gets \"_drop_first\"",
     {},
     "_drop_first"},
    {"interlacing",
     "an integer 1 (default: the Sobol' points), 2 or 3: the order-alpha net interlacing the "
     "digits of alpha*s Sobol' dimensions (alpha*s <= 3667; randomization owen, shift or none); "
     "the label gets \"_interlacing<alpha>\"",
     interlacing_names,
     {},
     true},
}};
constexpr std::array<point_set_option, 1> padded_sobol_options{{
    {"randomization",
     "\"owen\" (default), \"fast_owen\", \"lms_shift\" or \"shift\", as sobol's, drawn "
     "independently per coordinate; the label gets the suffix",
     padded_sobol_randomization_names,
     {}},
}};
constexpr std::array<point_set_option, 1> halton_options{{
    {"randomization",
     "\"owen\" (default: nested scrambling in each base), \"permutation\" (random digit "
     "permutations per base and digit), \"none\" (deterministic); the label gets the suffix",
     halton_randomization_names,
     {}},
}};
constexpr std::array<point_set_option, 2> lattice_options{{
    {"randomization",
     "\"shift\" (default: one uniform shift modulo 1), \"none\" (the lattice itself, "
     "deterministic); the label gets the suffix",
     lattice_randomization_names,
     {}},
    {"periodization",
     "\"none\" (default), \"baker\" (the tent map 1 - |2x - 1| of the points), or a change of "
     "variables weighting f(phi(x)) by prod phi'(x_j): \"c0\" (3x^2 - 2x^3), \"c1\" "
     "(x^3(10 - 15x + 6x^2)), \"c1sin\", \"c2sin\", \"c3sin\" (Sidi's sin^2, sin^3, sin^4 "
     "transforms); the label gets the suffix",
     periodization_names,
     {},
     false,
     weighted_periodization_names},
}};

std::optional<randomization> randomization_given(std::string_view value) {
  return value.empty() ? std::nullopt : parse_randomization(value);
}

point_set_options no_options(point_set_values) {
  return {};
}
point_set_options sobol_options_from(point_set_values v) {
  point_set_options o;
  o.random = randomization_given(v[0]);
  o.allow_any_n = v[1] == "true";
  o.drop_first_point = v[2] == "true";
  // A choice of interlacing_names: "1", "2" or "3" (checked against them before).
  if (!v[3].empty()) o.interlacing = static_cast<unsigned>(v[3][0] - '0');
  return o;
}
// The sets whose one key is `randomization` (padded_sobol, halton).
point_set_options randomization_from(point_set_values v) {
  point_set_options o;
  o.random = randomization_given(v[0]);
  return o;
}
point_set_options lattice_options_from(point_set_values v) {
  point_set_options o;
  o.random = randomization_given(v[0]);
  o.periodic = periodization_named(v[1]);
  return o;
}

// An interlaced Sobol' net (α ≥ 2): [Dick 2011]'s rate when Owen-scrambled before interlacing,
// [Dick 2008]'s when deterministic or digitally shifted; no net (a prefix of N ≠ 2^m, or the
// first point dropped) has the broken net's (docs/theory.md#interlaced-nets).
point_set_theory interlaced_sobol_theory(const point_set_options& o) {
  const std::string order = fmt::format("interlacing {}", o.interlacing);
  if (o.drop_first_point) return {rate_basis::broken_net, order + ", first point dropped", {}};
  if (o.allow_any_n) return {rate_basis::broken_net, order + ", N not 2^m (allow_any_n)", {}};
  point_set_theory t{rate_basis::interlaced_net, {}, {}};
  t.interlacing = o.interlacing;
  t.scrambled = o.random.value_or(sobol_randomizations.front()) == randomization::owen;
  return t;
}

// The theories of docs/theory.md#quasi-monte-carlo, per randomization.
point_set_theory sobol_theory(const point_set_options& o) {
  if (o.interlacing > 1) return interlaced_sobol_theory(o);
  switch (o.random.value_or(sobol_randomizations.front())) {
    case randomization::owen:
    case randomization::lms_shift:
      if (o.drop_first_point) return {rate_basis::broken_net, "first point dropped", {}};
      if (o.allow_any_n) return {rate_basis::broken_net, "N not 2^m (allow_any_n)", {}};
      return {rate_basis::scrambled_net, {}, {}};
    case randomization::fast_owen:
      return {rate_basis::unproven,
              "hash-based, not exactly nested uniform: Owen's rates are not proven for it",
              "docs/theory.md#scrambled-nets; [Burley 2020]"};
    case randomization::shift:
      return {rate_basis::low_discrepancy, "digital shift: one shift shared by all points",
              "docs/theory.md#digital-shift; [Dick & Pillichshammer 2010]"};
    default:
      return {rate_basis::low_discrepancy, "unrandomized Sobol' points",
              "docs/theory.md#digital-shift; [Niederreiter 1992, Thm 4.10]"};
  }
}
// Each pair a scrambled (0, m, 2)-net: Owen's rates in s ≤ 2, the padded rate beyond
// (docs/theory.md#padded-sobol); the randomizations that are not nested uniform as sobol's.
point_set_theory padded_sobol_theory(const point_set_options& o) {
  point_set_theory t = sobol_theory(o);
  t.padded = true;
  if (t.basis == rate_basis::scrambled_net) t.note = "(0, m, 2)-net per pair of dimensions";
  return t;
}
// Distributed as a nested uniform scramble of a (0,2)-sequence [Helmer et al. 2021]: Owen's rates
// at N = 2^m in s ≤ 2, the padded rate beyond (docs/theory.md#progressive-multi-jittered).
point_set_theory pmj02_theory(const point_set_options&) {
  point_set_theory t{rate_basis::scrambled_net, "random (0,2)-sequence per pair, N = 2^m", {}};
  t.padded = true;
  return t;
}
point_set_theory halton_theory(const point_set_options& o) {
  const randomization r = o.random.value_or(halton_randomizations.front());
  return {rate_basis::low_discrepancy,
          r == randomization::none
              ? "Halton points"
              : fmt::format("{}-randomized Halton points, no faster rate proven", to_string(r)),
          "docs/theory.md#halton; [Halton 1960]; [Niederreiter 1992, Thm 3.6]"};
}
// The order k to which the integrand the lattice rule sees has periodic derivatives
// (docs/theory.md#lattice-periodizations): none −1 (f itself, not periodic), the baker's map 0
// (f∘φ continuous and periodic), and m − 1 for a Jacobian vanishing to order m at 0 and 1.
int periodic_order_of(periodization p) noexcept {
  switch (p) {
    case periodization::none:
      return -1;
    case periodization::baker:
      return 0;
    case periodization::c0:
      return c0_transform::jacobian_zero_order - 1;
    case periodization::c1:
      return c1_transform::jacobian_zero_order - 1;
    case periodization::c1sin:
      return c1sin_transform::jacobian_zero_order - 1;
    case periodization::c2sin:
      return c2sin_transform::jacobian_zero_order - 1;
    case periodization::c3sin:
      return c3sin_transform::jacobian_zero_order - 1;
  }
  return -1;
}

point_set_theory lattice_theory(const point_set_options& o) {
  const bool shifted = o.random.value_or(lattice_randomizations.front()) != randomization::none;
  point_set_theory t{
      rate_basis::shifted_lattice, shifted ? "" : "unshifted lattice (deterministic)", {}};
  t.periodization = to_string(o.periodic);
  t.periodic_order = periodic_order_of(o.periodic);
  t.weighted = is_weighted(o.periodic);
  return t;
}

// The strata of each set, with its default options (the gallery's tests count the points per
// stratum of each). No strata by construction: independent points, Halton.
std::optional<point_strata> no_strata(std::size_t, std::uint64_t) {
  return std::nullopt;
}
// One point per cell of the k^s grid (jittered, unjittered).
std::optional<point_strata> grid_strata(std::size_t s, std::uint64_t n) {
  const std::uint64_t k = integer_root(n, s);
  if (checked_power(k, s) != n) return std::nullopt;
  return point_strata{strata_kind::cells, k};
}
// The k × k group of padded points (N = k²) is the whole set in s = 2; beyond, the cells are
// those of 2D projections only.
std::optional<point_strata> padded_strata(std::size_t s, std::uint64_t n) {
  if (s != 2) return std::nullopt;
  const std::uint64_t k = integer_root(n, 2);
  if (k * k != n) return std::nullopt;
  return point_strata{strata_kind::cells, k};
}
// A correlated multi-jittered pair: the k × k cells when N = k² in s = 2, else (N = k(k + 1)) its
// N fine rows and columns ([Kensler 2013]).
std::optional<point_strata> cmj_strata(std::size_t s, std::uint64_t n) {
  if (s != 2 || !cmj_points::is_valid_size(s, n)) return std::nullopt;
  const std::uint64_t k = integer_root(n, 2);
  if (k * k == n) return point_strata{strata_kind::cells, k};
  return point_strata{strata_kind::rows_and_columns, n};
}
// N rows and columns, one point in each, along every axis ([McKay et al. 1979]).
std::optional<point_strata> latin_strata(std::size_t, std::uint64_t n) {
  return point_strata{strata_kind::rows_and_columns, n};
}
// The first two Sobol' coordinates are a (0, m, 2)-net and Owen scrambling keeps it
// ([Owen 1995]): for N = 2^m = k² the k × k square grid is its elementary interval of shape
// 2^(m/2) × 2^(m/2).
std::optional<point_strata> net_strata(std::size_t s, std::uint64_t n) {
  if (s != 2 || !std::has_single_bit(n)) return std::nullopt;
  const std::uint64_t k = integer_root(n, 2);
  if (k * k != n) return std::nullopt;
  return point_strata{strata_kind::cells, k};
}
// A rank-1 lattice with N = 2^m in 2D: coordinates {i/N + Δ₁}, {i·z₂/N + Δ₂}, z₂ odd, so both
// are permutations of the N columns.
std::optional<point_strata> lattice_strata(std::size_t s, std::uint64_t n) {
  if (s > 2 || !std::has_single_bit(n)) return std::nullopt;
  return point_strata{strata_kind::rows_and_columns, n};
}

const point_set_entry& entry_named(std::string_view name);

// The checks every QMC set makes before it builds its points: a randomization it has, and a
// count it holds (the nearest valid sizes named otherwise).
void require_qmc_request(const point_set_entry& set, std::size_t s, std::uint64_t n,
                         const point_set_options& options) {
  if (options.random && !set.has(*options.random)) {
    std::string names;
    for (const randomization r : set.randomizations) {
      names += fmt::format("{}{}", names.empty() ? "" : ", ", to_string(r));
    }
    throw invalid_argument("randomization", std::string(to_string(*options.random)),
                           fmt::format("one of {} for the {} points", names, set.name));
  }
  if (const std::string problem = interlacing_problem(set, options); !problem.empty()) {
    throw invalid_argument("randomization", std::string(to_string(*set.randomization_of(options))),
                           problem);
  }
  if (const std::string problem = dimension_problem(set, s, options); !problem.empty()) {
    throw invalid_argument("dimension s", std::to_string(s), problem);
  }
  const std::string problem = size_problem(set, s, n, options);
  if (!problem.empty()) throw invalid_argument("number of points N", std::to_string(n), problem);
}

struct sobol_set {
  // The first 2^m points of the set built for n_cap are a net for every 2^m ≤ n_cap (the
  // scramble's depth covers n_cap), in Gray-code order; a digitally shifted one has the Walsh
  // coefficients of the guaranteed rule.
  static constexpr coefficient_transform coefficients = coefficient_transform::walsh;
  template <class Fn>
  static decltype(auto) visit_extensible(std::size_t s, std::uint64_t n, const point_set_options& o,
                                         const sample_stream& st, Fn&& fn) {
    return visit(s, n, o, st, std::forward<Fn>(fn));
  }
  template <class Fn>
  static decltype(auto) visit(std::size_t s, std::uint64_t n, const point_set_options& o,
                              const sample_stream& st, Fn&& fn) {
    const point_set_entry& set = entry_named("sobol");
    require_qmc_request(set, s, n, o);
    const bool drop = o.drop_first_point;
    if (o.interlacing > 1) return visit_interlaced(set, s, n, o, st, std::forward<Fn>(fn));
    switch (*set.randomization_of(o)) {
      case randomization::owen:
        return fn(sobol_points<owen_scramble>(s, n, st.seed, st.stream, drop, st.rng));
      case randomization::fast_owen:
        return fn(sobol_points<fast_owen_scramble>(s, n, st.seed, st.stream, drop, st.rng));
      case randomization::lms_shift:
        return fn(sobol_points<linear_matrix_scramble>(s, n, st.seed, st.stream, drop, st.rng));
      case randomization::shift:
        return fn(sobol_points<digital_shift>(s, n, st.seed, st.stream, drop, st.rng));
      default:
        return fn(sobol_points<unrandomized_digits>(s, n, st.seed, st.stream, drop, st.rng));
    }
  }

  // α = interlacing ≥ 2: the αs-dimensional Sobol' points randomized, then interlaced.
  template <class Fn>
  static decltype(auto) visit_interlaced(const point_set_entry& set, std::size_t s, std::uint64_t n,
                                         const point_set_options& o, const sample_stream& st,
                                         Fn&& fn) {
    const unsigned alpha = o.interlacing;
    const bool drop = o.drop_first_point;
    switch (*set.randomization_of(o)) {
      case randomization::owen:
        return fn(
            interlaced_sobol_points<owen_scramble>(s, alpha, n, st.seed, st.stream, drop, st.rng));
      case randomization::shift:
        return fn(
            interlaced_sobol_points<digital_shift>(s, alpha, n, st.seed, st.stream, drop, st.rng));
      case randomization::none:
        return fn(interlaced_sobol_points<unrandomized_digits>(s, alpha, n, st.seed, st.stream,
                                                               drop, st.rng));
      default:
        break;
    }
    throw invalid_argument("randomization", std::string(to_string(*set.randomization_of(o))),
                           interlacing_problem(set, o));
  }
};

struct padded_sobol_set {
  template <class Fn>
  static decltype(auto) visit(std::size_t s, std::uint64_t n, const point_set_options& o,
                              const sample_stream& st, Fn&& fn) {
    const point_set_entry& set = entry_named("padded_sobol");
    require_qmc_request(set, s, n, o);
    switch (*set.randomization_of(o)) {
      case randomization::owen:
        return fn(padded_sobol_points<owen_scramble>(s, n, st.seed, st.stream, st.rng));
      case randomization::fast_owen:
        return fn(padded_sobol_points<fast_owen_scramble>(s, n, st.seed, st.stream, st.rng));
      case randomization::lms_shift:
        return fn(padded_sobol_points<linear_matrix_scramble>(s, n, st.seed, st.stream, st.rng));
      default:
        return fn(padded_sobol_points<digital_shift>(s, n, st.seed, st.stream, st.rng));
    }
  }
};

struct halton_set {
  static constexpr coefficient_transform coefficients = coefficient_transform::none;
  template <class Fn>
  static decltype(auto) visit_extensible(std::size_t s, std::uint64_t n, const point_set_options& o,
                                         const sample_stream& st, Fn&& fn) {
    return visit(s, n, o, st, std::forward<Fn>(fn));
  }
  template <class Fn>
  static decltype(auto) visit(std::size_t s, std::uint64_t n, const point_set_options& o,
                              const sample_stream& st, Fn&& fn) {
    const point_set_entry& set = entry_named("halton");
    require_qmc_request(set, s, n, o);
    switch (*set.randomization_of(o)) {
      case randomization::owen:
        return fn(halton_points<nested_digit_scramble>(s, n, st.seed, st.stream, st.rng));
      case randomization::permutation:
        return fn(halton_points<random_digit_permutation>(s, n, st.seed, st.stream, st.rng));
      default:
        return fn(halton_points<unrandomized_radical_inverse>(s, n, st.seed, st.stream, st.rng));
    }
  }
};

struct lattice_set {
  // The extensible lattice in radical-inverse order: its first 2^m points are the 2^m-point
  // lattice with the same shift, for every 2^m ≤ n_cap; the guaranteed rule takes its Fourier
  // coefficients.
  static constexpr coefficient_transform coefficients = coefficient_transform::fourier;
  template <class Fn>
  static decltype(auto) visit_extensible(std::size_t s, std::uint64_t n, const point_set_options& o,
                                         const sample_stream& st, Fn&& fn) {
    const point_set_entry& set = entry_named("lattice");
    require_qmc_request(set, s, n, o);
    const bool shifted = *set.randomization_of(o) == randomization::shift;
    if (o.periodic == periodization::baker) {
      return fn(rank1_lattice_sequence<baker_transform>(s, n, st.seed, st.stream, shifted, st.rng));
    }
    return fn(rank1_lattice_sequence<no_periodization>(s, n, st.seed, st.stream, shifted, st.rng));
  }
  template <class Fn>
  static decltype(auto) visit(std::size_t s, std::uint64_t n, const point_set_options& o,
                              const sample_stream& st, Fn&& fn) {
    const point_set_entry& set = entry_named("lattice");
    require_qmc_request(set, s, n, o);
    const bool shifted = *set.randomization_of(o) == randomization::shift;
    if (is_weighted(o.periodic)) refuse_weighted(o.periodic);
    if (o.periodic == periodization::baker) {
      return fn(rank1_lattice_points<baker_transform>(s, n, st.seed, st.stream, shifted, st.rng));
    }
    return fn(rank1_lattice_points<no_periodization>(s, n, st.seed, st.stream, shifted, st.rng));
  }

  // The sample mean: with a weighted periodization, of g = f(φ(x))∏φ'(x_j) over the lattice
  // points themselves (estimators/periodized_monte_carlo.hpp); else monte_carlo over the points
  // visit makes, as every set's.
  static estimate monte_carlo_over(const any_integrand& f, const point_set_options& o,
                                   const sample_stream& st, std::uint64_t n, unsigned threads) {
    if (!is_weighted(o.periodic)) {
      return visit(f.dimension(), n, o, st,
                   [&](const auto& points) { return monte_carlo(f, points, threads); });
    }
    const point_set_entry& set = entry_named("lattice");
    require_qmc_request(set, f.dimension(), n, o);
    const bool shifted = *set.randomization_of(o) == randomization::shift;
    const rank1_lattice_points<no_periodization> points(f.dimension(), n, st.seed, st.stream,
                                                        shifted, st.rng);
    switch (o.periodic) {
      case periodization::c0:
        return periodized_monte_carlo<c0_transform>(f, points, threads);
      case periodization::c1:
        return periodized_monte_carlo<c1_transform>(f, points, threads);
      case periodization::c1sin:
        return periodized_monte_carlo<c1sin_transform>(f, points, threads);
      case periodization::c2sin:
        return periodized_monte_carlo<c2sin_transform>(f, points, threads);
      default:
        return periodized_monte_carlo<c3sin_transform>(f, points, threads);
    }
  }

  // The points, importance and irradiance estimators take equal-weight points: a weighted
  // periodization has none to give.
  [[noreturn]] static void refuse_weighted(periodization p) {
    throw invalid_argument(
        "periodization", std::string(to_string(p)),
        fmt::format("none or baker for the lattice's points and its importance and irradiance "
                    "estimators: {} is a change of variables that weights each point by "
                    "∏φ'(x_j) (docs/theory.md#lattice-periodizations), so only the "
                    "lattice's sample mean (the lattice method) applies it",
                    to_string(p)));
  }
};

// The extensible sets' runs of values: the set built for n_cap points, the run
// [first, first + y.size()) of it (sample_values.hpp).
template <class Set>
void extension_over(const any_integrand& f, const point_set_options& options,
                    const sample_stream& stream, std::uint64_t n_cap, std::uint64_t first,
                    std::span<double> y, unsigned threads, bool transform_order) {
  Set::visit_extensible(f.dimension(), n_cap, options, stream, [&](const auto& points) {
    sample_values(f, points, first, y, threads,
                  transform_order && Set::coefficients == coefficient_transform::walsh);
    return 0;
  });
}

template <class Set>
estimate monte_carlo_over(const any_integrand& f, const point_set_options& options,
                          const sample_stream& stream, std::uint64_t n, unsigned threads) {
  return Set::visit(f.dimension(), n, options, stream,
                    [&](const auto& points) { return monte_carlo(f, points, threads); });
}

// The interval [a, b] of a 1D integrand, the warps' target; checked before any point is made.
std::pair<double, double> importance_interval(const any_integrand& f) {
  require(f.dimension() == 1, "integrand dimension", f.dimension(),
          "1 (importance sampling with a 1D warp)");
  const box& domain = f.info().domain;
  const double a = domain.lower[0];
  const double b = domain.upper[0];
  require(std::isfinite(a) && std::isfinite(b) && b > a, "integrand interval upper", b,
          "a finite interval with b > a");
  return {a, b};
}

template <point_set P>
estimate importance_with(const any_integrand& f, const unit_warp& warp,
                         std::pair<double, double> interval, const P& points, unsigned threads) {
  const auto [a, b] = interval;
  switch (warp.kind) {
    case unit_warp_kind::power:
      return importance_sampling(f, interval_warp(power_warp(warp.parameter), a, b), points,
                                 threads);
    case unit_warp_kind::truncated_exponential:
      return importance_sampling(f, interval_warp(truncated_exponential_warp(warp.parameter), a, b),
                                 points, threads);
  }
  throw invalid_argument("warp kind", std::to_string(static_cast<int>(warp.kind)),
                         "power or truncated_exponential");
}

template <class Set>
estimate importance_over(const any_integrand& f, const unit_warp& warp,
                         const point_set_options& options, const sample_stream& stream,
                         std::uint64_t n, unsigned threads) {
  const std::pair<double, double> interval = importance_interval(f);
  return Set::visit(1, n, options, stream, [&](const auto& points) {
    return importance_with(f, warp, interval, points, threads);
  });
}

template <point_set P>
estimate irradiance_with(irradiance_sampling technique, const irradiance_setup& setup,
                         const P& points, unsigned threads) {
  switch (technique) {
    case irradiance_sampling::uniform_hemisphere:
      return irradiance_uniform_hemisphere(setup, points, threads);
    case irradiance_sampling::cosine_hemisphere:
      return irradiance_cosine_hemisphere(setup, points, threads);
    case irradiance_sampling::light_area:
      return irradiance_light_area(setup, points, threads);
  }
  throw invalid_argument("irradiance technique", std::to_string(static_cast<int>(technique)),
                         "uniform_hemisphere, cosine_hemisphere or light_area");
}

template <class Set>
estimate irradiance_over(irradiance_sampling technique, const irradiance_setup& setup,
                         const point_set_options& options, const sample_stream& stream,
                         std::uint64_t n, unsigned threads) {
  return Set::visit(2, n, options, stream, [&](const auto& points) {
    return irradiance_with(technique, setup, points, threads);
  });
}

template <class Set>
void points_over(std::size_t s, std::uint64_t n, const point_set_options& options,
                 const sample_stream& stream, const point_batch_sink& sink) {
  Set::visit(s, n, options, stream, [&](const auto& points) {
    std::vector<double> x(batch_points * s);
    for (std::uint64_t first = 0; first < n; first += batch_points) {
      const std::uint64_t count = std::min<std::uint64_t>(batch_points, n - first);
      const std::span<double> batch(x.data(), count * s);
      points.generate(first, batch);
      sink(first, batch);
    }
    return 0;
  });
}

// What an entry states beside its estimators; the defaults are those of a set without options.
struct set_facts {
  std::string_view name;
  std::string_view description;
  point_count counts = point_count::any;
  std::optional<point_strata> (*strata)(std::size_t, std::uint64_t) = no_strata;
  std::span<const randomization> randomizations = {};
  std::size_t max_dimension = 0;
  error_source errors = error_source::own;
  std::uint64_t max_points = 0;
  bool takes_any_prefix = false;
  std::span<const point_set_option> options = {};
  point_set_options (*options_from)(point_set_values) = no_options;
  point_set_theory (*theory)(const point_set_options&) = nullptr;
  // A set whose sample mean is not monte_carlo over its points (the lattice's weighted
  // periodizations) gives its own; nullptr: monte_carlo_over<Set>.
  estimate (*monte_carlo)(const any_integrand&, const point_set_options&, const sample_stream&,
                          std::uint64_t, unsigned) = nullptr;
};

template <class Set>
concept extensible_set = requires {
  Set::coefficients;
};

template <class Set>
constexpr point_set_entry point_set_entry_for(const set_facts& f) {
  point_set_entry e{f.name,
                    f.description,
                    f.counts,
                    f.randomizations,
                    f.max_dimension,
                    f.errors,
                    f.max_points,
                    f.takes_any_prefix,
                    f.options,
                    f.options_from,
                    f.theory,
                    f.strata,
                    f.monte_carlo != nullptr ? f.monte_carlo : monte_carlo_over<Set>,
                    importance_over<Set>,
                    irradiance_over<Set>,
                    points_over<Set>};
  if constexpr (extensible_set<Set>) {
    e.extension_over = extension_over<Set>;
    e.coefficients = Set::coefficients;
  }
  return e;
}

constexpr std::array<point_set_entry, 11> entries{{
    point_set_entry_for<extensible_plain_set<independent_points>>(
        {.name = "independent", .description = "independent uniform points"}),
    point_set_entry_for<plain_set<jittered_points>>(
        {.name = "jittered",
         .description = "one random point per cell of a k^s grid",
         .counts = point_count::perfect_power,
         .strata = grid_strata}),
    point_set_entry_for<plain_set<unjittered_points>>(
        {.name = "unjittered",
         .description = "cell centres of a randomly shifted k^s grid",
         .counts = point_count::perfect_power,
         .strata = grid_strata,
         .errors = error_source::none}),
    point_set_entry_for<plain_set<padded_jittered_points>>(
        {.name = "padded_jittered",
         .description = "k x k jittered strata padded across dimension pairs",
         .counts = point_count::perfect_square,
         .strata = padded_strata}),
    point_set_entry_for<plain_set<latin_hypercube_points>>(
        {.name = "latin_hypercube", .description = "Latin hypercube", .strata = latin_strata}),
    point_set_entry_for<plain_set<cmj_points>>(
        {.name = "cmj",
         .description = "correlated multi-jittered m x n cells (Kensler), padded across pairs",
         .counts = point_count::near_square,
         .strata = cmj_strata}),
    point_set_entry_for<sobol_set>(
        {.name = "sobol",
         .description =
             "Sobol' points (Joe-Kuo directions), Gray-code order, N = 2^m when randomized",
         .counts = point_count::power_of_two,
         .strata = net_strata,
         .randomizations = sobol_randomizations,
         .max_dimension = sobol_matrices::max_dimension,
         .errors = error_source::replicates,
         .max_points = std::uint64_t{1} << 32,
         .takes_any_prefix = true,
         .options = sobol_options,
         .options_from = sobol_options_from,
         .theory = sobol_theory}),
    point_set_entry_for<padded_sobol_set>(
        {.name = "padded_sobol",
         .description = "scrambled 2D Sobol' nets per pair of dimensions, shuffled across pairs",
         .counts = point_count::power_of_two,
         .strata = net_strata,
         .randomizations = padded_sobol_randomizations,
         .errors = error_source::replicates,
         .max_points = std::uint64_t{1} << 32,
         .options = padded_sobol_options,
         .options_from = randomization_from,
         .theory = padded_sobol_theory}),
    point_set_entry_for<plain_set<pmj02_points>>(
        {.name = "pmj02",
         .description = "progressive multi-jittered (0,2) sequence per pair, any N, padded",
         .strata = net_strata,
         .errors = error_source::replicates,
         .max_points = pmj02_points::max_points,
         .theory = pmj02_theory}),
    point_set_entry_for<halton_set>({.name = "halton",
                                     .description = "Halton points in the first s prime bases",
                                     .randomizations = halton_randomizations,
                                     .max_dimension = max_halton_dimension,
                                     .errors = error_source::replicates,
                                     .options = halton_options,
                                     .options_from = randomization_from,
                                     .theory = halton_theory}),
    point_set_entry_for<lattice_set>(
        {.name = "lattice",
         .description = "rank-1 lattice (Cools-Kuo-Nuyens vector), N = 2^m <= 2^20, random shift",
         .counts = point_count::power_of_two,
         .strata = lattice_strata,
         .randomizations = lattice_randomizations,
         .max_dimension = max_lattice_dimension,
         .errors = error_source::replicates,
         .max_points = max_lattice_points,
         .options = lattice_options,
         .options_from = lattice_options_from,
         .theory = lattice_theory,
         .monte_carlo = lattice_set::monte_carlo_over}),
}};

const point_set_entry& entry_named(std::string_view name) {
  return *find_point_set(name);
}

}  // namespace

point_count_choice largest_point_count(point_count counts, std::uint64_t N, std::size_t s) {
  switch (counts) {
    case point_count::perfect_power: {
      const std::uint64_t k = integer_root(N, s);
      return {k, *checked_power(k, s)};
    }
    case point_count::perfect_square: {
      if (s == 1) return {N, N};
      const std::uint64_t k = integer_root(N, 2);
      return {k, k * k};
    }
    case point_count::near_square: {
      if (s == 1) return {N, N};
      const std::uint64_t k = integer_root(N, 2);
      return {k, k * (k + 1) <= N ? k * (k + 1) : k * k};
    }
    case point_count::power_of_two:
      return {0, N == 0 ? 0 : std::bit_floor(N)};
    case point_count::any:
      break;
  }
  return {0, N};
}

estimate importance_over_file(const any_integrand& f, const unit_warp& warp,
                              const file_points& points, unsigned threads) {
  return importance_with(f, warp, importance_interval(f), points, threads);
}

estimate irradiance_over_file(irradiance_sampling technique, const irradiance_setup& setup,
                              const file_points& points, unsigned threads) {
  return irradiance_with(technique, setup, points, threads);
}

namespace {

// zsobol's points belong to an image: asked for those of one integral, it says where they are.
[[noreturn]] void zsobol_is_render_only() {
  throw invalid_argument("point set", "zsobol",
                         "a point set of the catalogue: zsobol indexes its points by a pixel's "
                         "Morton code, so it samples images only (quadmc render)");
}
estimate zsobol_monte_carlo(const any_integrand&, const point_set_options&, const sample_stream&,
                            std::uint64_t, unsigned) {
  zsobol_is_render_only();
}
estimate zsobol_importance(const any_integrand&, const unit_warp&, const point_set_options&,
                           const sample_stream&, std::uint64_t, unsigned) {
  zsobol_is_render_only();
}
estimate zsobol_irradiance(irradiance_sampling, const irradiance_setup&, const point_set_options&,
                           const sample_stream&, std::uint64_t, unsigned) {
  zsobol_is_render_only();
}
void zsobol_points_over(std::size_t, std::uint64_t, const point_set_options&, const sample_stream&,
                        const point_batch_sink&) {
  zsobol_is_render_only();
}

constexpr std::array<randomization, 1> zsobol_randomizations{randomization::owen};

constexpr point_set_entry zsobol_entry{
    "zsobol",
    "render only: one Owen-scrambled 2D Sobol' sequence over the image, by Morton order",
    point_count::power_of_two,
    zsobol_randomizations,
    2,
    error_source::replicates,
    std::uint64_t{1} << 32,
    false,
    {},
    no_options,
    nullptr,
    net_strata,
    zsobol_monte_carlo,
    zsobol_importance,
    zsobol_irradiance,
    zsobol_points_over};

}  // namespace

const point_set_entry& zsobol_render_set() noexcept {
  return zsobol_entry;
}

std::span<const point_set_entry> point_set_catalogue() noexcept {
  return entries;
}

const point_set_entry* find_point_set(std::string_view name) noexcept {
  for (const point_set_entry& e : entries) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

std::string point_set_names() {
  std::vector<std::string_view> names;
  for (const point_set_entry& e : entries) names.push_back(e.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

std::string_view to_string(randomization r) noexcept {
  return name_of(r);
}

std::string_view to_string(strata_kind k) noexcept {
  return k == strata_kind::cells ? "cells" : "rows_and_columns";
}

std::vector<std::string_view> point_set_option::point_choices() const {
  std::vector<std::string_view> out;
  for (const std::string_view c : choices) {
    if (std::find(weighted_choices.begin(), weighted_choices.end(), c) == weighted_choices.end()) {
      out.push_back(c);
    }
  }
  return out;
}

const point_set_option* point_set_entry::option(std::string_view key) const noexcept {
  for (const point_set_option& o : options) {
    if (o.key == key) return &o;
  }
  return nullptr;
}

point_set_options checked_options(const point_set_entry& set, std::span<const named_option> given,
                                  std::string (*parameter)(std::string_view key)) {
  for (const named_option& g : given) {
    if (set.option(g.key) != nullptr) continue;
    std::vector<std::string_view> owners;
    for (const point_set_entry& other : point_set_catalogue()) {
      if (other.option(g.key) != nullptr) owners.push_back(other.name);
    }
    throw invalid_argument(
        parameter(g.key), g.value,
        fmt::format("no {} for {} ({} only)", g.key, set.name, fmt::join(owners, ", ")));
  }
  // Values in the set's own order, so that of two bad ones the first of its table is named.
  std::vector<std::string_view> values(set.options.size());
  for (std::size_t i = 0; i < set.options.size(); ++i) {
    const point_set_option& o = set.options[i];
    const auto g = std::find_if(given.begin(), given.end(),
                                [&](const named_option& n) { return n.key == o.key; });
    if (g == given.end() || g->value.empty()) continue;
    const auto chosen = [&](std::span<const std::string_view> among) {
      return std::find(among.begin(), among.end(), g->value) != among.end();
    };
    const std::vector<std::string_view> plain = o.point_choices();
    if (!o.is_flag() && chosen(o.weighted_choices)) {
      throw invalid_argument(
          parameter(o.key), g->value,
          fmt::format("one of {} for {}'s points: {} is a change of variables that weights each "
                      "point by ∏φ'(x_j), not a set of equal-weight points, so only the "
                      "{} method's sample mean takes it",
                      fmt::join(plain, ", "), set.name, g->value, set.name));
    }
    if (!o.is_flag() && !chosen(o.choices)) {
      throw invalid_argument(parameter(o.key), g->value,
                             fmt::format("one of {} for {}", fmt::join(plain, ", "), set.name));
    }
    values[i] = g->value;
  }
  const point_set_options options = set.options_of(values);
  if (const std::string problem = interlacing_problem(set, options); !problem.empty()) {
    throw invalid_argument(parameter("randomization"), to_string(*set.randomization_of(options)),
                           problem);
  }
  return options;
}

std::optional<randomization> parse_randomization(std::string_view name) noexcept {
  for (const randomization r :
       {randomization::none, randomization::shift, randomization::lms_shift, randomization::owen,
        randomization::fast_owen, randomization::permutation}) {
    if (to_string(r) == name) return r;
  }
  return std::nullopt;
}

std::string_view to_string(periodization p) noexcept {
  const auto i = static_cast<std::size_t>(p);
  return i < periodization_names.size() ? periodization_names[i] : "?";
}

std::optional<randomization> point_set_entry::randomization_of(
    const point_set_options& options) const noexcept {
  if (randomizations.empty()) return std::nullopt;
  return options.random.value_or(randomizations.front());
}

bool point_set_entry::has(randomization r) const noexcept {
  return std::find(randomizations.begin(), randomizations.end(), r) != randomizations.end();
}

point_count point_set_entry::counts_with(const point_set_options& options) const noexcept {
  // Sobol': the first N points of the sequence are a valid (if poorer) point set for any N when
  // asked for, and the unrandomized sequence is a deterministic prefix for any N. A lattice of
  // another N would need another generating vector.
  if (counts == point_count::power_of_two && takes_any_prefix &&
      (options.allow_any_n || randomization_of(options) == randomization::none)) {
    return point_count::any;
  }
  return counts;
}

error_source point_set_entry::errors_with(const point_set_options& options) const noexcept {
  if (randomization_of(options) == randomization::none) return error_source::none;
  return errors;
}

std::uint64_t max_point_count(const point_set_entry& set, const point_set_options& options) {
  if (set.max_points == 0) return std::uint64_t{1} << 62;
  // Dropping the first point spends one index of the range.
  return set.max_points - (options.drop_first_point ? 1 : 0);
}

bool accepts_size(const point_set_entry& set, std::size_t s, std::uint64_t n,
                  const point_set_options& options) {
  return s != 0 && n != 0 && size_problem(set, s, n, options).empty();
}

std::string interlacing_problem(const point_set_entry& set, const point_set_options& options) {
  if (options.interlacing <= 1) return {};
  const auto r = set.randomization_of(options);
  if (!r || std::find(interlaced_randomizations.begin(), interlaced_randomizations.end(), *r) !=
                interlaced_randomizations.end()) {
    return {};
  }
  return fmt::format(
      "owen, shift or none with interlacing = {} ({} has no proven rate for an interlaced net: "
      "docs/theory.md#interlaced-nets)",
      options.interlacing, to_string(*r));
}

std::string dimension_problem(const point_set_entry& set, std::size_t s,
                              const point_set_options& options) {
  if (set.max_dimension == 0) return {};
  // An interlaced set draws α·s dimensions from the tables (sampling/interlaced_sobol_points.hpp).
  if (options.interlacing > 1 && s > set.max_dimension / options.interlacing) {
    return fmt::format(
        "α·s ≤ {} for the {} points with interlacing α = {}, got s = {} (α·s = {}): s ≤ {}",
        set.max_dimension, set.name, options.interlacing, s, s * options.interlacing,
        set.max_dimension / options.interlacing);
  }
  if (s > set.max_dimension) {
    return fmt::format("s ≤ {} for the {} points, got s = {}", set.max_dimension, set.name, s);
  }
  return {};
}

std::string size_problem(const point_set_entry& set, std::size_t s, std::uint64_t n,
                         const point_set_options& options) {
  if (s == 0) return "a dimension s ≥ 1";
  if (n == 0) return "N ≥ 1";
  if (std::string problem = dimension_problem(set, s, options); !problem.empty()) return problem;
  if (n > (std::uint64_t{1} << 62) / s) {
    return "N·s < 2^62 (the counter space of one random stream)";
  }
  const std::uint64_t most = max_point_count(set, options);
  if (n > most) return fmt::format("N ≤ {} for the {} points", most, set.name);
  switch (set.counts_with(options)) {
    case point_count::perfect_power:
      if (!stratum_grid::is_valid_size(s, n)) return "N = k^s (one point per stratum)";
      break;
    case point_count::power_of_two:
      if (!std::has_single_bit(n)) {
        const std::uint64_t below = std::bit_floor(n);
        const std::uint64_t above = below << 1;
        const auto r = set.randomization_of(options);
        return fmt::format(
            "a power of two: {} {}needs N = 2^m, nearest valid sizes {} and {}{}", set.name,
            r ? fmt::format("with randomization '{}' ", to_string(*r)) : std::string(), below,
            above <= most ? fmt::format("{}", above) : std::string("(none larger)"),
            set.takes_any_prefix ? " (allow_any_n = true takes N as it is, losing the net)" : "");
      }
      break;
    case point_count::perfect_square:
      if (!padded_jittered_points::is_valid_size(s, n)) {
        const std::uint64_t k = integer_root(n, 2);
        return fmt::format(
            "N = k² in s ≥ 2 (k × k strata per pair of dimensions), nearest valid "
            "sizes {} and {}",
            k * k, (k + 1) * (k + 1));
      }
      break;
    case point_count::near_square:
      if (!cmj_points::is_valid_size(s, n)) {
        const std::uint64_t k = integer_root(n, 2);
        return fmt::format(
            "N = k² or k(k + 1) in s ≥ 2 (an m × n grid per pair of dimensions, n = m or m + 1), "
            "nearest valid sizes {} and {}",
            k * (k + 1) <= n ? k * (k + 1) : k * k,
            k * (k + 1) > n ? k * (k + 1) : (k + 1) * (k + 1));
      }
      break;
    case point_count::any:
      break;
  }
  return {};
}

}  // namespace quadmc
