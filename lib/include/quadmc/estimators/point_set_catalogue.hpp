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
// count. Sets that need N = k^s (jittered, unjittered) or N = 2^m (Sobol', lattice) reject other N
// with the nearest valid sizes: largest_point_count() maps a nominal N to the count a set can
// hold first. The quasi-Monte Carlo sets (sobol, halton, lattice) take point_set_options (their
// randomization, the lattice's periodization, Sobol's allow_any_n and drop_first_point); the
// other sets ignore them.
#pragma once

#include "quadmc/estimators/estimate.hpp"
#include "quadmc/functions/any_integrand.hpp"
#include "quadmc/functions/irradiance.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace quadmc {

// Which point counts a set can hold.
enum class point_count {
  any,             // every N ≥ 1 (independent points, Latin hypercube, Halton)
  perfect_power,   // one point per cell of a k^s grid: N = k^s (jittered, unjittered)
  perfect_square,  // k × k 2D strata padded across dimension pairs: N = k² (any N in 1D)
  power_of_two,    // a (t, m, s)-net or an embedded lattice: N = 2^m (Sobol', lattice)
};

// How a quasi-Monte Carlo set is randomized (the `randomization` of the sobol, halton and lattice
// methods); each set lists the ones it has, its default first.
enum class randomization {
  none,         // the deterministic points themselves
  shift,        // digital shift (Sobol') or Cranley–Patterson shift modulo 1 (lattice)
  lms_shift,    // random linear matrix scramble plus digital shift (Sobol')
  owen,         // nested uniform scrambling (Sobol', Halton)
  fast_owen,    // hash-based approximation of nested scrambling (Sobol')
  permutation,  // random digit permutations per base and digit (Halton)
};
std::string_view to_string(randomization r) noexcept;
std::optional<randomization> parse_randomization(std::string_view name) noexcept;

// The lattice's periodization: none, or the baker's (tent) transform.
enum class periodization { none, baker };
std::string_view to_string(periodization p) noexcept;

// A set's configuration beyond (s, N, seed, stream). Sets without options ignore it, so the
// default leaves every existing set's bits as they were.
struct point_set_options {
  std::optional<quadmc::randomization> random;  // empty: the set's default
  quadmc::periodization periodic = quadmc::periodization::none;
  bool allow_any_n = false;       // Sobol': N other than 2^m (the first N points of the sequence)
  bool drop_first_point = false;  // Sobol': start at index 1 (the anti-pattern)
};

// Whether one run estimates its own error (σ̂²/N and its stratified variants), or only
// independent replicates of the whole set can (randomized quasi-Monte Carlo:
// docs/theory.md#replicate-error-bars).
enum class error_source { own, replicates };

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

// Receives the points of a set in consecutive batches: (index of the batch's first point, its
// coordinates row-major).
using point_batch_sink = std::function<void(std::uint64_t first, std::span<const double> x)>;

struct point_set_entry {
  std::string_view name;
  std::string_view description;  // one line
  point_count counts;
  // The randomizations the set has, its default first; empty for a set without the option.
  std::span<const randomization> randomizations;
  std::size_t max_dimension;  // 0: any s
  error_source errors;        // with its default options

  // The estimators (function pointers, instantiated per set by point_set_entry_for); call them
  // through the members below.
  estimate (*monte_carlo_over)(const any_integrand& f, const point_set_options& options,
                               const sample_stream& stream, std::uint64_t n, unsigned threads);
  estimate (*importance_over)(const any_integrand& f, const unit_warp& warp,
                              const point_set_options& options, const sample_stream& stream,
                              std::uint64_t n, unsigned threads);
  estimate (*irradiance_over)(irradiance_sampling technique, const irradiance_setup& setup,
                              const point_set_options& options, const sample_stream& stream,
                              std::uint64_t n, unsigned threads);
  // The N points in s dimensions, in batches of at most 256, for `quadmc points` and the
  // discrepancy columns.
  void (*points_over)(std::size_t s, std::uint64_t n, const point_set_options& options,
                      const sample_stream& stream, const point_batch_sink& sink);

  // Plain Monte Carlo: the mean of f·volume over the points mapped to f's box.
  estimate monte_carlo(const any_integrand& f, const sample_stream& stream, std::uint64_t n,
                       unsigned threads, const point_set_options& options = {}) const {
    return monte_carlo_over(f, options, stream, n, threads);
  }
  // Importance sampling of a 1D integrand with the warp's u from this set.
  estimate importance(const any_integrand& f, const unit_warp& warp, const sample_stream& stream,
                      std::uint64_t n, unsigned threads,
                      const point_set_options& options = {}) const {
    return importance_over(f, warp, options, stream, n, threads);
  }
  // An irradiance estimator whose 2D u come from this set.
  estimate irradiance(irradiance_sampling technique, const irradiance_setup& setup,
                      const sample_stream& stream, std::uint64_t n, unsigned threads,
                      const point_set_options& options = {}) const {
    return irradiance_over(technique, setup, options, stream, n, threads);
  }
  void points(std::size_t s, std::uint64_t n, const sample_stream& stream,
              const point_batch_sink& sink, const point_set_options& options = {}) const {
    points_over(s, n, options, stream, sink);
  }

  // The randomization `options` resolve to (the default when none is given); nullopt for a set
  // without randomizations.
  std::optional<randomization> randomization_of(const point_set_options& options) const noexcept;
  // Whether the set has that randomization.
  bool has(randomization r) const noexcept;
  // The counts the set holds with these options (allow_any_n lifts N = 2^m to any N).
  point_count counts_with(const point_set_options& options) const noexcept;
  // Where the error bars come from with these options: a randomized QMC set needs replicates,
  // an unrandomized one has none (it is deterministic).
  error_source errors_with(const point_set_options& options) const noexcept;
};

// Every set, in listing order.
std::span<const point_set_entry> point_set_catalogue() noexcept;
// The entry named `name`, or nullptr.
const point_set_entry* find_point_set(std::string_view name) noexcept;
// Comma-separated names, for "expected one of …" messages.
std::string point_set_names();
// Whether the set can hold exactly n points in s dimensions (with these options).
bool accepts_size(const point_set_entry& set, std::size_t s, std::uint64_t n,
                  const point_set_options& options = {});
// The largest N a set holds (2^32 for Sobol', 2^20 for the lattice), else 2^62.
std::uint64_t max_point_count(const point_set_entry& set, const point_set_options& options = {});
// "s ≤ 3667 for the sobol points, got s = 3668" for a dimension beyond the set's tables, or empty
// (size_problem begins with it; a caller that names its parameters blames s, not N, for it).
std::string dimension_problem(const point_set_entry& set, std::size_t s);
// "N = 2^m required: nearest valid sizes 512 and 1024"-style text for a count a set cannot hold,
// or empty when it can.
std::string size_problem(const point_set_entry& set, std::size_t s, std::uint64_t n,
                         const point_set_options& options = {});

}  // namespace quadmc
