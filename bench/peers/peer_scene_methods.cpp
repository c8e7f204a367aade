// The peers as scene methods (peer_scene_methods.hpp). How each is called, so that the
// comparison is honest:
//  - every integrand call goes through a counting adapter, so a cell's evaluations are the calls
//    the library really made (its caps are soft: hcubature and pcubature stop after the round
//    that passes maxEval, so a budget cell may spend more than N, and the CSV says so);
//  - a non-finite value is caught in the adapter and rethrown after the library returns (an
//    exception must not unwind through cubature's or GSL's C frames), naming the point, as the
//    suite's own kernels do (functions/integrand.hpp, check_finite_batch);
//  - each reports its own error estimate (cubature's err, GSL's σ, Boost's error), so the
//    reliability table judges it like the suite's;
//  - all are single-threaded (none of these libraries has a parallel mode), so a seed gives the
//    same result for any --threads.
// cubature (hcubature_v, pcubature_v) takes whole batches in quadmc's layout, cut here into the
// batches of core/batching.hpp; GSL and Boost call the integrand point by point (their APIs have
// no batch form), which costs them one indirect call per point on top of their own.
#include "peer_scene_methods.hpp"

#include "python_peer_process.hpp"

#include "quadmc/analysis/theoretical_rate.hpp"
#include "quadmc/core/batching.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/functions/any_integrand.hpp"
#include "quadmc/functions/integrand.hpp"
#include "quadmc/methods/registry.hpp"
#include "quadmc/rules/genz_malik_rule.hpp"

#include <cubature.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_monte.h>
#include <gsl/gsl_monte_miser.h>
#include <gsl/gsl_monte_plain.h>
#include <gsl/gsl_monte_vegas.h>
#include <gsl/gsl_rng.h>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace quadmc::peers {
namespace {

// The integrand as the libraries see it: calls counted, the first failure kept for after the
// library returns.
struct counted_integrand {
  const any_integrand* f;
  std::string_view name;
  std::size_t s;
  std::uint64_t calls = 0;
  std::exception_ptr failure;

  void rethrow() const {
    if (failure) std::rethrow_exception(failure);
  }
  // One point (GSL, Boost); 0 after a failure, which is rethrown once the library returns.
  double at(const double* x) {
    ++calls;
    if (failure) return 0.0;
    double y = 0.0;
    try {
      const std::span<const double> xs(x, s);
      const std::span<double> ys(&y, 1);
      f->evaluate(xs, ys);
      check_finite_batch(name, xs, ys, s);
    } catch (...) {
      failure = std::current_exception();
      y = 0.0;
    }
    return y;
  }
};

counted_integrand counted(const method_cell& cell) {
  return counted_integrand{&cell.function, cell.function.info().name, cell.function.dimension(), 0,
                           nullptr};
}

// ---------------------------------------------------------------------------------------------
// cubature (Steven G. Johnson, libcubature-dev): hcubature = h-adaptive Genz–Malik (Gauss–Kronrod
// 7/15 in 1D), pcubature = p-adaptive tensor Clenshaw–Curtis.

int cubature_batch(unsigned ndim, std::size_t npt, const double* x, void* data, unsigned,
                   double* fval) {
  auto* c = static_cast<counted_integrand*>(data);
  try {
    for (std::size_t first = 0; first < npt; first += batch_points) {
      const std::size_t n = std::min(batch_points, npt - first);
      const std::span<const double> xs(x + first * ndim, n * ndim);
      const std::span<double> ys(fval + first, n);
      c->f->evaluate(xs, ys);
      c->calls += n;
      check_finite_batch(c->name, xs, ys, ndim);
    }
    return 0;
  } catch (...) {
    c->failure = std::current_exception();
    return 1;  // cubature stops and returns FAILURE
  }
}

enum class cubature_kind { h_adaptive, p_adaptive };

class cubature_method final : public method {
 public:
  cubature_method(const method_descriptor& d, cubature_kind kind) : method(d), kind_(kind) {}

  // The first round: one region (hcubature: 15 Gauss–Kronrod points in 1D, the Genz–Malik rule's
  // 2^s + 2s² + 2s + 1 above) or the first Clenshaw–Curtis grid (pcubature: 3 points per axis).
  sizing size_for(std::uint64_t N, std::size_t s) const override {
    if (s > max_dimension) {
      return {std::nullopt, fmt::format("{} is run up to s = {} here (s = {})", descriptor().name,
                                        max_dimension, s)};
    }
    const std::uint64_t first = first_round(s);
    if (N < first) {
      return {std::nullopt, fmt::format("N is below {}'s first round of {} evaluations",
                                        descriptor().name, first)};
    }
    return {cell_size{N, 0, 0, 0}, {}};
  }

  std::optional<std::string> incompatibility(const integrand_traits& f) const override {
    if (f.s > max_dimension) {
      return fmt::format("{} is run up to s = {} here (2^s points per region); s = {}",
                         descriptor().name, max_dimension, f.s);
    }
    return std::nullopt;
  }

  theoretical_rate theory(const integrand_class&) const override {
    if (kind_ == cubature_kind::h_adaptive) {
      return {std::nullopt, "h-adaptive (cubature's hcubature): no proven algebraic rate",
              "docs/theory.md#genz-malik; [Genz & Malik 1980]"};
    }
    return {std::nullopt,
            "p-adaptive Clenshaw-Curtis (cubature's pcubature): exponential on analytic f",
            "docs/theory.md#exponential-convergence; [Trefethen 2008]"};
  }

  repetition_result run(const method_cell& cell, const run_context&) const override {
    const box& domain = cell.function.info().domain;
    counted_integrand c = counted(cell);
    const double tolerance = cell.control == cell_control::tolerance ? cell.tolerance : 0.0;
    double value = 0.0, error = 0.0;
    const auto call = kind_ == cubature_kind::h_adaptive ? hcubature_v : pcubature_v;
    // maxEval = 0 would mean "no limit" to cubature; size_for keeps N ≥ the first round.
    const int status = call(1, &cubature_batch, &c, static_cast<unsigned>(c.s), domain.lower.data(),
                            domain.upper.data(), cell.size.evaluations, tolerance, 0.0,
                            ERROR_INDIVIDUAL, &value, &error);
    c.rethrow();
    if (status != 0) {
      throw std::runtime_error(fmt::format("{} returned {}", descriptor().name, status));
    }
    repetition_result out;
    out.value = value;
    out.evaluations = c.calls;
    out.error_estimate = error;
    return out;
  }

 private:
  static constexpr std::size_t max_dimension = 20;

  std::uint64_t first_round(std::size_t s) const {
    if (kind_ == cubature_kind::p_adaptive) {
      std::uint64_t n = 1;
      for (std::size_t j = 0; j < s; ++j) n *= 3;
      return n;
    }
    return s == 1 ? 15 : genz_malik_rule::points_for(s);
  }

  cubature_kind kind_;
};

// ---------------------------------------------------------------------------------------------
// GSL's Monte Carlo integrators (GSL reference manual, "Monte Carlo Integration"): plain, MISER
// (recursive stratified sampling, Press & Farrar 1990), VEGAS (Lepage 1978) with GSL's defaults.

enum class gsl_kind { plain, miser, vegas };

double gsl_point(double* x, std::size_t, void* params) {
  return static_cast<counted_integrand*>(params)->at(x);
}

struct rng_deleter {
  void operator()(gsl_rng* r) const noexcept { gsl_rng_free(r); }
};

// The generator's seed from the scene's seed and the repetition's stream: SplitMix64's
// finaliser (Steele, Lea & Flood, "Fast splittable pseudorandom number generators", OOPSLA
// 2014) over both, so neighbouring streams get unrelated mt19937 states.
unsigned long mixed_seed(std::uint64_t seed, std::uint64_t stream) noexcept {
  std::uint64_t z = seed ^ (stream * 0x9e3779b97f4a7c15ULL + 0x632be59bd9b4e019ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return static_cast<unsigned long>(z ^ (z >> 31));
}

void require_gsl(int status, std::string_view what) {
  if (status != GSL_SUCCESS) {
    throw std::runtime_error(fmt::format("{} failed: {}", what, gsl_strerror(status)));
  }
}

class gsl_method final : public method {
 public:
  gsl_method(const method_descriptor& d, gsl_kind kind) : method(d), kind_(kind) {}

  // Two points for σ̂ (plain, MISER); VEGAS runs its 5 iterations (GSL's default) of N/5 each,
  // at least 2 per iteration.
  sizing size_for(std::uint64_t N, std::size_t) const override {
    const std::uint64_t least = kind_ == gsl_kind::vegas ? 10 : 2;
    if (N < least) {
      return {std::nullopt,
              fmt::format("N is below {}'s {} evaluations", descriptor().name, least)};
    }
    return {cell_size{N, 0, 0, 0}, {}};
  }

  theoretical_rate theory(const integrand_class& f) const override {
    switch (kind_) {
      case gsl_kind::plain:
        return root_n_rate(f, "GSL plain Monte Carlo: sigma/sqrt(N)",
                           "docs/theory.md#plain-monte-carlo");
      case gsl_kind::miser:
        return adaptive_monte_carlo_rate(
            f, "GSL MISER: recursive stratification lowers sigma, not the rate",
            "docs/theory.md#plain-monte-carlo; [Press & Farrar 1990]");
      case gsl_kind::vegas:
        break;
    }
    return adaptive_monte_carlo_rate(f, "GSL VEGAS: sigma/sqrt(N) with the adapted density's sigma",
                                     "docs/theory.md#vegas; [Lepage 1978]");
  }

  repetition_result run(const method_cell& cell, const run_context& context) const override {
    const box& domain = cell.function.info().domain;
    counted_integrand c = counted(cell);
    gsl_monte_function g{&gsl_point, c.s, &c};
    std::vector<double> lower = domain.lower, upper = domain.upper;  // VEGAS takes them non-const
    const std::unique_ptr<gsl_rng, rng_deleter> rng(gsl_rng_alloc(gsl_rng_mt19937));
    gsl_rng_set(rng.get(), mixed_seed(context.seed, cell.stream));
    const std::size_t calls = cell.size.evaluations;
    double value = 0.0, error = 0.0;
    repetition_result out;
    switch (kind_) {
      case gsl_kind::plain: {
        gsl_monte_plain_state* state = gsl_monte_plain_alloc(c.s);
        const int status = gsl_monte_plain_integrate(&g, lower.data(), upper.data(), c.s, calls,
                                                     rng.get(), state, &value, &error);
        gsl_monte_plain_free(state);
        c.rethrow();
        require_gsl(status, "gsl_monte_plain_integrate");
        break;
      }
      case gsl_kind::miser: {
        gsl_monte_miser_state* state = gsl_monte_miser_alloc(c.s);
        const int status = gsl_monte_miser_integrate(&g, lower.data(), upper.data(), c.s, calls,
                                                     rng.get(), state, &value, &error);
        gsl_monte_miser_free(state);
        c.rethrow();
        require_gsl(status, "gsl_monte_miser_integrate");
        break;
      }
      case gsl_kind::vegas: {
        gsl_monte_vegas_state* state = gsl_monte_vegas_alloc(c.s);
        gsl_monte_vegas_params params;
        gsl_monte_vegas_params_get(state, &params);
        const std::size_t per_iteration = calls / params.iterations;
        const int status = gsl_monte_vegas_integrate(
            &g, lower.data(), upper.data(), c.s, per_iteration, rng.get(), state, &value, &error);
        // GSL's chisq is already per degree of freedom (iterations − 1 of them); Q is the
        // upper tail of χ² with that many degrees of freedom (Lepage 1978).
        const double dof = static_cast<double>(params.iterations) - 1.0;
        out.chi2_per_dof = gsl_monte_vegas_chisq(state);
        if (dof > 0.0 && std::isfinite(out.chi2_per_dof)) {
          out.q_value = boost::math::gamma_q(dof / 2.0, out.chi2_per_dof * dof / 2.0);
        }
        gsl_monte_vegas_free(state);
        c.rethrow();
        require_gsl(status, "gsl_monte_vegas_integrate");
        break;
      }
    }
    out.value = value;
    out.std_error = error;
    out.error_estimate = error;
    out.evaluations = c.calls;
    return out;
  }

 private:
  gsl_kind kind_;
};

// ---------------------------------------------------------------------------------------------
// Boost.Math's 1D quadrature (Boost 1.74, "Quadrature and Differentiation"): tanh_sinh
// (double-exponential) and gauss_kronrod<double, 15> (adaptive, depth ≤ 15, Boost's default).
// Both stop at a tolerance relative to ∫|f| (their L1): an absolute tolerance t is passed as
// t / L1, L1 taken from one 15-point Gauss–Kronrod pass whose evaluations are counted with the
// run's. Tolerance control only: neither has an evaluation cap.

enum class boost_kind { tanh_sinh, gauss_kronrod };

class boost_method final : public method {
 public:
  boost_method(const method_descriptor& d, boost_kind kind) : method(d), kind_(kind) {}

  std::optional<std::string> incompatibility(const integrand_traits& f) const override {
    if (f.s != 1) {
      return fmt::format("{} is a 1D rule; the integrand has s = {}", descriptor().name, f.s);
    }
    return std::nullopt;
  }

  sizing size_for(std::uint64_t N, std::size_t s) const override {
    if (s != 1) return {std::nullopt, fmt::format("{} needs s = 1 (s = {})", descriptor().name, s)};
    return {cell_size{N, 0, 0, 0}, {}};
  }

  theoretical_rate theory(const integrand_class&) const override {
    return {std::nullopt,
            kind_ == boost_kind::tanh_sinh
                ? "Boost tanh_sinh: double-exponential, faster than any power on analytic f"
                : "Boost gauss_kronrod<15>: adaptive, exponential on analytic f",
            "docs/theory.md#exponential-convergence; [Trefethen & Weideman 2014]"};
  }

  repetition_result run(const method_cell& cell, const run_context&) const override {
    const box& domain = cell.function.info().domain;
    const double a = domain.lower[0], b = domain.upper[0];
    counted_integrand c = counted(cell);
    auto g = [&c](double x) { return c.at(&x); };
    using gauss_kronrod = boost::math::quadrature::gauss_kronrod<double, 15>;
    double error = 0.0, l1 = 0.0;
    gauss_kronrod::integrate(g, a, b, 0, 0.0, &error, &l1);
    c.rethrow();
    const double relative = l1 > 0.0 ? cell.tolerance / l1 : 1.0;
    double value = 0.0;
    if (kind_ == boost_kind::tanh_sinh) {
      boost::math::quadrature::tanh_sinh<double> integrator;  // integrate() is not const
      value = integrator.integrate(g, a, b, relative, &error, &l1);
    } else {
      value = gauss_kronrod::integrate(g, a, b, 15, relative, &error, &l1);
    }
    c.rethrow();
    repetition_result out;
    out.value = value;
    out.evaluations = c.calls;
    out.error_estimate = error;
    return out;
  }

 private:
  boost_kind kind_;
};

// ---------------------------------------------------------------------------------------------
// scipy's qmc_quad (python3-scipy 1.10: scipy.integrate._quadrature._qmc_quad, public as
// scipy.integrate.qmc_quad from 1.11): the mean of n_estimates = 8 estimates (its default), each
// over n_points scrambled Sobol' points (scipy.stats.qmc.Sobol, random linear scramble and
// digital shift), with its standard_error s/√8 as the 1σ claim the reliability table audits. It
// runs in a Python process of its own (scipy_qmc_quad.py, python_peer_process.hpp) on the same
// instance, rebuilt there by the quadmc module from the instance's parameters; the instance's
// exact value is compared bit for bit so that a mismatch cannot pass unnoticed. Single-threaded,
// seeded from the scene's seed and the repetition's stream: the same result for any --threads.

constexpr std::uint64_t qmc_quad_estimates = 8;

// A JSON string of a catalogue name or key: quotes and backslashes escaped (nothing else occurs).
std::string json_string(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

std::string json_number(double v) {
  require(std::isfinite(v), "integrand parameter", v, "a finite number (JSON has no other)");
  return fmt::format("{:.17g}", v);
}

// A JSON object of one kind of integrand_params keys, each value written by `write`.
template <class Map, class Write>
std::string json_object(const Map& keys, Write write) {
  std::vector<std::string> members;
  for (const auto& [key, value] : keys) members.push_back(json_string(key) + ": " + write(value));
  return fmt::format("{{{}}}", fmt::join(members, ", "));
}

// The request line of scipy_qmc_quad.py for one repetition.
std::string qmc_quad_request(const method_cell& cell, std::uint64_t n_points,
                             std::uint64_t qrng_seed) {
  const integrand_params& p = cell.params;
  const auto list = [](const std::vector<double>& values) {
    std::vector<std::string> numbers;
    for (const double v : values) numbers.push_back(json_number(v));
    return fmt::format("[{}]", fmt::join(numbers, ", "));
  };
  return fmt::format(
      "{{\"family\": {}, \"s\": {}, \"seed\": {}, \"scalars\": {}, \"vectors\": {}, "
      "\"strings\": {}, \"n_points\": {}, \"n_estimates\": {}, \"qrng_seed\": {}}}",
      json_string(cell.function.info().name), cell.function.dimension(), p.seed,
      json_object(p.scalars, json_number), json_object(p.vectors, list),
      json_object(p.strings, [](const std::string& v) { return json_string(v); }), n_points,
      qmc_quad_estimates, qrng_seed);
}

class scipy_qmc_quad_method final : public method {
 public:
  explicit scipy_qmc_quad_method(const method_descriptor& d)
      : method(d),
        process_(std::make_unique<python_peer_process>(
            std::vector<std::string>{QUADMC_PEERS_PYTHON, QUADMC_PEERS_QMC_QUAD_SCRIPT},
            QUADMC_PEERS_PYTHON_MODULE_DIR)) {
    // What a run would need, checked when the scene is planned (scipy itself is imported when
    // the first cell runs, and a missing one is named then).
    namespace fs = std::filesystem;
    if (!fs::exists(QUADMC_PEERS_PYTHON)) {
      throw invalid_argument("method", descriptor().name,
                             fmt::format("{} to run scipy (install python3-scipy with ./run.sh "
                                         "deps)",
                                         QUADMC_PEERS_PYTHON));
    }
    if (!fs::exists(fs::path(QUADMC_PEERS_PYTHON_MODULE_DIR) / "quadmc")) {
      throw invalid_argument("method", descriptor().name,
                             fmt::format("the quadmc Python module in {} (a build with "
                                         "QUADMC_PYTHON on builds it)",
                                         QUADMC_PEERS_PYTHON_MODULE_DIR));
    }
  }

  // n_points = 2^m ≤ N/8 per estimate (a Sobol' net, as scipy advises), at least 2.
  sizing size_for(std::uint64_t N, std::size_t) const override {
    if (N < 2 * qmc_quad_estimates) {
      return {std::nullopt, fmt::format("N is below {} estimates of 2 points", qmc_quad_estimates)};
    }
    return {cell_size{qmc_quad_estimates * std::bit_floor(N / qmc_quad_estimates), 0, 0, 0}, {}};
  }

  theoretical_rate theory(const integrand_class& f) const override {
    theoretical_rate rate = scrambled_net_rate(f);
    rate.note = "scipy qmc_quad: the mean of 8 scrambled Sobol' estimates; " + rate.note;
    return rate;
  }

  repetition_result run(const method_cell& cell, const run_context& context) const override {
    const std::uint64_t n_points = cell.size.evaluations / qmc_quad_estimates;
    const std::string answer =
        process_->request(qmc_quad_request(cell, n_points, mixed_seed(context.seed, cell.stream)));
    std::istringstream in(answer);
    std::string status, integral, error, evaluations, exact;
    in >> status >> integral >> error >> evaluations >> exact;
    if (status != "ok") {
      throw std::runtime_error(
          fmt::format("{} on {}: {}", descriptor().name, cell.function.info().name, answer));
    }
    const double there = std::strtod(exact.c_str(), nullptr);
    const double here = cell.function.info().exact;
    if (!(there == here || (std::isnan(there) && std::isnan(here)))) {
      throw std::runtime_error(
          fmt::format("{}: the Python module built another {} (exact {} there, {} here)",
                      descriptor().name, cell.function.info().name, exact, here));
    }
    repetition_result out;
    out.value = std::strtod(integral.c_str(), nullptr);
    out.std_error = std::strtod(error.c_str(), nullptr);
    if (!std::isfinite(out.value) || !(out.std_error >= 0.0)) {
      throw std::runtime_error(fmt::format("{} on {} answered {}", descriptor().name,
                                           cell.function.info().name, answer));
    }
    out.error_estimate = out.std_error;
    out.evaluations = std::strtoull(evaluations.c_str(), nullptr, 10);
    return out;
  }

 private:
  std::unique_ptr<python_peer_process> process_;  // const methods share it (it has a mutex)
};

std::unique_ptr<const method> create_scipy_qmc_quad(const method_descriptor& d, option_reader&) {
  return std::make_unique<scipy_qmc_quad_method>(d);
}

// ---------------------------------------------------------------------------------------------

constexpr std::array<cell_control, 2> adaptive_controls{cell_control::budget,
                                                        cell_control::tolerance};
constexpr std::array<cell_control, 1> budget_only{cell_control::budget};
constexpr std::array<cell_control, 1> tolerance_only{cell_control::tolerance};

template <class M, auto Kind>
std::unique_ptr<const method> create(const method_descriptor& d, option_reader&) {
  return std::make_unique<M>(d, Kind);
}

constexpr std::array<cell_control, 1> fixed_only{cell_control::fixed_size};

const std::array<method_descriptor, 8> descriptors{{
    {peers::hcubature.name,
     "peer: cubature's hcubature (h-adaptive Genz-Malik, Gauss-Kronrod 7/15 in 1D), GPL",
     method_kind::deterministic,
     {},
     adaptive_controls,
     create<cubature_method, cubature_kind::h_adaptive>},
    {peers::pcubature.name,
     "peer: cubature's pcubature (p-adaptive tensor Clenshaw-Curtis), GPL",
     method_kind::deterministic,
     {},
     adaptive_controls,
     create<cubature_method, cubature_kind::p_adaptive>},
    {peers::gsl_plain.name,
     "peer: GSL's gsl_monte_plain (mt19937), GPL",
     method_kind::randomized,
     {},
     budget_only,
     create<gsl_method, gsl_kind::plain>},
    {peers::gsl_miser.name,
     "peer: GSL's gsl_monte_miser (recursive stratified sampling), GPL",
     method_kind::randomized,
     {},
     budget_only,
     create<gsl_method, gsl_kind::miser>},
    {peers::gsl_vegas.name,
     "peer: GSL's gsl_monte_vegas (5 iterations of N/5), GPL",
     method_kind::randomized,
     {},
     budget_only,
     create<gsl_method, gsl_kind::vegas>},
    {peers::boost_tanh_sinh.name,
     "peer: Boost.Math tanh_sinh (1D, double-exponential)",
     method_kind::deterministic,
     {},
     tolerance_only,
     create<boost_method, boost_kind::tanh_sinh>},
    {peers::boost_gauss_kronrod.name,
     "peer: Boost.Math gauss_kronrod<double, 15> (1D, adaptive)",
     method_kind::deterministic,
     {},
     tolerance_only,
     create<boost_method, boost_kind::gauss_kronrod>},
    {peers::scipy_qmc_quad.name,
     "peer: scipy's qmc_quad (8 scrambled Sobol' estimates, their standard error), in a Python "
     "process; BSD",
     method_kind::randomized,
     {},
     fixed_only,
     create_scipy_qmc_quad},
}};

// GSL's default error handler aborts the process; the adapters check every status instead.
// Then the descriptors join the registry, before main (registry.hpp, add_methods).
const bool registered = [] {
  gsl_set_error_handler_off();
  add_methods(descriptors);
  return true;
}();

}  // namespace

std::span<const method_descriptor> peer_scene_methods() noexcept {
  static_cast<void>(registered);
  return descriptors;
}

}  // namespace quadmc::peers
