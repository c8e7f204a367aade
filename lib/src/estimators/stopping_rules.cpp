// The stopping rules of estimators/stopping_rules.hpp (docs/theory.md#stopping-rules).
#include "quadmc/estimators/stopping_rules.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/normal_quantile.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/estimators/replicate_estimator.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <boost/math/special_functions/cos_pi.hpp>
#include <boost/math/special_functions/sin_pi.hpp>
#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <numeric>
#include <string>
#include <utility>

namespace quadmc {

namespace {

void require_power_of_two(std::uint64_t n, const char* name, const std::string& expected) {
  require(std::has_single_bit(n), name, n, expected);
}

}  // namespace

stopped_estimate replicate_stopping(extension_values values, const replicate_stopping_options& o) {
  require(o.tolerance > 0.0, "tolerance", o.tolerance, "a tolerance > 0");
  require(o.replications >= 2, "replications", o.replications,
          "at least 2 randomizations (their spread is the error estimate)");
  require_power_of_two(o.n_init, "n_init", "a power of two (the nets need N = 2^m)");
  require(std::has_single_bit(o.n_max) && o.n_max >= o.n_init, "n_max", o.n_max,
          "a power of two ≥ n_init = " + std::to_string(o.n_init));
  require(o.alpha > 0.0 && o.alpha < 1.0, "alpha", o.alpha, "an uncertainty in (0, 1)");
  require(o.inflate >= 1.0, "inflate", o.inflate, "an inflation factor ≥ 1");

  const std::size_t R = o.replications;
  const boost::math::students_t t_law(static_cast<double>(R - 1));
  const double t = boost::math::quantile(boost::math::complement(t_law, o.alpha / 2.0));
  std::vector<neumaier_sum> sums(R);
  std::vector<double> means(R);
  std::vector<double> y;
  std::uint64_t lo = 0;
  std::uint64_t hi = o.n_init;
  for (;;) {
    // The points lo … hi − 1 of every replicate; their sums join the running ones (a block's
    // sum pairwise, the blocks with Neumaier: the rounding stays at the block level).
    y.resize(hi - lo);
    for (std::size_t r = 0; r < R; ++r) {
      values(r, lo, y);
      sums[r].add(pairwise_sum(y));
      means[r] = sums[r].value() / static_cast<double>(hi);
    }
    const auto [mean, sd] = replicate_mean_and_sd(means);
    const double half_width = t * o.inflate * sd / std::sqrt(static_cast<double>(R));
    stopped_estimate out{mean, half_width, hi * R, hi, half_width <= o.tolerance};
    if (out.met || hi * 2 > o.n_max) return out;
    lo = hi;
    hi *= 2;
  }
}

// --- the guaranteed rules ---------------------------------------------------------------------

void walsh_butterflies(std::span<double> y, unsigned from_level, unsigned to_level) noexcept {
  const std::size_t n = y.size();
  for (unsigned l = from_level; l < to_level; ++l) {
    const std::size_t nl = std::size_t{1} << l;
    for (std::size_t b = 0; b < n; b += 2 * nl) {
      for (std::size_t k = 0; k < nl; ++k) {
        const double even = y[b + k];
        const double odd = y[b + k + nl];
        y[b + k] = (even + odd) / 2.0;
        y[b + k + nl] = (even - odd) / 2.0;
      }
    }
  }
}

void fourier_butterflies(std::span<std::complex<double>> y, unsigned from_level,
                         unsigned to_level) noexcept {
  if (from_level >= to_level) return;
  const std::size_t n = y.size();
  // w_k = exp(−iπk/nl) of level l is the top level's twiddle k·2^(top − l): one table of
  // 2^(to_level − 1) values serves every level. k/top is an exact dyadic fraction in [0, 1), so
  // cos and sin of π·(k/top) are within an ulp or two (no large-argument reduction).
  const std::size_t top = std::size_t{1} << (to_level - 1);
  std::vector<std::complex<double>> twiddle(top);
  for (std::size_t k = 0; k < top; ++k) {
    const double a = std::numbers::pi * (static_cast<double>(k) / static_cast<double>(top));
    twiddle[k] = {std::cos(a), -std::sin(a)};
  }
  for (unsigned l = from_level; l < to_level; ++l) {
    const std::size_t nl = std::size_t{1} << l;
    const std::size_t stride = top / nl;
    for (std::size_t b = 0; b < n; b += 2 * nl) {
      for (std::size_t k = 0; k < nl; ++k) {
        const std::complex<double> w = twiddle[k * stride];
        const std::complex<double> v = y[b + k + nl];
        // The product written out: std::complex's operator* checks for NaN and infinities
        // (Annex G), a library call per butterfly that the values here never need.
        const std::complex<double> odd{w.real() * v.real() - w.imag() * v.imag(),
                                       w.real() * v.imag() + w.imag() * v.real()};
        const std::complex<double> even = y[b + k];
        y[b + k] = (even + odd) / 2.0;
        y[b + k + nl] = (even - odd) / 2.0;
      }
    }
  }
}

coefficient_map::coefficient_map(unsigned m, function_ref<double(std::uint64_t)> magnitude)
    : kappa_(std::size_t{1} << m), m_(m) {
  std::iota(kappa_.begin(), kappa_.end(), std::uint64_t{0});
  for (unsigned l = m; l-- > 1;) sort_level(l, magnitude);
}

void coefficient_map::extend(unsigned r_lag, function_ref<double(std::uint64_t)> magnitude) {
  const std::size_t n = kappa_.size();
  kappa_.resize(2 * n);
  for (std::size_t i = 0; i < n; ++i) kappa_[n + i] = kappa_[i] + n;
  ++m_;
  const unsigned lowest = m_ > r_lag ? m_ - r_lag : 1;
  for (unsigned l = m_; l-- > std::max(lowest, 1U);) sort_level(l, magnitude);
}

// Level l: of the classes k and k + 2^l (1 ≤ k < 2^l), the one whose coefficient is larger in
// the first block takes the lower class, and every block of 2^(l+1) swaps alike, so that the
// map stays a refinement of the wavenumbers' alias classes ([Hickernell & Jiménez Rugama 2016,
// §3]; docs/theory.md#stopping-rules).
void coefficient_map::sort_level(unsigned l, function_ref<double(std::uint64_t)> magnitude) {
  const std::size_t nl = std::size_t{1} << l;
  const std::size_t n = kappa_.size();
  for (std::size_t k = 1; k < nl; ++k) {
    if (magnitude(kappa_[k + nl]) > magnitude(kappa_[k])) {
      for (std::size_t b = 0; b < n; b += 2 * nl) std::swap(kappa_[b + k], kappa_[b + k + nl]);
    }
  }
}

namespace {

void check_guaranteed(const guaranteed_qmc_options& o) {
  require(o.tolerance > 0.0, "tolerance", o.tolerance, "a tolerance > 0");
  require(o.r_lag >= 1 && o.r_lag <= 20, "r_lag", o.r_lag, "an integer in [1, 20]");
  require(std::has_single_bit(o.n_init) && o.n_init >= (std::uint64_t{2} << o.r_lag), "n_init",
          o.n_init,
          "a power of two ≥ 2^(r_lag + 1) = " + std::to_string(std::uint64_t{2} << o.r_lag) +
              " (S̃ sums the coefficients 2^(m − r_lag − 1) … 2^(m − r_lag) − 1)");
  require(std::has_single_bit(o.n_max) && o.n_max >= o.n_init, "n_max", o.n_max,
          "a power of two ≥ n_init = " + std::to_string(o.n_init));
  require(o.fudge > 0.0 && std::isfinite(o.fudge), "fudge", o.fudge, "a finite constant > 0");
}

// The rule of both guaranteed algorithms, over the coefficients `Coefficient` (real Walsh or
// complex Fourier) that `butterflies` computes.
template <class Coefficient, class Butterflies>
stopped_estimate guaranteed_qmc(extension_values values, const guaranteed_qmc_options& o,
                                Butterflies butterflies) {
  check_guaranteed(o);
  unsigned m = static_cast<unsigned>(std::countr_zero(o.n_init));
  std::vector<double> fresh(o.n_init);
  values(0, 0, fresh);
  std::vector<Coefficient> y(fresh.begin(), fresh.end());
  butterflies(std::span<Coefficient>(y), 0, m);
  const auto magnitude = [&y](std::uint64_t i) { return std::abs(y[i]); };
  coefficient_map map(m, function_ref<double(std::uint64_t)>(magnitude));
  for (;;) {
    const std::uint64_t n = std::uint64_t{1} << m;
    // S̃(m): the coefficients of classes 2^(m−r−1) … 2^(m−r) − 1, the error bound C·2^−m·S̃(m)
    // ([Hickernell & Jiménez Rugama 2016, Thm 3] with GAIL's fudge function).
    const std::uint64_t start = n >> (o.r_lag + 1);
    double stilde = 0.0;
    for (std::uint64_t k = start; k < 2 * start; ++k) stilde += magnitude(map.kappa()[k]);
    const double bound = o.fudge * std::ldexp(stilde, -static_cast<int>(m));
    stopped_estimate out{std::real(y[0]), bound, n, n, bound <= o.tolerance};
    if (out.met || 2 * n > o.n_max) return out;
    // Double: transform the new half alone, then one butterfly level across the halves.
    fresh.resize(n);
    values(0, n, fresh);
    y.resize(2 * n);
    std::copy(fresh.begin(), fresh.end(), y.begin() + static_cast<std::ptrdiff_t>(n));
    butterflies(std::span<Coefficient>(y).subspan(n), 0, m);
    butterflies(std::span<Coefficient>(y), m, m + 1);
    ++m;
    map.extend(o.r_lag, function_ref<double(std::uint64_t)>(magnitude));
  }
}

}  // namespace

stopped_estimate guaranteed_digital(extension_values values, const guaranteed_qmc_options& o) {
  return guaranteed_qmc<double>(values, o, walsh_butterflies);
}

stopped_estimate guaranteed_lattice(extension_values values, const guaranteed_qmc_options& o) {
  return guaranteed_qmc<std::complex<double>>(values, o, fourier_butterflies);
}

// --- the two-stage Monte Carlo rules ----------------------------------------------------------

namespace {

void check_two_stage(const two_stage_options& o) {
  require(o.tolerance > 0.0, "tolerance", o.tolerance, "a tolerance > 0");
  require(o.n_init >= 2, "n_init", o.n_init, "at least 2 pilot points (σ̂ needs two)");
  require(o.n_max >= 2 * o.n_init, "n_max", o.n_max,
          "at least 2·n_init = " + std::to_string(2 * o.n_init) + " (a pilot and a final sample)");
  require(o.alpha > 0.0 && o.alpha < 1.0, "alpha", o.alpha, "an uncertainty in (0, 1)");
  require(o.inflate >= 1.0, "inflate", o.inflate, "an inflation factor ≥ 1");
}

// σ̂ of one value from the pilot: its standard error times √n (σ̂/√n for independent points;
// the set's own, smaller, estimate for stratified ones).
double pilot_sigma(const stage_estimate& pilot) {
  return pilot.std_error * std::sqrt(static_cast<double>(pilot.evaluations));
}

// The final sample's size: n, or what the budget leaves after the pilot.
std::uint64_t final_size(double n, std::uint64_t spent, std::uint64_t n_max, bool& capped) {
  const auto left = static_cast<double>(n_max - std::min(spent, n_max));
  capped = !(n <= left);  // NaN (σ̂ NaN) caps too
  return capped ? n_max - std::min(spent, n_max) : static_cast<std::uint64_t>(n);
}

}  // namespace

stopped_estimate clt_stopping(stage_run run, const two_stage_options& o) {
  check_two_stage(o);
  const stage_estimate pilot = run(0, o.n_init);
  const double sigma = pilot_sigma(pilot);
  const double z = normal_quantile(1.0 - o.alpha / 2.0);
  const double wanted = std::max(static_cast<double>(o.n_init),
                                 std::ceil(std::pow(z * o.inflate * sigma / o.tolerance, 2)));
  bool capped = false;
  const std::uint64_t n = final_size(wanted, pilot.evaluations, o.n_max, capped);
  if (n == 0) return {pilot.value, NAN, pilot.evaluations, pilot.evaluations, false};
  const stage_estimate last = run(1, n);
  const double claim = z * o.inflate * sigma / std::sqrt(static_cast<double>(last.evaluations));
  return {last.value, claim, pilot.evaluations + last.evaluations, last.evaluations,
          !capped && claim <= o.tolerance};
}

berry_esseen_size berry_esseen_sample_size(double toloversig, double alpha, double kurtosis_max,
                                           double n_budget) {
  // The constants of the Berry–Esseen inequality and Jensen's bound on the third moment, as
  // [Hickernell, Jiang, Liu & Owen 2013, §3] use them (meanMC_g).
  constexpr double A = 18.1139;
  constexpr double A1 = 0.3328;
  constexpr double A2 = 0.429;
  const double m3 = std::pow(kurtosis_max, 0.75);
  // P(|error| > ε) ≤ Φ(−√n·ε/σ) + (Berry–Esseen term)/√n, with L = log √n and r = ε/σ.
  const auto tail = [&](double L, double r) {
    const double q = std::exp(L) * r;
    return 0.5 * std::erfc(q / std::sqrt(2.0)) +
           std::exp(-L) * std::min(A1 * (m3 + A2), A * m3 / (1.0 + q * q * q)) - alpha / 2.0;
  };
  const double n_chebyshev = std::ceil(1.0 / (alpha * toloversig * toloversig));
  // Both tails decrease in their argument from a positive value: bracket the root by doubling.
  const auto root = [](auto&& f, double lo, double step) {
    double hi = lo + step;
    while (f(hi) > 0.0) {
      lo = hi;
      step *= 2.0;
      hi = lo + step;
    }
    std::uintmax_t iterations = 200;
    const auto r = boost::math::tools::toms748_solve(
        f, lo, hi, boost::math::tools::eps_tolerance<double>(50), iterations);
    return (r.first + r.second) / 2.0;
  };
  const double L_clt = std::log(normal_quantile(1.0 - alpha / 2.0) / toloversig);
  const double L_be = root([&](double L) { return tail(L, toloversig); }, L_clt, 1.0);
  const double n_be = std::ceil(std::exp(2.0 * L_be));
  const double n = std::min({n_chebyshev, n_be, n_budget});
  const double L = std::log(std::sqrt(n));
  const double r = root([&](double x) { return tail(L, x); }, 0.0, toloversig);
  return {n, r};
}

stopped_estimate guaranteed_mc(stage_run run, const two_stage_options& o) {
  check_two_stage(o);
  // [Hickernell, Jiang, Liu & Owen 2013]: with probability 1 − α_σ the inflated pilot variance
  // bounds σ² for every f whose kurtosis is at most κ_max; the rest of α goes to the mean.
  const double alpha_sigma = o.alpha / 2.0;
  const auto n0 = static_cast<double>(o.n_init);
  const double kurtosis_max =
      (n0 - 3.0) / (n0 - 1.0) +
      alpha_sigma * n0 / (1.0 - alpha_sigma) * std::pow(1.0 - 1.0 / (o.inflate * o.inflate), 2);
  const stage_estimate pilot = run(0, o.n_init);
  const double sigma_up = o.inflate * pilot_sigma(pilot);
  const double alpha_mu = 1.0 - (1.0 - o.alpha) / (1.0 - alpha_sigma);
  if (!(sigma_up > 0.0)) {
    // Every pilot value equal (or σ̂ NaN): no sample size follows; the final sample repeats the
    // pilot's size and the claim is what the pilot saw, 0 (or NaN).
    const stage_estimate last = run(1, o.n_init);
    return {last.value, sigma_up == 0.0 ? 0.0 : NAN, pilot.evaluations + last.evaluations,
            last.evaluations, sigma_up == 0.0};
  }
  const berry_esseen_size size = berry_esseen_sample_size(
      o.tolerance / sigma_up, alpha_mu, kurtosis_max, static_cast<double>(o.n_max));
  bool capped = false;
  const std::uint64_t n = final_size(size.n, pilot.evaluations, o.n_max, capped);
  if (n == 0) return {pilot.value, NAN, pilot.evaluations, pilot.evaluations, false};
  const stage_estimate last = run(1, n);
  // The error the n really spent guarantees with probability 1 − α_μ: the smaller of
  // Chebyshev's σ_up/√(α_μ·n) and the Berry–Esseen one. Uncapped, n was chosen so that one of
  // them is ε.
  const auto spent = static_cast<double>(last.evaluations);
  const double chebyshev = sigma_up / std::sqrt(alpha_mu * spent);
  const double berry_esseen =
      berry_esseen_sample_size(o.tolerance / sigma_up, alpha_mu, kurtosis_max, spent)
          .error_over_sigma *
      sigma_up;
  const double claim = std::min(chebyshev, berry_esseen);
  return {last.value, capped ? claim : std::min(claim, o.tolerance),
          pilot.evaluations + last.evaluations, last.evaluations, !capped};
}

}  // namespace quadmc
