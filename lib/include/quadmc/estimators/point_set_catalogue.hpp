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
// randomization, the lattice's periodization, Sobol's allow_any_n, drop_first_point and
// interlacing); the
// other sets ignore them. An entry owns its options: it lists their keys (point_set_option, which
// the methods read from a [[method]] table and `quadmc points` from its command line), turns the
// values given into point_set_options (options_from), states the rate theory gives its sample
// mean and where its error bars come from (theory_of, errors_with), and the strata it fills with
// one point each (strata_of), so that no caller branches on a set's name.
#pragma once

#include "quadmc/core/rng.hpp"
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
#include <vector>

namespace quadmc {

// Which point counts a set can hold.
enum class point_count {
  any,             // every N ≥ 1 (independent points, Latin hypercube, Halton)
  perfect_power,   // one point per cell of a k^s grid: N = k^s (jittered, unjittered)
  perfect_square,  // k × k 2D strata padded across dimension pairs: N = k² (any N in 1D)
  near_square,  // k × k or k × (k + 1) 2D cells padded across pairs: N = k², k(k + 1) (any in 1D)
  power_of_two,  // a (t, m, s)-net or an embedded lattice: N = 2^m (Sobol', lattice)
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

// The lattice's periodization (docs/theory.md#lattice-periodizations): none; the baker's (tent)
// map of the points, which preserves the uniform measure; or a periodizing change of variables
// ∫f = ∫f(φ(x))∏φ'(x_j)dx (sampling/periodizing_transforms.hpp), which weights each point by ∏φ'
// and so applies only to the lattice's sample mean (monte_carlo), not to its points, importance
// or irradiance estimators.
enum class periodization { none, baker, c0, c1, c1sin, c2sin, c3sin };
std::string_view to_string(periodization p) noexcept;
// Whether p weights the points by a Jacobian (c0 … c3sin) rather than moving them (none, baker).
constexpr bool is_weighted(periodization p) noexcept {
  return p != periodization::none && p != periodization::baker;
}

// A set's configuration beyond (s, N, seed, stream). Sets without options ignore it, so the
// default leaves every existing set's bits as they were.
struct point_set_options {
  std::optional<quadmc::randomization> random;  // empty: the set's default
  quadmc::periodization periodic = quadmc::periodization::none;
  bool allow_any_n = false;       // Sobol': N other than 2^m (the first N points of the sequence)
  bool drop_first_point = false;  // Sobol': start at index 1 (the anti-pattern)
  // Sobol': the digit interlacing factor α of an order-α net (sampling/interlaced_sobol_points.hpp;
  // docs/theory.md#interlaced-nets); 1 is the Sobol' points themselves.
  unsigned interlacing = 1;
};

// One option key of a point set, as a [[method]] table names it (`quadmc points` takes it as
// --key with '-' for '_'): a choice among `choices` (the default first), or a flag (no choices;
// false unless given as true). An integer choice (`integer`) is written as a TOML integer in a
// scene (interlacing = 2), its choices being the decimal texts it may take, and the label gets
// "_<key><value>"; a string choice is a TOML string and the label gets "_<value>".
struct point_set_option {
  std::string_view key;
  std::string_view meaning;                   // values, default and what the label gets, one line
  std::span<const std::string_view> choices;  // empty: a flag
  std::string_view flag_label;                // a flag set to true: the default label's suffix
  bool integer = false;                       // choices are integers (decimal text)
  // The choices that weight the points instead of moving them (the lattice's c0 … c3sin): valid
  // for the set's sample mean (the methods), refused by checked_options, whose callers want
  // equal-weight points.
  std::span<const std::string_view> weighted_choices = {};

  bool is_flag() const noexcept { return choices.empty(); }
  // The choices that give equal-weight points (all but weighted_choices), in order: what
  // `quadmc points` and the Python module's point_sets() list.
  std::vector<std::string_view> point_choices() const;
};

// The values given for a set's options, one per entry of its `options` (same order): the chosen
// value of a choice, "true" for a flag that is set, empty when not given (the default).
using point_set_values = std::span<const std::string_view>;

// What theory says about a set's sample mean with given options, in the terms of the rate
// building blocks of analysis/theoretical_rate.hpp, which this layer may not include: the
// methods layer turns it into a rate for an integrand class (methods/qmc.cpp).
enum class rate_basis {
  scrambled_net,    // Owen's rates for a scrambled (t, m, s)-net (docs/theory.md#scrambled-nets)
  broken_net,       // a net's points without the net property: `note` says why
  low_discrepancy,  // Koksma–Hlawka with the set's star discrepancy: `note`, `source`
  shifted_lattice,  // a randomly shifted rank-1 lattice, periodized as `periodization` says
  unproven,         // no rate proven: `note`, `source`
  // An order-α digital net by interlacing (`interlacing` = α ≥ 2), Owen-scrambled before
  // interlacing (`scrambled`) or deterministic/digitally shifted (docs/theory.md#interlaced-nets)
  interlaced_net,
};
struct point_set_theory {
  rate_basis basis = rate_basis::unproven;
  std::string note;  // scrambled_net, shifted_lattice: a prefix to the block's own note, if any
  std::string_view source;
  // shifted_lattice (docs/theory.md#lattice-periodizations): how the integrand is made periodic
  // — the periodization's name; the order k to which the integrand the rule sees has periodic
  // derivatives (−1: not periodic; 0 for the baker's map and c0, m − 1 for a Jacobian vanishing
  // to order m); and whether it is a weighted change of variables (c0 … c3sin) rather than a
  // map of the points.
  std::string_view periodization = "none";
  int periodic_order = -1;
  bool weighted = false;
  // The basis holds for s ≤ 2 only: a set padded across pairs of dimensions, whose pairs are
  // associated at random, has plain Monte Carlo's rate beyond (docs/theory.md#padded-jittered).
  bool padded = false;
  // interlaced_net: the order α and whether the αs-dimensional net was Owen-scrambled.
  unsigned interlacing = 1;
  bool scrambled = false;
};

// The transform whose coefficients a guaranteed stopping rule reads off an extensible set's
// values (estimators/stopping_rules.hpp): Walsh for a digital net, Fourier for a rank-1 lattice,
// none for a set with neither structure.
enum class coefficient_transform { none, walsh, fourier };

// The strata a set fills with exactly one point each, by construction: the k^s cells of a grid
// (`per_axis` = k), or N strata along every axis (a Latin hypercube's rows and columns).
enum class strata_kind { cells, rows_and_columns };
struct point_strata {
  strata_kind kind = strata_kind::cells;
  std::uint64_t per_axis = 0;
};
std::string_view to_string(strata_kind k) noexcept;

// Whether one run estimates its own error (σ̂²/N and its stratified variants), only independent
// replicates of the whole set can (randomized quasi-Monte Carlo:
// docs/theory.md#replicate-error-bars), or neither can (a deterministic set; cell centres that
// share one random shift): the methods report no error estimate then, and a stopping rule has
// nothing to size a sample from.
enum class error_source { own, replicates, none };

// The largest count ≤ N a set can hold in s dimensions, and its strata per axis k (0 for `any`).
struct point_count_choice {
  std::uint64_t per_axis = 0;
  std::uint64_t points = 0;
};
point_count_choice largest_point_count(point_count counts, std::uint64_t N, std::size_t s);

// The stream of one repetition: the scene's seed keys its generator (`rng`, Philox unless the
// scene names ARS), `stream` names the repetition (core/rng.hpp).
struct sample_stream {
  std::uint64_t seed = 0;
  std::uint64_t stream = 0;
  rng_kind rng = rng_kind::philox4x32_10;
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
  std::uint64_t max_points;   // the largest N (its tables' range); 0: 2^62, a random stream's
  // Whether the first N points of the sequence are a valid (if poorer) set for any N, although
  // its nets need N = 2^m: allow_any_n and the unrandomized sequence then take N as it is.
  bool takes_any_prefix;
  std::span<const point_set_option> options;  // its own keys, in listing order

  // The options `values` (one per entry of `options`, checked against its choices) configure.
  point_set_options (*options_from)(point_set_values values);
  // The rate theory gives the set's sample mean with these options; nullptr for a set whose
  // methods state it themselves (methods/point_set_methods.cpp).
  point_set_theory (*theory_over)(const point_set_options& options);
  // The strata of n points in s dimensions (with the default options), if it has them.
  std::optional<point_strata> (*strata_over)(std::size_t s, std::uint64_t n);

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
  // f·vol at points first … first + y.size() − 1 of the set built for n_cap points, for the
  // stopping rules that double N and keep what they spent (estimators/stopping_rules.hpp);
  // nullptr for a set whose 2N points are not its N points and N more (jittered, Latin
  // hypercube: their strata change with N). `transform_order`: Sobol' values in natural-index
  // order (the Walsh transform's), which the run [0, 2^k) or [2^k, 2^(k+1)) permutes; the lattice
  // is in radical-inverse order either way (sampling/rank1_lattice_sequence.hpp).
  void (*extension_over)(const any_integrand& f, const point_set_options& options,
                         const sample_stream& stream, std::uint64_t n_cap, std::uint64_t first,
                         std::span<double> y, unsigned threads, bool transform_order) = nullptr;
  coefficient_transform coefficients = coefficient_transform::none;

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
  bool extensible() const noexcept { return extension_over != nullptr; }
  void extension_values(const any_integrand& f, const sample_stream& stream, std::uint64_t n_cap,
                        std::uint64_t first, std::span<double> y, unsigned threads,
                        bool transform_order, const point_set_options& options = {}) const {
    extension_over(f, options, stream, n_cap, first, y, threads, transform_order);
  }

  // The option keyed `key`, or nullptr.
  const point_set_option* option(std::string_view key) const noexcept;
  point_set_options options_of(point_set_values values) const { return options_from(values); }
  std::optional<point_set_theory> theory_of(const point_set_options& options) const {
    if (theory_over == nullptr) return std::nullopt;
    return theory_over(options);
  }
  std::optional<point_strata> strata_of(std::size_t s, std::uint64_t n) const {
    return strata_over(s, n);
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

class file_points;  // sampling/point_file.hpp

// The importance and irradiance estimators of the entries, over a file's points instead of a
// catalogue set (point_set = "external_points" of those methods): the same kernels in the same
// chunks, so the points of a set, read back from a file, give the bits of that set's own
// estimator.
estimate importance_over_file(const any_integrand& f, const unit_warp& warp,
                              const file_points& points, unsigned threads);
estimate irradiance_over_file(irradiance_sampling technique, const irradiance_setup& setup,
                              const file_points& points, unsigned threads);

// Every set, in listing order.
std::span<const point_set_entry> point_set_catalogue() noexcept;
// The entry named `name`, or nullptr.
const point_set_entry* find_point_set(std::string_view name) noexcept;
// Comma-separated names, for "expected one of …" messages.
std::string point_set_names();
// `zsobol`, the render-only set (sampling/zsobol_points.hpp; docs/theory.md#z-ordered-sobol): not
// in the catalogue, since a pixel's points depend on where the pixel is and there are no points
// of one integral to give: its estimators and points() throw invalid_argument saying so.
// estimate_irradiance_pixels (estimators/irradiance_image.hpp) draws its images.
const point_set_entry& zsobol_render_set() noexcept;

// One option a caller names by key (`quadmc points`' flags, the Python module's keywords), as
// text: a choice's name, "true" for a flag that is set, empty for one left at its default.
struct named_option {
  std::string_view key;
  std::string_view value;
};
// The options `given` configure, every key and choice checked against the set's own: a key the
// set lacks (given with any value) is invalid_argument naming the sets that have it, a choice it
// lacks one naming the choices it has, and a weighted choice (the lattice's c0 … c3sin: no
// equal-weight points to give) one saying why and naming the choices its points take. Keys are
// checked before values. `parameter` is the name an error gives a key (the command's --allow-any-n,
// the module's allow_any_n).
point_set_options checked_options(const point_set_entry& set, std::span<const named_option> given,
                                  std::string (*parameter)(std::string_view key));

// Whether the set can hold exactly n points in s dimensions (with these options).
bool accepts_size(const point_set_entry& set, std::size_t s, std::uint64_t n,
                  const point_set_options& options = {});
// The largest N a set holds (2^32 for Sobol', 2^20 for the lattice), else 2^62.
std::uint64_t max_point_count(const point_set_entry& set, const point_set_options& options = {});
// "s ≤ 3667 for the sobol points, got s = 3668" for a dimension beyond the set's tables, or empty
// (size_problem begins with it; a caller that names its parameters blames s, not N, for it).
// With interlacing α > 1 the tables must hold α·s dimensions: "α·s ≤ 3667 …" names s, α and the
// limit.
std::string dimension_problem(const point_set_entry& set, std::size_t s,
                              const point_set_options& options = {});
// "owen, shift or none with interlacing = 2 (fast_owen …)" for a randomization an interlaced set
// (interlacing > 1) refuses, or empty (docs/theory.md#interlaced-nets).
std::string interlacing_problem(const point_set_entry& set, const point_set_options& options);
// "N = 2^m required: nearest valid sizes 512 and 1024"-style text for a count a set cannot hold,
// or empty when it can.
std::string size_problem(const point_set_entry& set, std::size_t s, std::uint64_t n,
                         const point_set_options& options = {});

}  // namespace quadmc
