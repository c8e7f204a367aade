// The point-set table of point_set_catalogue.hpp: each entry's estimators are instantiated here,
// once per set, by point_set_entry_for<P>.
#include "quadmc/estimators/point_set_catalogue.hpp"

#include "quadmc/core/batching.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/integer_powers.hpp"
#include "quadmc/estimators/importance_sampling.hpp"
#include "quadmc/estimators/irradiance_estimators.hpp"
#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/sampling/halton_points.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/inversion_warps.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/latin_hypercube_points.hpp"
#include "quadmc/sampling/padded_jittered_points.hpp"
#include "quadmc/sampling/rank1_lattice_points.hpp"
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
    return fn(P(s, n, st.seed, st.stream));
  }
};

constexpr std::array<randomization, 5> sobol_randomizations{
    randomization::owen, randomization::fast_owen, randomization::lms_shift, randomization::shift,
    randomization::none};
constexpr std::array<randomization, 3> halton_randomizations{
    randomization::owen, randomization::permutation, randomization::none};
constexpr std::array<randomization, 2> lattice_randomizations{randomization::shift,
                                                              randomization::none};

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
  const std::string problem = size_problem(set, s, n, options);
  if (!problem.empty()) throw invalid_argument("number of points N", std::to_string(n), problem);
}

struct sobol_set {
  template <class Fn>
  static decltype(auto) visit(std::size_t s, std::uint64_t n, const point_set_options& o,
                              const sample_stream& st, Fn&& fn) {
    const point_set_entry& set = entry_named("sobol");
    require_qmc_request(set, s, n, o);
    const bool drop = o.drop_first_point;
    switch (*set.randomization_of(o)) {
      case randomization::owen:
        return fn(sobol_points<owen_scramble>(s, n, st.seed, st.stream, drop));
      case randomization::fast_owen:
        return fn(sobol_points<fast_owen_scramble>(s, n, st.seed, st.stream, drop));
      case randomization::lms_shift:
        return fn(sobol_points<linear_matrix_scramble>(s, n, st.seed, st.stream, drop));
      case randomization::shift:
        return fn(sobol_points<digital_shift>(s, n, st.seed, st.stream, drop));
      default:
        return fn(sobol_points<unrandomized_digits>(s, n, st.seed, st.stream, drop));
    }
  }
};

struct halton_set {
  template <class Fn>
  static decltype(auto) visit(std::size_t s, std::uint64_t n, const point_set_options& o,
                              const sample_stream& st, Fn&& fn) {
    const point_set_entry& set = entry_named("halton");
    require_qmc_request(set, s, n, o);
    switch (*set.randomization_of(o)) {
      case randomization::owen:
        return fn(halton_points<nested_digit_scramble>(s, n, st.seed, st.stream));
      case randomization::permutation:
        return fn(halton_points<random_digit_permutation>(s, n, st.seed, st.stream));
      default:
        return fn(halton_points<unrandomized_radical_inverse>(s, n, st.seed, st.stream));
    }
  }
};

struct lattice_set {
  template <class Fn>
  static decltype(auto) visit(std::size_t s, std::uint64_t n, const point_set_options& o,
                              const sample_stream& st, Fn&& fn) {
    const point_set_entry& set = entry_named("lattice");
    require_qmc_request(set, s, n, o);
    const bool shifted = *set.randomization_of(o) == randomization::shift;
    if (o.periodic == periodization::baker) {
      return fn(rank1_lattice_points<baker_transform>(s, n, st.seed, st.stream, shifted));
    }
    return fn(rank1_lattice_points<no_periodization>(s, n, st.seed, st.stream, shifted));
  }
};

template <class Set>
estimate monte_carlo_over(const any_integrand& f, const point_set_options& options,
                          const sample_stream& stream, std::uint64_t n, unsigned threads) {
  return Set::visit(f.dimension(), n, options, stream,
                    [&](const auto& points) { return monte_carlo(f, points, threads); });
}

template <class Set>
estimate importance_over(const any_integrand& f, const unit_warp& warp,
                         const point_set_options& options, const sample_stream& stream,
                         std::uint64_t n, unsigned threads) {
  require(f.dimension() == 1, "integrand dimension", f.dimension(),
          "1 (importance sampling with a 1D warp)");
  const box& domain = f.info().domain;
  const double a = domain.lower[0];
  const double b = domain.upper[0];
  require(std::isfinite(a) && std::isfinite(b) && b > a, "integrand interval upper", b,
          "a finite interval with b > a");
  return Set::visit(1, n, options, stream, [&](const auto& points) {
    switch (warp.kind) {
      case unit_warp_kind::power:
        return importance_sampling(f, interval_warp(power_warp(warp.parameter), a, b), points,
                                   threads);
      case unit_warp_kind::truncated_exponential:
        return importance_sampling(
            f, interval_warp(truncated_exponential_warp(warp.parameter), a, b), points, threads);
    }
    throw invalid_argument("warp kind", std::to_string(static_cast<int>(warp.kind)),
                           "power or truncated_exponential");
  });
}

template <class Set>
estimate irradiance_over(irradiance_sampling technique, const irradiance_setup& setup,
                         const point_set_options& options, const sample_stream& stream,
                         std::uint64_t n, unsigned threads) {
  return Set::visit(2, n, options, stream, [&](const auto& points) {
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

template <class Set>
constexpr point_set_entry point_set_entry_for(std::string_view name, std::string_view description,
                                              point_count counts,
                                              std::span<const randomization> randomizations = {},
                                              std::size_t max_dimension = 0,
                                              error_source errors = error_source::own) {
  return {name,
          description,
          counts,
          randomizations,
          max_dimension,
          errors,
          monte_carlo_over<Set>,
          importance_over<Set>,
          irradiance_over<Set>,
          points_over<Set>};
}

constexpr std::array<point_set_entry, 8> entries{{
    point_set_entry_for<plain_set<independent_points>>("independent", "independent uniform points",
                                                       point_count::any),
    point_set_entry_for<plain_set<jittered_points>>(
        "jittered", "one random point per cell of a k^s grid", point_count::perfect_power),
    point_set_entry_for<plain_set<unjittered_points>>(
        "unjittered", "cell centres of a randomly shifted k^s grid", point_count::perfect_power),
    point_set_entry_for<plain_set<padded_jittered_points>>(
        "padded_jittered", "k x k jittered strata padded across dimension pairs",
        point_count::perfect_square),
    point_set_entry_for<plain_set<latin_hypercube_points>>("latin_hypercube", "Latin hypercube",
                                                           point_count::any),
    point_set_entry_for<sobol_set>(
        "sobol", "Sobol' points (Joe-Kuo directions), Gray-code order, N = 2^m when randomized",
        point_count::power_of_two, sobol_randomizations, sobol_matrices::max_dimension,
        error_source::replicates),
    point_set_entry_for<halton_set>("halton", "Halton points in the first s prime bases",
                                    point_count::any, halton_randomizations, max_halton_dimension,
                                    error_source::replicates),
    point_set_entry_for<lattice_set>(
        "lattice", "rank-1 lattice (Cools-Kuo-Nuyens vector), N = 2^m <= 2^20, random shift",
        point_count::power_of_two, lattice_randomizations, max_lattice_dimension,
        error_source::replicates),
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
    case point_count::power_of_two:
      return {0, N == 0 ? 0 : std::bit_floor(N)};
    case point_count::any:
      break;
  }
  return {0, N};
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

std::optional<randomization> parse_randomization(std::string_view name) noexcept {
  for (const randomization r :
       {randomization::none, randomization::shift, randomization::lms_shift, randomization::owen,
        randomization::fast_owen, randomization::permutation}) {
    if (to_string(r) == name) return r;
  }
  return std::nullopt;
}

std::string_view to_string(periodization p) noexcept {
  return p == periodization::baker ? "baker" : "none";
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
  if (counts == point_count::power_of_two && name == "sobol" &&
      (options.allow_any_n || randomization_of(options) == randomization::none)) {
    return point_count::any;
  }
  return counts;
}

error_source point_set_entry::errors_with(const point_set_options& options) const noexcept {
  if (randomization_of(options) == randomization::none) return error_source::own;
  return errors;
}

std::uint64_t max_point_count(const point_set_entry& set, const point_set_options& options) {
  if (set.name == "sobol") {
    return (std::uint64_t{1} << 32) - (options.drop_first_point ? 1 : 0);
  }
  if (set.name == "lattice") return max_lattice_points;
  return std::uint64_t{1} << 62;
}

bool accepts_size(const point_set_entry& set, std::size_t s, std::uint64_t n,
                  const point_set_options& options) {
  return s != 0 && n != 0 && size_problem(set, s, n, options).empty();
}

std::string dimension_problem(const point_set_entry& set, std::size_t s) {
  if (set.max_dimension != 0 && s > set.max_dimension) {
    return fmt::format("s ≤ {} for the {} points, got s = {}", set.max_dimension, set.name, s);
  }
  return {};
}

std::string size_problem(const point_set_entry& set, std::size_t s, std::uint64_t n,
                         const point_set_options& options) {
  if (s == 0) return "a dimension s ≥ 1";
  if (n == 0) return "N ≥ 1";
  if (std::string problem = dimension_problem(set, s); !problem.empty()) return problem;
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
            set.name == "sobol" ? " (allow_any_n = true takes N as it is, losing the net)" : "");
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
    case point_count::any:
      break;
  }
  return {};
}

}  // namespace quadmc
