// A method of the suite as a scene names it: the descriptor (name, kind, options, controls, how
// to configure one) and the configured method (how a scene's N becomes its size, which integrands
// it takes, its theoretical rate, how it runs one cell).
//
// Use it to add a method: one class deriving from `method`, one descriptor in its family's table
// (lib/src/methods/<family>.cpp) — nothing else in the library names it. The scene parser, the
// planner, the runner and `quadmc list` ask these two types and never compare method names
// (the shape of pbrt-v4's Sampler::Create: look the name up once, let the type read its own
// parameters). Not for the kernels themselves (rules/, estimators/): a method is the thin layer
// that chooses a kernel, its size and its theory.
//
// Controls (docs/design.md#layers): a cell is run at a fixed size (rules, Monte Carlo: the N
// ladder mapped to the method's sizes), with an evaluation budget (an adaptive method may spend
// up to N), or to a tolerance (the method stops when its own error estimate is below it). Every
// cell records the evaluations it really spent and, where the method has one, its own error
// estimate.
#pragma once

#include "quadmc/analysis/cell_statistics.hpp"
#include "quadmc/analysis/error_prediction.hpp"
#include "quadmc/analysis/theoretical_rate.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/functions/any_integrand.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/methods/option_reader.hpp"

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

enum class method_kind {
  deterministic,  // one run per cell; repetitions do not apply
  randomized,     // `repetitions` independent runs per cell, each on its own random stream
};

enum class cell_control {
  fixed_size,  // "fixed": N is mapped to a size the method uses exactly
  budget,      // "budget": N is the most the method may spend; it may stop earlier
  tolerance,   // "tolerance": the method runs until its error estimate is below the target
};
std::string_view to_string(cell_control control) noexcept;

// What the plan decided for one cell. Exact integers throughout: N → grid arithmetic never
// rounds (core/integer_powers.hpp).
struct cell_size {
  std::uint64_t evaluations = 0;      // per repetition (budget, tolerance: the most it may spend)
  std::uint64_t per_axis = 0;         // rules: panels n; stratified points: strata k; else 0
  std::uint64_t points_per_axis = 0;  // rules: nodes per axis p(n); else 0
  int order = 0;                      // rules: r of this grid, |error| = O(n^−r); else 0
  int level = -1;                     // sparse grids: the Smolyak level L; −1 otherwise
};

// A size for a nominal N, or why none fits (a plan skip, e.g. "N is below the smallest grid").
struct sizing {
  std::optional<cell_size> size;
  std::string reason;
};

// What a method may ask of an integrand before it is run.
struct integrand_traits {
  std::string_view family;  // catalogue name
  std::size_t s = 1;
  bool rendering = false;  // an irradiance integrand (catalogue_entry::rendering)
};

struct run_context {
  std::uint64_t seed = 0;  // the scene's seed: the key of every random stream
  unsigned threads = 1;    // as many as may be used; results do not depend on it
  // The scene's `rng`: the generator of every random stream a method draws (core/rng.hpp).
  rng_kind rng = rng_kind::philox4x32_10;
};

// One cell to run: the integrand instance, its size, and the stream of this repetition.
struct method_cell {
  const any_integrand& function;
  const integrand_params& params;  // what the instance was built from (irradiance geometry)
  const cell_size& size;
  cell_control control = cell_control::fixed_size;
  double tolerance = std::numeric_limits<double>::quiet_NaN();  // control = tolerance only
  std::uint64_t stream = 0;
  std::uint64_t repetition = 0;  // r, 0 … repetitions − 1 (the realization of a file's points)
};

// Why a configured method cannot run under a control: the key to blame and the message.
struct control_refusal {
  std::string key;
  std::string message;
};

struct method_descriptor;

// A [[method]] as configured by its table. Immutable after creation, so one object serves every
// cell and thread.
class method {
 public:
  explicit method(const method_descriptor& descriptor) noexcept : descriptor_(&descriptor) {}
  method(const method&) = delete;
  method& operator=(const method&) = delete;
  virtual ~method() = default;

  const method_descriptor& descriptor() const noexcept { return *descriptor_; }

  // Deterministic or randomized as configured: the descriptor's kind, unless an option removes
  // the randomness (a quasi-Monte Carlo set with randomization = "none" runs once per cell).
  virtual method_kind kind() const;

  // Where a cell's error bars come from (analysis/cell_statistics.hpp): each repetition's own
  // std_error and error estimate, or the spread of the repetitions when one run cannot estimate
  // its own error (randomized quasi-Monte Carlo: docs/theory.md#replicate-error-bars).
  virtual quadmc::error_bars error_bars() const;

  // Appended to the name for the default label: "_naive" (an accumulator), "_power" (a warp),
  // "_jittered" (a point set), so two configurations of one method get two series.
  virtual std::string label_suffix() const { return {}; }

  // Why the method cannot integrate such an integrand (a plan skip; an error when the scene pairs
  // them explicitly), or nullopt.
  virtual std::optional<std::string> incompatibility(const integrand_traits& f) const;

  // The size for nominal N in s dimensions.
  virtual sizing size_for(std::uint64_t N, std::size_t s) const = 0;

  // The size of a cell run to a tolerance within `budget` evaluations per repetition (what a
  // stopping rule may spend), or why the budget cannot hold it; by default size_for(budget).
  virtual sizing tolerance_size_for(std::uint64_t budget, std::size_t s) const {
    return size_for(budget, s);
  }

  // Why the method, as its table configured it, cannot run under `control` (keys that belong to
  // another control, a control its options leave no rule for); nullopt when it can. The scene
  // parser and quadmc.integrate fail with it before any plan.
  virtual std::optional<control_refusal> refuses(cell_control) const { return std::nullopt; }

  // Explicit sizes replacing the ladder (the rules' `panels`), each as a size; empty when the
  // method follows budget.N.
  virtual std::vector<sizing> explicit_sizes(std::size_t s) const;
  // The [[method]] key those sizes come from ("panels" per axis for a rule, "points" for a
  // quasi-Monte Carlo set), for the plan's note; empty when the method has none.
  virtual std::string explicit_sizes_key() const { return {}; }

  // The convergence rate theory predicts on f (analysis/theoretical_rate.hpp).
  virtual theoretical_rate theory(const integrand_class& f) const = 0;

  // An a-priori bound on |error| of a fixed-size cell on f (a rule on a jump:
  // rules/jump_error_envelope.hpp); NaN when the method has none for f.
  virtual double error_envelope(const integrand_info& f, const cell_size& size) const;

  // The predicted error of its fixed-size cells on f, cell by cell (a composite rule on f with
  // known end-point derivatives: its Euler–Maclaurin expansion, rules/euler_maclaurin.hpp), or
  // nullopt when it has none.
  virtual std::optional<error_prediction> predict_error(const integrand_info& f) const;

  // How the method adds its terms, which sets its rounding floor (analysis/rounding_floor.hpp):
  // the rules' `accumulator`; pairwise for every other method.
  virtual summation summation_scheme() const { return summation::pairwise; }

  // Whether a cell of this method, run by the K processes of an MPI run together (a split cell,
  // bench/quadmc/mpi_run.hpp), costs each of them about 1/K of its work: every reduction of its
  // run is a parallel_reduce whose chunk result is all that a chunk computes
  // (shareable_chunk_result, core/chunk_exchange.hpp) or a left-to-right sum split exactly
  // (core/split_naive_sum.hpp). False (the default): the work is done whole on every process
  // that runs the cell — chunks that write on the side, a serial method — so the planner gives such
  // a cell to one process instead of splitting it. An override returns what its kernels declare
  // (rules/weighted_sum.hpp, estimators/sample_mean.hpp), not a list of names;
  // tests/methods/method_test.cpp runs every registered method under a two-process exchange and
  // counts each process's evaluations, so a declaration that disagrees with its kernel fails there.
  virtual bool shares_chunks() const { return false; }
  // The same for its cells under `control`: by default shares_chunks(). A cell run to a
  // tolerance by a rule that keeps every value (estimators/sample_values.hpp) computes them all
  // on every process, whatever the method's fixed-size kernel does.
  virtual bool shares_chunks_at(cell_control) const { return shares_chunks(); }

  // Checks, before any work, every input a cell of this size in s dimensions would read over
  // its repetitions (the point files of methods/external.cpp); throws invalid_argument naming
  // the file. The plan calls it for every cell; by default there is nothing to check.
  virtual void check_inputs(std::size_t s, const cell_size& size, std::uint64_t repetitions) const;

  // One repetition of one cell. Throws what the kernels throw (invalid_argument,
  // non_finite_value naming the point).
  virtual repetition_result run(const method_cell& cell, const run_context& context) const = 0;

  // Measures of the repetition's points that are not part of its cost (the discrepancies of a
  // quasi-Monte Carlo set), added to `result` after the timed run; by default none.
  virtual void measure_points(const method_cell& cell, const run_context& context,
                              repetition_result& result) const;

 private:
  const method_descriptor* descriptor_;
};

// One option key of a method, for `quadmc list`, the README and unknown-key messages.
struct option_doc {
  std::string_view key;
  std::string_view meaning;  // values, default and constraints, one line
};

struct method_descriptor {
  std::string_view name;
  std::string_view description;  // one line
  method_kind kind;
  std::span<const option_doc> options;     // its own keys, beyond the ones every method has
  std::span<const cell_control> controls;  // the controls it supports; the first is its default
  // Reads the method's own options from its [[method]] table (the reader refuses the rest).
  std::unique_ptr<const method> (*create)(const method_descriptor& self, option_reader& options);

  bool supports(cell_control control) const noexcept;
};

}  // namespace quadmc
