// One method run alone, and the peak-memory table built from such runs; see peak_memory.hpp.
#include "peak_memory.hpp"

#include "quadmc_methods.hpp"
#include "sum_of_coordinates.hpp"

#include "peak_rss.hpp"               // bench/common
#include "scalar_reference_loop.hpp"  // bench/common

#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/functions/genz.hpp"
#include "quadmc/rules/simpson_rule.hpp"
#include "quadmc/rules/tensor_product.hpp"
#include "quadmc/rules/trapezoid_rule.hpp"
#include "quadmc/sampling/halton_points.hpp"
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/latin_hypercube_points.hpp"
#include "quadmc/sampling/rank1_lattice_points.hpp"
#include "quadmc/sampling/sobol_points.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace quadmc::peers {
namespace {

constexpr std::array<std::string_view, 12> methods = {
    "baseline",        "reference",  "plain",       "jittered",
    "latin_hypercube", "simpson",    "trapezoid",   "sobol_lms_shift",
    "sobol_fast_owen", "sobol_owen", "halton_owen", "lattice_shift"};
constexpr std::array<std::string_view, 3> integrands = {"genz_oscillatory", "genz_gaussian",
                                                        "sum_of_coordinates"};

// The methods whose peak memory the report shows: `--one` name and the name of the study's rows.
const std::vector<std::pair<std::string, std::string>> rss_methods{
    {"plain", "quadmc plain MC"},
    {"jittered", "quadmc jittered"},
    {"latin_hypercube", "quadmc Latin hypercube"},
    {"simpson", "quadmc tensor Simpson"},
    {"trapezoid", "quadmc tensor trapezoid"},
    {"sobol_lms_shift", "quadmc sobol lms_shift"},
    {"sobol_fast_owen", "quadmc sobol fast_owen"},
    {"sobol_owen", "quadmc sobol owen"},
    {"halton_owen", "quadmc halton owen"},
    {"lattice_shift", "quadmc lattice shift"}};

// The size a method is run at for a requested N: the nearest it holds (jittered k^s, tensor
// (n+1)^s are chosen inside run_one_on); the lattice holds at most 2^20 points, so the largest
// power of two ≤ min(N, 2^20); the digit-scrambled Halton set generates 2–5 M points/s, so
// 10^8 points would cost 10–25 s of the study: at most 10^7 (one byte per point would still
// add 9 MiB, above the report's 4 MiB bound).
std::uint64_t rss_size(const std::string& method, std::uint64_t n) {
  if (method == "lattice_shift") return std::bit_floor(std::min(n, max_lattice_points));
  if (method == "halton_owen") return std::min<std::uint64_t>(n, 10000000);
  return n;
}

template <class F>
int run_one_on(const F& f, const std::string& method, std::uint64_t n, unsigned threads) {
  const std::size_t s = f.dimension();
  const std::uint64_t seed = base_seed;
  double value = 0.0;
  if (method == "baseline") {
    value = f.info().exact;
  } else if (method == "reference") {
    value = bench::scalar_reference_loop(f, n, seed).value;
  } else if (method == "plain") {
    value = monte_carlo(f, independent_points(s, n, seed, 1), threads).value;
  } else if (method == "jittered") {
    value = monte_carlo(f, jittered_points(s, jittered_size(n, s), seed, 1), threads).value;
  } else if (method == "latin_hypercube") {
    value = monte_carlo(f, latin_hypercube_points(s, n, seed, 1), threads).value;
  } else if (method == "simpson") {
    value = integrate(f, simpson_rule{}, tensor_panels(n, s, true, false), threads).value;
  } else if (method == "trapezoid") {
    value = integrate(f, trapezoid_rule{}, tensor_panels(n, s, false, false), threads).value;
  } else if (method == "sobol_lms_shift") {
    value = monte_carlo(f, sobol_points<linear_matrix_scramble>(s, n, seed, 1), threads).value;
  } else if (method == "sobol_fast_owen") {
    value = monte_carlo(f, sobol_points<fast_owen_scramble>(s, n, seed, 1), threads).value;
  } else if (method == "sobol_owen") {
    value = monte_carlo(f, sobol_points<owen_scramble>(s, n, seed, 1), threads).value;
  } else if (method == "halton_owen") {
    value = monte_carlo(f, halton_points<nested_digit_scramble>(s, n, seed, 1), threads).value;
  } else if (method == "lattice_shift") {
    value = monte_carlo(f, rank1_lattice_points<no_periodization>(s, n, seed, 1), threads).value;
  } else {
    std::string known;
    for (std::string_view m : methods) known += (known.empty() ? "" : ", ") + std::string(m);
    std::cerr << "--one: unknown method " << method << " (" << known << ")\n";
    return 2;
  }
  if (!std::isfinite(value)) return 1;
  std::cout << bench::peak_rss_kib() << std::endl;
  return 0;
}

}  // namespace

std::span<const std::string_view> one_run_methods() noexcept {
  return methods;
}
std::span<const std::string_view> one_run_integrands() noexcept {
  return integrands;
}

int run_one(const std::string& method, const std::string& integrand, std::size_t s, std::uint64_t n,
            unsigned threads) {
  if (integrand == "genz_oscillatory") {
    auto p = genz_random_parameters(genz_family::oscillatory, s, genz_seed);
    return run_one_on(genz_oscillatory(std::move(p.a), std::move(p.u)), method, n, threads);
  }
  if (integrand == "genz_gaussian") {
    auto p = genz_random_parameters(genz_family::gaussian, s, genz_seed);
    return run_one_on(genz_gaussian(std::move(p.a), std::move(p.u)), method, n, threads);
  }
  if (integrand == "sum_of_coordinates")
    return run_one_on(sum_of_coordinates(s), method, n, threads);
  std::cerr << "--one: unknown integrand " << integrand
            << " (genz_oscillatory, genz_gaussian, sum_of_coordinates)\n";
  return 2;
}

void measure_peak_memory(const configuration& c, study& out) {
  std::cerr << "peak RSS:" << std::flush;
  // The memory case: Genz Gaussian, s = 2, 2 threads.
  auto one = [](const std::string& method, std::uint64_t n) {
    return bench::child_peak_rss_kib(
        {"--one", method, "genz_gaussian", "2", std::to_string(n), "2"});
  };
  out.rss_baseline_kib = one("baseline", 1);
  for (const auto& [key, name] : rss_methods) {
    std::cerr << " " << key << std::flush;
    rss_row r{name, {}, {}};
    for (std::uint64_t n : c.rss_sizes) {
      r.n.push_back(rss_size(key, n));
      r.kib.push_back(one(key, r.n.back()));
    }
    out.rss.push_back(r);
  }
  std::cerr << "\n";
}

}  // namespace quadmc::peers
