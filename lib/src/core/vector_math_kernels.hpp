// The per-instruction-set bodies of vector_exp and vector_cos (core/vector_math.hpp). Private to
// lib/src/core. Each ISA file is compiled with its own flag and calls no inline function of a
// shared header (see philox_lanes.hpp on the ODR hazard of per-file flags).
#pragma once

#include "quadmc/core/vector_math.hpp"

#include <cstddef>

namespace quadmc::detail {

void vector_math_sse2(vector_function f, const double* x, double* y, std::size_t n) noexcept;
void vector_math_avx2(vector_function f, const double* x, double* y, std::size_t n) noexcept;
void vector_math_avx512(vector_function f, const double* x, double* y, std::size_t n) noexcept;

// Applies `call` (one libmvec variant: Lanes::lanes doubles in, as many out) to x[0..n) in whole
// registers; the tail is padded with zeros into one more register, so every element takes the
// same path.
template <class Lanes, class Call>
inline void apply_in_lanes(Call call, const double* x, double* y, std::size_t n) noexcept {
  constexpr std::size_t lanes = Lanes::lanes;
  std::size_t i = 0;
  for (; i + lanes <= n; i += lanes) Lanes::store(y + i, call(Lanes::load(x + i)));
  if (i < n) {
    double in[lanes] = {};
    double out[lanes];
    for (std::size_t k = 0; i + k < n; ++k) in[k] = x[i + k];
    Lanes::store(out, call(Lanes::load(in)));
    for (std::size_t k = 0; i + k < n; ++k) y[i + k] = out[k];
  }
}

}  // namespace quadmc::detail
