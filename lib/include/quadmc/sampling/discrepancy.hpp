// L2 discrepancies of a point set in [0,1)^s: the L2-star discrepancy by Warnock's formula
// ([Warnock 1972]), and Hickernell's centered and wrap-around L2 discrepancies
// ([Hickernell 1998]) — the measures of uniformity behind the Koksma–Hlawka-type error bounds
// of quasi-Monte Carlo (docs/theory.md#discrepancy).
//
// Use it to put a number on how evenly a point set covers the cube beside the integration error
// (the `*_discrepancy` columns of convergence.csv), or to compare point sets at equal N. Each is
// exact, O(N²·s) (every pair of points), so N is bounded by max_discrepancy_points = 2^14 (a few
// seconds at s = 8). Not a bound on any one integrand's error without its variation, and
// unlike the star discrepancy (a supremum) these are root mean squares over boxes:
//   L2-star    D*² = 3^−s − (2^(1−s)/N) Σᵢ Πⱼ (1 − xᵢⱼ²) + (1/N²) Σᵢ Σₖ Πⱼ (1 − max(xᵢⱼ, xₖⱼ)),
//              boxes anchored at the origin;
//   centered   CD² = (13/12)^s − (2/N) Σᵢ Πⱼ (1 + ½|xᵢⱼ − ½| − ½|xᵢⱼ − ½|²)
//                    + (1/N²) Σᵢ Σₖ Πⱼ (1 + ½|xᵢⱼ − ½| + ½|xₖⱼ − ½| − ½|xᵢⱼ − xₖⱼ|),
//              boxes anchored at the nearest vertex (invariant under reflections xⱼ ↦ 1 − xⱼ);
//   wrap-around WD² = −(4/3)^s + (1/N²) Σᵢ Σₖ Πⱼ (3/2 − |xᵢⱼ − xₖⱼ|(1 − |xᵢⱼ − xₖⱼ|)),
//              boxes that wrap around the torus (invariant under shifts modulo 1, so a randomly
//              shifted lattice has the wrap-around discrepancy of its lattice).
// For N independent uniform points E[D*²] = (2^−s − 3^−s)/N, E[CD²] = ((5/4)^s − (13/12)^s)/N,
// E[WD²] = ((3/2)^s − (4/3)^s)/N (docs/theory.md#discrepancy derives them; the tests check
// them). The functions return D, the square root (0 where rounding makes D² slightly negative).
#pragma once

#include "quadmc/sampling/point_set.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace quadmc {

inline constexpr std::uint64_t max_discrepancy_points = std::uint64_t{1} << 14;

struct l2_discrepancies {
  double l2_star = 0.0;
  double centered = 0.0;
  double wraparound = 0.0;
};

// All three of N = points.size()/s points given row-major (x[i*s + j]), in one pass over the
// pairs. Throws invalid_argument for s = 0, a size that is not a multiple of s, no points, more
// than 2^14 points, or a coordinate outside [0, 1].
l2_discrepancies discrepancies(std::span<const double> points, std::size_t s);

double l2_star_discrepancy(std::span<const double> points, std::size_t s);
double centered_discrepancy(std::span<const double> points, std::size_t s);
double wraparound_discrepancy(std::span<const double> points, std::size_t s);

// The discrepancies of a whole point set (N ≤ 2^14), generated in one batch.
template <point_set P>
l2_discrepancies discrepancies_of(const P& points) {
  require(points.size() <= max_discrepancy_points, "number of points N", points.size(),
          "N ≤ 2^14 for an O(N²) discrepancy");
  std::vector<double> x(points.size() * points.dimension());
  points.generate(0, x);
  return discrepancies(x, points.dimension());
}

}  // namespace quadmc
