// One method of the peers benchmark, seen from the driver: a name, how many threads it uses, and
// a function that runs it once at a given size and returns the value and the evaluations spent.
//
// Use it to put quadmc's estimators and rules beside GSL, Boost.Math, cubature and the
// hand-written loop under one measuring loop (quadmc_peers.cpp). The std::function is called
// once per run, never per sample, so it costs nothing measurable. Not a library interface:
// quadmc's own kernels are templates (dispatch once, then inline:
// docs/design.md#hot-path-contract).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace quadmc::peers {

struct run_result {
  double value = 0.0;
  std::uint64_t evaluations = 0;  // integrand evaluations actually spent (counted, not assumed)
};

// What a method's size parameter ("control") means.
enum class control_kind {
  evaluations,   // N (a point set or grid may round it to a valid size: jittered k^s, (n+1)^s)
  panels,        // tensor rules: panels per axis n, N = (n+1)^s
  tolerance,     // adaptive 1D rules: control k asks for a tolerance of 10^−k
  target_calls,  // Boost naive_monte_carlo: error goal √(V̂/N) so that it stops near N calls
};

struct peer_method {
  std::string name;    // e.g. "quadmc plain MC", "GSL plain"
  std::string family;  // "quadmc", "reference", "GSL", "Boost.Math", "cubature"
  unsigned threads = 1;
  bool random = true;  // random methods are repeated with independent seeds in the ladder
  control_kind kind = control_kind::evaluations;
  std::vector<std::uint64_t> ladder;  // controls of the work-precision ladder, ascending
  // Control of the throughput measurement (N ≥ 10^6); 0: the ladder point with the most
  // evaluations (adaptive 1D rules, which converge long before 10^6 evaluations).
  std::uint64_t throughput_control = 0;
  std::function<run_result(std::uint64_t control, std::uint64_t seed)> run;
};

}  // namespace quadmc::peers
