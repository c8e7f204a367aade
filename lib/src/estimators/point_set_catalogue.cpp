// The point-set table of point_set_catalogue.hpp: each entry's estimators are instantiated here,
// once per set, by point_set_entry_for<P>.
#include "quadmc/estimators/point_set_catalogue.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/integer_powers.hpp"
#include "quadmc/estimators/importance_sampling.hpp"
#include "quadmc/estimators/irradiance_estimators.hpp"
#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/inversion_warps.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/latin_hypercube_points.hpp"
#include "quadmc/sampling/padded_jittered_points.hpp"
#include "quadmc/sampling/stratum_grid.hpp"
#include "quadmc/sampling/unjittered_points.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
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

template <class P>
estimate monte_carlo_over(const any_integrand& f, const sample_stream& stream, std::uint64_t n,
                          unsigned threads) {
  return monte_carlo(f, P(f.dimension(), n, stream.seed, stream.stream), threads);
}

template <class P>
estimate importance_over(const any_integrand& f, const unit_warp& warp, const sample_stream& stream,
                         std::uint64_t n, unsigned threads) {
  require(f.dimension() == 1, "integrand dimension", f.dimension(),
          "1 (importance sampling with a 1D warp)");
  const box& domain = f.info().domain;
  const double a = domain.lower[0];
  const double b = domain.upper[0];
  require(std::isfinite(a) && std::isfinite(b) && b > a, "integrand interval upper", b,
          "a finite interval with b > a");
  const P points(1, n, stream.seed, stream.stream);
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

template <class P>
estimate irradiance_over(irradiance_sampling technique, const irradiance_setup& setup,
                         const sample_stream& stream, std::uint64_t n, unsigned threads) {
  const P points(2, n, stream.seed, stream.stream);
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

template <class P>
constexpr point_set_entry point_set_entry_for(std::string_view name, std::string_view description,
                                              point_count counts) {
  return {name, description, counts, monte_carlo_over<P>, importance_over<P>, irradiance_over<P>};
}

constexpr std::array<point_set_entry, 5> entries{{
    point_set_entry_for<independent_points>("independent", "independent uniform points",
                                            point_count::any),
    point_set_entry_for<jittered_points>("jittered", "one random point per cell of a k^s grid",
                                         point_count::perfect_power),
    point_set_entry_for<unjittered_points>(
        "unjittered", "cell centres of a randomly shifted k^s grid", point_count::perfect_power),
    point_set_entry_for<padded_jittered_points>(
        "padded_jittered", "k x k jittered strata padded across dimension pairs",
        point_count::perfect_square),
    point_set_entry_for<latin_hypercube_points>("latin_hypercube", "Latin hypercube",
                                                point_count::any),
}};

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

bool accepts_size(const point_set_entry& set, std::size_t s, std::uint64_t n) {
  if (s == 0 || n == 0) return false;
  switch (set.counts) {
    case point_count::perfect_power:
      return stratum_grid::is_valid_size(s, n);
    case point_count::perfect_square:
    case point_count::any:
      break;
  }
  return n <= (std::uint64_t{1} << 62) / s;
}

}  // namespace quadmc
