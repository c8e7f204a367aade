// The warp interface: a map from a point u of [0,1)^m to a sample x with a known density p(x)
// (docs/theory.md#inversion, docs/theory.md#rejection; [Pharr et al. 2016, §13.6]).
//
// Use it for importance sampling (estimators/importance_sampling.hpp: Y = f(X)/p(X)); any point
// set can feed a warp, so stratified directions are stratified u pushed through the warp.
// Not for rejection sampling, which consumes a random number of uniforms per sample and so is no
// map of a fixed u (sampling/rejection_disk.hpp stands apart for that reason).
//
// Contract: sample(u, x) reads input_dimension() coordinates and writes output_dimension()
// coordinates; pdf(x) is the density of x with respect to the warp's own measure (stated in each
// warp's comment: length, area, or solid angle for directions), and integrates to 1 over the
// image. Warps are small value types with inline members: one call per sample, no virtual call.
#pragma once

#include <concepts>
#include <cstddef>
#include <span>

namespace quadmc {

template <class W>
concept warp = requires(const W& w, std::span<const double> u, std::span<double> x) {
  { w.input_dimension() } -> std::convertible_to<std::size_t>;
  { w.output_dimension() } -> std::convertible_to<std::size_t>;
  { w.sample(u, x) } -> std::same_as<void>;
  { w.pdf(std::span<const double>(x)) } -> std::convertible_to<double>;
};

}  // namespace quadmc
