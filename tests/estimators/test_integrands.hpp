// Test support: small integrands with known integrals, defined here so the estimator tests do
// not depend on the functions catalogue. f is called per point inside a batch loop (static
// dispatch; speed is irrelevant at test sizes).
#pragma once

#include "quadmc/functions/integrand.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <utility>

namespace quadmc::test_support {

template <class Fn>
class test_integrand {
 public:
  test_integrand(std::string name, box domain, double exact, Fn fn) : fn_(std::move(fn)) {
    info_.name = std::move(name);
    info_.domain = std::move(domain);
    info_.exact = exact;
    info_.reference = "closed form (see the test)";
  }
  std::size_t dimension() const noexcept { return info_.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const {
    const std::size_t s = dimension();
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = fn_(x.subspan(i * s, s));
  }
  integrand_info info() const { return info_; }

 private:
  Fn fn_;
  integrand_info info_;
};

template <class Fn>
test_integrand<Fn> make_integrand(std::string name, box domain, double exact, Fn fn) {
  return test_integrand<Fn>(std::move(name), std::move(domain), exact, std::move(fn));
}

}  // namespace quadmc::test_support
