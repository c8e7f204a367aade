// The method-by-name entry points of sampling_method.hpp: one switch per call, templates below.
#include "quadmc/estimators/sampling_method.hpp"

#include "quadmc/core/errors.hpp"
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

#include <array>
#include <string>
#include <utility>

namespace quadmc {

namespace {

constexpr std::array<std::pair<std::string_view, point_set_kind>, 6> names{{
    {"independent", point_set_kind::independent},
    {"plain", point_set_kind::independent},
    {"jittered", point_set_kind::jittered},
    {"unjittered", point_set_kind::unjittered},
    {"padded_jittered", point_set_kind::padded_jittered},
    {"latin_hypercube", point_set_kind::latin_hypercube},
}};

// Builds the named point set and hands it to `run` (a generic lambda): the one run-time dispatch.
template <class Run>
estimate with_point_set(point_set_kind kind, std::size_t s, std::uint64_t n, std::uint64_t seed,
                        std::uint64_t stream, Run&& run) {
  switch (kind) {
    case point_set_kind::independent:
      return run(independent_points(s, n, seed, stream));
    case point_set_kind::jittered:
      return run(jittered_points(s, n, seed, stream));
    case point_set_kind::unjittered:
      return run(unjittered_points(s, n, seed, stream));
    case point_set_kind::padded_jittered:
      return run(padded_jittered_points(s, n, seed, stream));
    case point_set_kind::latin_hypercube:
      return run(latin_hypercube_points(s, n, seed, stream));
  }
  throw invalid_argument("point set kind", std::to_string(static_cast<int>(kind)),
                         "one of the point_set_kind values");
}

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

}  // namespace

std::string_view to_string(point_set_kind kind) noexcept {
  switch (kind) {
    case point_set_kind::independent:
      return "independent";
    case point_set_kind::jittered:
      return "jittered";
    case point_set_kind::unjittered:
      return "unjittered";
    case point_set_kind::padded_jittered:
      return "padded_jittered";
    case point_set_kind::latin_hypercube:
      return "latin_hypercube";
  }
  return "?";
}

point_set_kind parse_point_set_kind(std::string_view name) {
  for (const auto& [n, kind] : names) {
    if (n == name) return kind;
  }
  throw invalid_argument("point set", std::string(name),
                         "one of independent (or plain), jittered, unjittered, padded_jittered, "
                         "latin_hypercube");
}

bool accepts_size(point_set_kind kind, std::size_t s, std::uint64_t n) {
  if (s == 0 || n == 0) return false;
  switch (kind) {
    case point_set_kind::jittered:
    case point_set_kind::unjittered:
      return stratum_grid::is_valid_size(s, n);
    default:
      return n <= (std::uint64_t{1} << 62) / s;
  }
}

estimate run_monte_carlo(point_set_kind kind, const any_integrand& f, std::uint64_t seed,
                         std::uint64_t stream, std::uint64_t n, unsigned threads) {
  return with_point_set(kind, f.dimension(), n, seed, stream,
                        [&](const auto& points) { return monte_carlo(f, points, threads); });
}

estimate run_importance(point_set_kind kind, const any_integrand& f, unit_warp_kind warp,
                        double parameter, std::uint64_t seed, std::uint64_t stream, std::uint64_t n,
                        unsigned threads) {
  require(f.dimension() == 1, "integrand dimension", f.dimension(),
          "1 (importance sampling by name uses a 1D warp)");
  const box& domain = f.info().domain;
  const double a = domain.lower[0];
  const double b = domain.upper[0];
  require(std::isfinite(a) && std::isfinite(b) && b > a, "integrand interval upper", b,
          "a finite interval with b > a");
  return with_point_set(kind, 1, n, seed, stream, [&](const auto& points) {
    switch (warp) {
      case unit_warp_kind::power:
        return importance_sampling(f, interval_warp(power_warp(parameter), a, b), points, threads);
      case unit_warp_kind::truncated_exponential:
        return importance_sampling(f, interval_warp(truncated_exponential_warp(parameter), a, b),
                                   points, threads);
    }
    throw invalid_argument("warp kind", std::to_string(static_cast<int>(warp)),
                           "power or truncated_exponential");
  });
}

estimate run_irradiance(irradiance_sampling technique, point_set_kind kind,
                        const irradiance_setup& setup, std::uint64_t seed, std::uint64_t stream,
                        std::uint64_t n, unsigned threads) {
  return with_point_set(kind, 2, n, seed, stream, [&](const auto& points) {
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

}  // namespace quadmc
