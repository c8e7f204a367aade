// What a Monte Carlo estimator returns for one run.
#pragma once

#include <cstdint>

namespace quadmc {

struct estimate {
  double value = 0.0;      // F, the estimate of the integral
  double std_error = 0.0;  // the estimator's own estimate of its standard deviation, √(V̂[F])
  double variance = 0.0;   // the per-sample variance estimate V̂[Y] (Y = f(X)/p(X) times volume)
  std::uint64_t evaluations = 0;  // integrand evaluations spent
};

}  // namespace quadmc
