// Test support: Pearson's chi-square test of warped samples against a density, on a grid of
// cells in two parameters (a, b) of the warp's image (1D warps use one cell row).
//
// Expected cell probabilities are the density integrated over the cell by a 2D Gauss–Legendre
// rule (Boost.Math, 15 points per axis: exact to rounding for the smooth densities tested, so
// the test checks sampling against the pdf, not against a second formula). Cells expected to
// hold fewer than 5 samples are pooled into one (Cochran's rule), and the statistic has
// (cells − 1) degrees of freedom. The caller names the false-alarm probability α.
#pragma once

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/quadrature/gauss.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace quadmc::test_support {

// Every warp test draws this many samples and runs each of its chi-square tests at this
// false-alarm probability (the suite's bound, 1e-4 per test).
inline constexpr std::uint64_t warp_samples = 1000000;
inline constexpr double warp_alpha = 1e-4;

struct chi_square_result {
  double statistic = 0.0;
  double critical = 0.0;  // the (1 − α) quantile of χ²(dof)
  std::size_t dof = 0;
  bool passes() const { return statistic <= critical; }
};

// counts[i*nb + j]: samples in cell i along a, j along b; density(a, b) includes any Jacobian,
// so that its integral over [a0,a1]×[b0,b1] is the probability of the whole grid (the tail
// outside, if any, is tail_probability with tail_count samples).
inline chi_square_result chi_square_test(const std::vector<double>& counts, std::size_t na,
                                         std::size_t nb, double a0, double a1, double b0, double b1,
                                         const std::function<double(double, double)>& density,
                                         double total, double alpha, double tail_count = 0.0,
                                         double tail_probability = 0.0) {
  using rule = boost::math::quadrature::gauss<double, 15>;
  const double da = (a1 - a0) / static_cast<double>(na);
  const double db = (b1 - b0) / static_cast<double>(nb);
  double statistic = 0.0;
  std::size_t cells = 0;
  double pooled_observed = tail_count;
  double pooled_expected = tail_probability * total;
  for (std::size_t i = 0; i < na; ++i) {
    for (std::size_t j = 0; j < nb; ++j) {
      const double al = a0 + da * static_cast<double>(i);
      const double bl = b0 + db * static_cast<double>(j);
      const double p = rule::integrate(
          [&](double a) {
            return rule::integrate([&](double b) { return density(a, b); }, bl, bl + db);
          },
          al, al + da);
      const double expected = p * total;
      const double observed = counts[i * nb + j];
      if (expected < 5.0) {
        pooled_observed += observed;
        pooled_expected += expected;
        continue;
      }
      statistic += (observed - expected) * (observed - expected) / expected;
      ++cells;
    }
  }
  if (pooled_expected >= 5.0 || pooled_observed > 0.0) {
    statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) /
                 std::max(pooled_expected, 1e-300);
    ++cells;
  }
  chi_square_result r;
  r.statistic = statistic;
  r.dof = cells - 1;
  r.critical = boost::math::quantile(
      boost::math::complement(boost::math::chi_squared(static_cast<double>(r.dof)), alpha));
  return r;
}

}  // namespace quadmc::test_support
