// Steven G. Johnson's cubature (Debian libcubature-dev, /usr/include/cubature.h) as peers:
// hcubature (h-adaptive: Genz–Malik rule of degree 7 on subdivided boxes, Genz & Malik, J.
// Comput. Appl. Math. 6, 1980; Gauss–Kronrod 7/15 in 1D) and pcubature (p-adaptive:
// tensor Clenshaw–Curtis, doubling the degree per axis).
//
// How they are called, so that the comparison is honest: through the vectorised entry points
// hcubature_v / pcubature_v, whose layout x[i*ndim + j], fval[i] is exactly quadmc's batch
// contract, so the suite's integrand evaluates whole batches there too (what a user who has a
// batch integrand would do); maxEval = N with both tolerances 0, so they refine until the budget
// is spent (or the error estimate is exactly 0); evaluations are counted in the callback.
// Single-threaded (cubature has no parallel mode). Its region heap grows with N (hcubature) and
// pcubature stores its whole grid, so their memory is not constant in N.
#pragma once

#include "peer_method.hpp"

#include <cubature.h>

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace quadmc::peers {

enum class cubature_algorithm { h_adaptive, p_adaptive };

namespace detail {

template <class F>
struct counted_batch_integrand {
  const F* f;
  std::uint64_t calls = 0;
};

template <class F>
int cubature_batch(unsigned ndim, std::size_t npt, const double* x, void* data, unsigned,
                   double* fval) {
  auto* p = static_cast<counted_batch_integrand<F>*>(data);
  p->calls += npt;
  p->f->evaluate(std::span<const double>(x, npt * ndim), std::span<double>(fval, npt));
  return 0;
}

}  // namespace detail

template <class F>
peer_method cubature(cubature_algorithm algorithm, const F& f,
                     const std::vector<std::uint64_t>& ladder, std::uint64_t throughput_n) {
  peer_method m;
  m.name =
      algorithm == cubature_algorithm::h_adaptive ? "cubature hcubature" : "cubature pcubature";
  m.family = "cubature";
  m.threads = 1;
  m.random = false;
  m.kind = control_kind::evaluations;
  m.ladder = ladder;
  m.throughput_control = throughput_n;
  m.run = [&f, algorithm](std::uint64_t n, std::uint64_t) {
    const unsigned s = static_cast<unsigned>(f.dimension());
    detail::counted_batch_integrand<F> counted{&f};
    const std::vector<double> lower(s, 0.0), upper(s, 1.0);
    double value = 0.0, error = 0.0;
    const auto call = algorithm == cubature_algorithm::h_adaptive ? hcubature_v : pcubature_v;
    const int status = call(1, &detail::cubature_batch<F>, &counted, s, lower.data(), upper.data(),
                            n, 0.0, 0.0, ERROR_INDIVIDUAL, &value, &error);
    if (status != 0) throw std::runtime_error("cubature returned " + std::to_string(status));
    return run_result{value, counted.calls};
  };
  return m;
}

}  // namespace quadmc::peers
