// The point sets a scene may name, each with its count rule and the estimators of this library
// compiled over it: the one table a new point set joins (a header in sampling/ for the set, one
// entry here).
//
// Use it where the point set is chosen at run time (the methods layer, `quadmc list`). Each entry
// dispatches once per call to code templated on the concrete set (one virtual call per batch
// inside any_integrand, never per point). Kernels that know their set at compile time construct
// it directly (sampling/*.hpp) and skip the table.
//
// Every run is named by (seed, stream, N, threads) and is bitwise reproducible for any thread
// count. Sets that need N = k^s (jittered, unjittered) reject other N with the nearest valid
// sizes: largest_point_count() maps a nominal N to the count a set can hold first.
#pragma once

#include "quadmc/estimators/estimate.hpp"
#include "quadmc/functions/any_integrand.hpp"
#include "quadmc/functions/irradiance.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace quadmc {

// Which point counts a set can hold.
enum class point_count {
  any,             // every N ≥ 1 (independent points, Latin hypercube)
  perfect_power,   // one point per cell of a k^s grid: N = k^s (jittered, unjittered)
  perfect_square,  // k × k 2D strata padded across dimension pairs: N = k² (any N in 1D)
};

// The largest count ≤ N a set can hold in s dimensions, and its strata per axis k (0 for `any`).
struct point_count_choice {
  std::uint64_t per_axis = 0;
  std::uint64_t points = 0;
};
point_count_choice largest_point_count(point_count counts, std::uint64_t N, std::size_t s);

// The stream of one repetition: the scene's seed keys the Philox generator, `stream` names the
// repetition (core/rng.hpp).
struct sample_stream {
  std::uint64_t seed = 0;
  std::uint64_t stream = 0;
};

// A 1D density on [0, 1] sampled by inversion (sampling/inversion_warps.hpp), carried to the
// integrand's interval [a, b]: X = a + (b − a)W(U), p_X = p_W/(b − a).
enum class unit_warp_kind { power, truncated_exponential };
struct unit_warp {
  unit_warp_kind kind = unit_warp_kind::power;
  double parameter = 1.0;  // the exponent k of (k+1)x^k, or the rate λ of λe^(λx)/(e^λ − 1)
};

enum class irradiance_sampling { uniform_hemisphere, cosine_hemisphere, light_area };

struct point_set_entry {
  std::string_view name;
  std::string_view description;  // one line
  point_count counts;
  // Plain Monte Carlo: the mean of f·volume over the points mapped to f's box.
  estimate (*monte_carlo)(const any_integrand& f, const sample_stream& stream, std::uint64_t n,
                          unsigned threads);
  // Importance sampling of a 1D integrand with the warp's u from this set.
  estimate (*importance)(const any_integrand& f, const unit_warp& warp, const sample_stream& stream,
                         std::uint64_t n, unsigned threads);
  // An irradiance estimator whose 2D u come from this set.
  estimate (*irradiance)(irradiance_sampling technique, const irradiance_setup& setup,
                         const sample_stream& stream, std::uint64_t n, unsigned threads);
};

// Every set, in listing order.
std::span<const point_set_entry> point_set_catalogue() noexcept;
// The entry named `name`, or nullptr.
const point_set_entry* find_point_set(std::string_view name) noexcept;
// Comma-separated names, for "expected one of …" messages.
std::string point_set_names();
// Whether the set can hold exactly n points in s dimensions.
bool accepts_size(const point_set_entry& set, std::size_t s, std::uint64_t n);

}  // namespace quadmc
