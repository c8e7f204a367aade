// tensor_rows: the portable row loop (the reference every vector kernel is tested against) and
// the run-time choice of kernel (core/simd_level.hpp).
#include "tensor_product_rows_kernels.hpp"

#include "quadmc/core/simd_level.hpp"

namespace quadmc::detail {
namespace {

struct scalar_rows {
  template <std::size_t S>
  static void row(std::size_t s, const double* lead, double w_lead, const double* last_x,
                  const double* last_w, std::size_t run, double* x, double* weights) noexcept {
    const std::size_t last = s - 1;
    for (std::size_t r = 0; r < run; ++r) {
      double* point = x + r * s;
      for (std::size_t j = 0; j < last; ++j) point[j] = lead[j];
      point[last] = last_x[r];
      weights[r] = w_lead * last_w[r];
    }
  }
};

}  // namespace

void tensor_rows_scalar(const tensor_row_tables& t, std::uint64_t first, std::size_t count,
                        double* x, double* weights) noexcept {
  tensor_walk_rows_by_dimension<scalar_rows>(t, first, count, x, weights);
}

void tensor_rows(const tensor_row_tables& t, std::uint64_t first, std::size_t count, double* x,
                 double* weights) noexcept {
#if defined(__x86_64__)
  switch (active_simd_level()) {
    case simd_level::avx512:
    case simd_level::avx2:
      return tensor_rows_avx2(t, first, count, x, weights);
    default:
      break;
  }
#endif
  tensor_rows_scalar(t, first, count, x, weights);
}

}  // namespace quadmc::detail
