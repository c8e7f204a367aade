// The plan of a scene: every cell the runner will execute and everything it skips, with why.
//
// Use make_plan after parse_scene, and format_plan for `quadmc plan scene.toml`; the runner
// (scene/run.hpp) executes plan::cells in order. The plan holds only what the scene names
// (docs/design.md#skip-what-a-scene-does-not-need):
//  - a deterministic rule runs once per N (its repetitions are 1; a `repetitions` key on it is
//    ignored with a note);
//  - N is mapped to a count the method can use (methods.hpp): the largest tensor grid with
//    p(n)^s ≤ N, or k^s strata for jittered points; `evaluations` is the real count;
//  - an N that gives the same grid or strata as a smaller N is skipped ("same grid as N = …"),
//    as is a grid smaller than N allows for no grid at all;
//  - a cell whose evaluations × repetitions exceed budget.max_evaluations is skipped;
//  - a method that cannot integrate an integrand is skipped for it (an error when the scene
//    pairs them explicitly, parse.hpp);
//  - outputs the scene turned off are listed as skipped.
// make_plan also builds every integrand instance through the catalogue, so a family or a
// parameter the catalogue rejects is a scene_error naming the file, line and key.
//
// Everything a run would refuse is refused here, before any work, as a scene_error at the key
// concerned: an exact integral (or an ensemble's mean of them) that is not finite, or a largest
// value max|f| that overflows; a random cell whose point set cannot hold N·s ≥ 2^62 counters
// (sampling/point_set.hpp), at budget.N; and values too large for the run's statistics: a Monte
// Carlo estimate sums N values and N squared deviations of Y = f·volume, so 8·M²·N must stay below
// DBL_MAX, M = max(|I|, max|f|·volume) (≈ 1.5e146 at N = 2^53, 4.7e153 at N = 1); a rule's error
// est − I needs 4·M ≤ DBL_MAX. The plan's own size is bounded (plan_limits), also checked before
// anything is built, so no scene makes planning itself take unbounded time or memory.
#pragma once

#include "quadmc/functions/any_integrand.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/scene/computed_reference.hpp"
#include "quadmc/scene/scene.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace quadmc {

// Bounds on what one scene may make the planner build (parse.hpp bounds the file itself).
struct plan_limits {
  // Ensemble instances over all integrands, and instances × s: each instance holds its box and
  // parameters (about 64 bytes per coordinate), so 2^20 coordinates are ≈ 64 MiB.
  static constexpr std::size_t max_instances = 65536;
  static constexpr std::uint64_t max_coordinates = std::uint64_t{1} << 20;
  // Terms of the 2^s-vertex closed forms (genz_corner_peak, half_space) summed while building
  // the instances, ≈ 1.4 µs each in 50-digit arithmetic: 2^24 is about 25 s of planning.
  static constexpr std::uint64_t max_reference_terms = std::uint64_t{1} << 24;
  // Cells (integrands × methods × N values × ensemble instances), and as many skips at most.
  static constexpr std::uint64_t max_cells = std::uint64_t{1} << 20;
  // Σ repetitions over the cells: the runner keeps one 40-byte result per repetition (1.25 GiB).
  static constexpr std::uint64_t max_repetitions = std::uint64_t{1} << 25;
  // What a cell run to a tolerance may spend per repetition when the scene sets no
  // budget.max_evaluations: 2^30 evaluations, seconds to minutes of a cheap integrand.
  static constexpr std::uint64_t default_tolerance_budget = std::uint64_t{1} << 30;
};

// One instance of one integrand of the scene (an ensemble of K has K of them).
struct plan_instance {
  std::size_t integrand = 0;  // index into scene::integrands
  std::size_t instance = 0;   // k, 0 … ensemble − 1
  std::uint64_t seed = 0;     // params.seed = stream_id({scene seed, integrand, k})
  integrand_params params;    // what make_integrand was given (dimension resolved)
  any_integrand function;
  // Parameters not given in the file and drawn from `seed` (Genz a, u), with their values.
  std::map<std::string, std::vector<double>, std::less<>> drawn;
};

struct plan_cell {
  std::size_t integrand = 0;    // index into scene::integrands
  std::size_t instance = 0;     // ensemble instance k
  std::size_t method = 0;       // index into scene::methods
  std::size_t dimension = 1;    // s
  std::uint64_t nominal_N = 0;  // from budget.N, or p(n)^s for explicit panels; 0 for a
                                // cell run to a tolerance
  cell_control control = cell_control::fixed_size;
  double tolerance = std::numeric_limits<double>::quiet_NaN();  // control = tolerance only
  std::uint64_t per_axis = 0;         // rules: panels n per axis; jittered-like: strata k per axis;
                                      // 0 when the points have no grid
  std::uint64_t points_per_axis = 0;  // rules: nodes per axis p(n); 0 otherwise
  std::uint64_t evaluations = 0;      // per repetition: exact, or the most a budget or
                                      // tolerance cell may spend
  std::uint64_t repetitions = 1;      // 1 for deterministic rules
  int order = 0;                      // rules: r, |error| = O(n^-r); 0 for random methods
  int level = -1;                     // sparse grids: the Smolyak level L; −1 otherwise
  // Names the cell's random streams: the runner appends (repetition, chunk) and calls
  // quadmc::stream_id with the scene seed as the Philox key.
  // {name_id(integrand name), instance, name_id(method label), nominal_N}, never positions in
  // the scene; a tolerance cell has the tolerance's bits for N.
  std::array<std::uint64_t, 4> stream_parts{};

  cell_size size() const noexcept { return {evaluations, per_axis, points_per_axis, order, level}; }
};

struct plan_skip {
  std::string what;    // e.g. "simpson × genz_gaussian_s8, N = 256"
  std::string reason;  // e.g. "same grid as N = 64 (n = 2 per axis, 6561 evaluations)"
};

// Where one integrand's errors are measured from (integrand_spec::reference): the family's exact
// value, or a given or computed one with its absolute uncertainty, below 10 times which an error
// is a floor point (docs/theory.md#references-without-a-closed-form).
struct plan_reference {
  reference_source source = reference_source::exact;
  double value = std::numeric_limits<double>::quiet_NaN();  // plan::mean_reference's entry
  double uncertainty = 0.0;                                 // 0 for the exact value
  std::optional<computed_reference> computed;               // source = computed: how
  // "given, ± 1e-12" or "computed: tanh-sinh (Boost.Math), …"; empty for the exact value.
  std::string describe() const;
};

struct plan {
  scene source;  // the scene it was made from, with every integrand's dimension resolved
  std::vector<plan_instance> instances;  // ordered by (integrand, instance)
  // Per integrand of the scene: Ī, the mean of its instances' exact integrals (the series'
  // reference; run.hpp shifts each instance's estimates by Ī − I_k).
  std::vector<double> mean_reference;
  // Per integrand: where mean_reference's entry comes from (a given or computed reference
  // replaces the exact value there, and the runner then shifts nothing).
  std::vector<plan_reference> references;
  std::vector<plan_cell> cells;  // ordered by (integrand, instance, method, N)
  std::vector<plan_skip> skips;
  std::vector<std::string> notes;       // ignored keys and other remarks
  std::uint64_t total_evaluations = 0;  // Σ evaluations × repetitions (saturates at 2^64 − 1)

  const plan_instance& instance_of(const plan_cell& c) const;
  // I of one instance, as its errors and a relative tolerance see it: the family's exact value,
  // or the given or computed reference that replaces it (the family may have none, NaN).
  double reference_of(const plan_instance& inst) const;
};

plan make_plan(const scene& s);

// Human-readable listing for `quadmc plan`: the cells (integrand, s, method, N, n per axis,
// evaluations, repetitions), each skip with its reason, the notes, and the drawn parameters of
// integrands whose parameters came from the seed.
std::string format_plan(const plan& p);

}  // namespace quadmc
