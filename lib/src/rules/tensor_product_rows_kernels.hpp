// The odometer shared by the row kernels of tensor_rows (rules/tensor_product_rows.hpp), and the
// per-instruction-set entry points. Private to lib/src/rules.
//
// Each kernel file (tensor_product_rows.cpp, tensor_product_rows_avx2.cpp) instantiates
// tensor_walk_rows with its own Rows type from an anonymous namespace and calls no inline function
// of a shared header: an out-of-line copy compiled for AVX2 could otherwise be chosen by the
// linker for the whole program (the ODR hazard of per-file -m flags, core/philox_lanes.hpp).
#pragma once

#include "quadmc/rules/tensor_product_rows.hpp"

#include <cstddef>
#include <cstdint>

namespace quadmc::detail {

void tensor_rows_scalar(const tensor_row_tables& t, std::uint64_t first, std::size_t count,
                        double* x, double* weights) noexcept;
#if defined(__x86_64__)
void tensor_rows_avx2(const tensor_row_tables& t, std::uint64_t first, std::size_t count, double* x,
                      double* weights) noexcept;
#endif

// Room after the leading coordinates, so that a kernel may load them in whole registers of up to
// 8 doubles (the values past s − 1 are never stored).
inline constexpr std::size_t tensor_row_lead_padding = 8;

// The walk of tensor_product_grid::walk on the tables: decodes `first` into a multi-index once,
// then hands each row (a run of points sharing their leading coordinates) to
// Rows::template row<S>(s, lead, w_lead, last_x, last_w, run, x, weights), which writes the run's
// points and nothing past them, and carries into the leading axes between rows. S is s when it is
// known at compile time, 0 otherwise. The leading weight is formed left to right from 1.0 at every
// carry, as the template walk forms it.
template <class Rows, std::size_t S>
inline void tensor_walk_rows(const tensor_row_tables& t, std::uint64_t first, std::size_t count,
                             double* x, double* weights) noexcept {
  const std::size_t s = S != 0 ? S : t.s;
  const std::size_t last = s - 1;
  const std::uint64_t m = t.m;
  std::uint64_t index[tensor_row_max_axes];
  double lead[tensor_row_max_axes + tensor_row_lead_padding] = {};
  std::uint64_t rest = first;
  for (std::size_t j = s; j-- > 0;) {
    index[j] = rest % m;
    rest /= m;
  }
  for (std::size_t j = 0; j < last; ++j) lead[j] = t.axis_x[j * m + index[j]];
  auto leading_weight = [&] {
    double w = 1.0;
    for (std::size_t j = 0; j < last; ++j) w *= t.weight[index[j]];
    return w;
  };
  double w_lead = leading_weight();
  const double* last_x = t.axis_x + last * m;
  std::uint64_t k = index[last];
  for (std::size_t i = 0; i < count;) {
    const std::uint64_t left = m - k;
    const std::size_t run = left < count - i ? static_cast<std::size_t>(left) : count - i;
    Rows::template row<S>(s, lead, w_lead, last_x + k, t.weight + k, run, x + i * s, weights + i);
    i += run;
    k += run;
    if (k == m) {  // carry into the leading axes
      k = 0;
      for (std::size_t j = last; j-- > 0;) {
        if (++index[j] < m) {
          lead[j] = t.axis_x[j * m + index[j]];
          break;
        }
        index[j] = 0;
        lead[j] = t.axis_x[j * m];
      }
      w_lead = leading_weight();
    }
  }
}

// Calls tensor_walk_rows with S = s for s ≤ 8 (the dimensions a tensor grid is used in: the loops
// over the coordinates of a point unroll), S = 0 above.
template <class Rows>
inline void tensor_walk_rows_by_dimension(const tensor_row_tables& t, std::uint64_t first,
                                          std::size_t count, double* x, double* weights) noexcept {
  switch (t.s) {
    case 1:
      return tensor_walk_rows<Rows, 1>(t, first, count, x, weights);
    case 2:
      return tensor_walk_rows<Rows, 2>(t, first, count, x, weights);
    case 3:
      return tensor_walk_rows<Rows, 3>(t, first, count, x, weights);
    case 4:
      return tensor_walk_rows<Rows, 4>(t, first, count, x, weights);
    case 5:
      return tensor_walk_rows<Rows, 5>(t, first, count, x, weights);
    case 6:
      return tensor_walk_rows<Rows, 6>(t, first, count, x, weights);
    case 7:
      return tensor_walk_rows<Rows, 7>(t, first, count, x, weights);
    case 8:
      return tensor_walk_rows<Rows, 8>(t, first, count, x, weights);
    default:
      return tensor_walk_rows<Rows, 0>(t, first, count, x, weights);
  }
}

}  // namespace quadmc::detail
