// A type-erased integrand for the scene runner, which picks integrands from a file at run time.
// Cost: one virtual call per batch (≥ 256 points in every kernel of this library), never per
// point. Kernels that know the concrete type take it as a template parameter instead.
#pragma once

#include "quadmc/functions/integrand.hpp"

#include <memory>
#include <utility>

namespace quadmc {

class any_integrand {
 public:
  template <integrand F>
  explicit any_integrand(F f)
      : self_(std::make_shared<const model<F>>(std::move(f))), info_(self_->info()) {}

  std::size_t dimension() const noexcept { return info_.dimension(); }
  void evaluate(std::span<const double> x, std::span<double> y) const { self_->evaluate(x, y); }
  const integrand_info& info() const noexcept { return info_; }

 private:
  struct concept_base {
    virtual ~concept_base() = default;
    virtual void evaluate(std::span<const double> x, std::span<double> y) const = 0;
    virtual integrand_info info() const = 0;
  };
  template <class F>
  struct model final : concept_base {
    explicit model(F f) : f_(std::move(f)) {}
    void evaluate(std::span<const double> x, std::span<double> y) const override {
      f_.evaluate(x, y);
    }
    integrand_info info() const override { return f_.info(); }
    F f_;
  };

  // shared_ptr to const: copies are cheap and the integrand is immutable, so threads may share it.
  std::shared_ptr<const concept_base> self_;
  integrand_info info_;
};

}  // namespace quadmc
