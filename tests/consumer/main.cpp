// Proves the installed package is usable: headers found, dependencies re-found by
// quadmcConfig.cmake, static layers linked. Exits non-zero on a wrong answer.
#include <quadmc/core/rng.hpp>
#include <quadmc/core/summation.hpp>
#include <quadmc/core/welford.hpp>
#include <quadmc/functions/catalogue.hpp>
#include <quadmc/methods/registry.hpp>

#include <cmath>
#include <cstdio>

int main() {
  // Mean of 10^5 Philox uniforms: 1/2 within 5 standard errors (σ = 1/√12), false-alarm ≈ 6e-7.
  const quadmc::random_stream stream(42, quadmc::stream_id({1, 2, 3}));
  quadmc::welford w;
  for (std::uint64_t i = 0; i < 100000; ++i) w.add(stream.uniform(i));
  const double tolerance = 5.0 / std::sqrt(12.0 * 100000.0);
  quadmc::neumaier_sum s;
  for (int k = 0; k < 10; ++k) s.add(0.1);
  // A method from the registry, as the README shows: Simpson on eˣ over [0, 1] with 4096 points
  // at most in 1D is n = 4094 panels, error (e − 1)·h⁴/180 ≈ 3e-17 of I, so within 4ε·I.
  const auto simpson = quadmc::make_method("simpson", {{"accumulator", "neumaier"}});
  const quadmc::sizing size = simpson->size_for(4096, 1);
  const quadmc::integrand_params params;
  const quadmc::any_integrand f = quadmc::make_integrand("exp", params);
  const quadmc::method_cell cell{f, params, *size.size, quadmc::cell_control::fixed_size, 0.0, 0};
  const double value = simpson->run(cell, {0, 1}).value;
  const double exact = std::exp(1.0) - 1.0;
  const bool ok = std::abs(w.mean() - 0.5) < tolerance && s.value() == 1.0 &&
                  size.size->per_axis == 4094 && std::abs(value - exact) <= 4e-16 * exact;
  std::printf("consumer: mean of uniforms %.6f, ten times 0.1 = %.17g, Simpson %.17g: %s\n",
              w.mean(), s.value(), value, ok ? "ok" : "WRONG");
  return ok ? 0 : 1;
}
