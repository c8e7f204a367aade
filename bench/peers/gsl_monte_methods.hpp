// GSL's Monte Carlo integrators as peers: plain, MISER (recursive stratified sampling, Press &
// Farrar 1990) and VEGAS (adaptive importance sampling, Lepage 1978), through gsl_monte_*
// (GSL reference manual, ch. "Monte Carlo Integration").
//
// How they are called, so that the comparison is honest:
//  - the integrand is the suite's own code behind a gsl_monte_function (one call through a
//    function pointer per point: GSL's API has no batch form); the adapter adds one counter
//    increment per call so that the evaluations reported are counted, not assumed;
//  - the generator is gsl_rng_mt19937, GSL's default (gsl_rng_env_setup with no GSL_RNG_TYPE);
//  - plain and MISER get calls = N. VEGAS spends `calls` per iteration and runs
//    params.iterations = 5 iterations per integrate call (GSL's default), so it gets calls = N/5
//    and its counted evaluations are about N (its cost per call includes the grid refinement);
//  - the state and generator are allocated inside the timed run (a few hundred bytes).
// Single-threaded: GSL's integrators have no parallel mode.
#pragma once

#include "peer_method.hpp"

#include "point_adapter.hpp"  // bench/common

#include <gsl/gsl_errno.h>
#include <gsl/gsl_monte.h>
#include <gsl/gsl_monte_miser.h>
#include <gsl/gsl_monte_plain.h>
#include <gsl/gsl_monte_vegas.h>
#include <gsl/gsl_rng.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace quadmc::peers {

enum class gsl_monte_algorithm { plain, miser, vegas };

namespace detail {

template <class F>
struct counted_integrand {
  const F* f;
  std::uint64_t calls = 0;
};

template <class F>
double gsl_point(double* x, std::size_t dim, void* params) {
  auto* p = static_cast<counted_integrand<F>*>(params);
  ++p->calls;
  return bench::evaluate_point(*p->f, x, dim);
}

struct gsl_rng_deleter {
  void operator()(gsl_rng* r) const noexcept { gsl_rng_free(r); }
};

inline void require_gsl(int status, const char* what) {
  if (status != GSL_SUCCESS) {
    throw std::runtime_error(std::string(what) + " failed: " + gsl_strerror(status));
  }
}

template <class F>
run_result gsl_monte_run(gsl_monte_algorithm algorithm, const F& f, std::uint64_t n,
                         std::uint64_t seed) {
  const std::size_t s = f.dimension();
  counted_integrand<F> counted{&f};
  gsl_monte_function g{&gsl_point<F>, s, &counted};
  std::vector<double> lower(s, 0.0), upper(s, 1.0);  // VEGAS takes them non-const
  const std::unique_ptr<gsl_rng, gsl_rng_deleter> rng(gsl_rng_alloc(gsl_rng_mt19937));
  gsl_rng_set(rng.get(), static_cast<unsigned long>(seed));
  double value = 0.0, error = 0.0;
  switch (algorithm) {
    case gsl_monte_algorithm::plain: {
      gsl_monte_plain_state* state = gsl_monte_plain_alloc(s);
      const int status = gsl_monte_plain_integrate(&g, lower.data(), upper.data(), s, n, rng.get(),
                                                   state, &value, &error);
      gsl_monte_plain_free(state);
      require_gsl(status, "gsl_monte_plain_integrate");
      break;
    }
    case gsl_monte_algorithm::miser: {
      gsl_monte_miser_state* state = gsl_monte_miser_alloc(s);
      const int status = gsl_monte_miser_integrate(&g, lower.data(), upper.data(), s, n, rng.get(),
                                                   state, &value, &error);
      gsl_monte_miser_free(state);
      require_gsl(status, "gsl_monte_miser_integrate");
      break;
    }
    case gsl_monte_algorithm::vegas: {
      gsl_monte_vegas_state* state = gsl_monte_vegas_alloc(s);
      gsl_monte_vegas_params params;
      gsl_monte_vegas_params_get(state, &params);
      const std::uint64_t per_iteration =
          std::max<std::uint64_t>(1, n / static_cast<std::uint64_t>(params.iterations));
      const int status = gsl_monte_vegas_integrate(&g, lower.data(), upper.data(), s, per_iteration,
                                                   rng.get(), state, &value, &error);
      gsl_monte_vegas_free(state);
      require_gsl(status, "gsl_monte_vegas_integrate");
      break;
    }
  }
  return {value, counted.calls};
}

}  // namespace detail

template <class F>
peer_method gsl_monte(gsl_monte_algorithm algorithm, const F& f,
                      const std::vector<std::uint64_t>& ladder, std::uint64_t throughput_n) {
  static constexpr const char* names[] = {"GSL plain", "GSL MISER", "GSL VEGAS"};
  peer_method m;
  m.name = names[static_cast<int>(algorithm)];
  m.family = "GSL";
  m.threads = 1;
  m.random = true;
  m.kind = control_kind::evaluations;
  m.ladder = ladder;
  m.throughput_control = throughput_n;
  m.run = [&f, algorithm](std::uint64_t n, std::uint64_t seed) {
    return detail::gsl_monte_run(algorithm, f, n, seed);
  };
  return m;
}

}  // namespace quadmc::peers
