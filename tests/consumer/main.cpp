// Proves the installed package is usable: headers found, dependencies re-found by
// quadmcConfig.cmake, static layers linked. Exits non-zero on a wrong answer.
#include <quadmc/core/rng.hpp>
#include <quadmc/core/summation.hpp>
#include <quadmc/core/welford.hpp>

#include <cmath>
#include <cstdio>

int main() {
  // Mean of 10^5 Philox uniforms: 1/2 within 5 standard errors (σ = 1/√12), false-alarm ≈ 6e-7.
  const quadmc::philox_stream stream(42, quadmc::stream_id({1, 2, 3}));
  quadmc::welford w;
  for (std::uint64_t i = 0; i < 100000; ++i) w.add(stream.uniform(i));
  const double tolerance = 5.0 / std::sqrt(12.0 * 100000.0);
  quadmc::neumaier_sum s;
  for (int k = 0; k < 10; ++k) s.add(0.1);
  const bool ok = std::abs(w.mean() - 0.5) < tolerance && s.value() == 1.0;
  std::printf("consumer: mean of uniforms %.6f, ten times 0.1 = %.17g: %s\n", w.mean(), s.value(),
              ok ? "ok" : "WRONG");
  return ok ? 0 : 1;
}
