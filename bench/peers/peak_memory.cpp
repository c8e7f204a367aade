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
#include "quadmc/sampling/independent_points.hpp"
#include "quadmc/sampling/jittered_points.hpp"
#include "quadmc/sampling/latin_hypercube_points.hpp"

#include <array>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace quadmc::peers {
namespace {

constexpr std::array<std::string_view, 7> methods = {
    "baseline", "reference", "plain", "jittered", "latin_hypercube", "simpson", "trapezoid"};
constexpr std::array<std::string_view, 3> integrands = {"genz_oscillatory", "genz_gaussian",
                                                        "sum_of_coordinates"};

// The methods whose peak memory the report shows, by their `--one` name.
const std::vector<std::string> rss_methods{"plain", "jittered", "latin_hypercube", "simpson",
                                           "trapezoid"};

std::string rss_method_name(const std::string& key) {
  if (key == "plain") return "quadmc plain MC";
  if (key == "jittered") return "quadmc jittered";
  if (key == "latin_hypercube") return "quadmc Latin hypercube";
  if (key == "simpson") return "quadmc tensor Simpson";
  return "quadmc tensor trapezoid";
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
  } else {
    std::cerr << "--one: unknown method " << method
              << " (baseline, reference, plain, jittered, latin_hypercube, simpson, trapezoid)\n";
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
  for (const auto& m : rss_methods) {
    std::cerr << " " << m << std::flush;
    rss_row r{rss_method_name(m), {}};
    for (std::uint64_t n : c.rss_sizes) {
      r.kib.push_back(one(m, n));
    }
    out.rss.push_back(r);
  }
  std::cerr << "\n";
}

}  // namespace quadmc::peers
