// A validated scene: what an experiment file asks for, in C++ types, before any planning.
//
// Use it as the output of parse_scene (parse.hpp) and the input of make_plan (plan.hpp). It
// holds the values exactly as the file gives them, plus where each came from, so that later
// checks (the integrand catalogue's, the plan's impossible pairings) can still name the file,
// line and key. It does not hold defaults the plan derives (drawn parameters, mapped counts).
#pragma once

#include "quadmc/methods/method.hpp"
#include "quadmc/scene/scene_error.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

// Positions of the keys of one table, by key name, for messages raised after parsing.
using key_locations = std::map<std::string, source_location, std::less<>>;

// Where an integrand's errors are measured from (docs/theory.md#references-without-a-closed-form):
// the family's exact value, a value the scene gives (`reference = 1.23`, with
// `reference_uncertainty`), or one make_plan computes (`reference = "computed"`).
enum class reference_source { exact, given, computed };

// One integrand of the scene. A [[integrand]] table with `dimensions = [1, 2, 4]` becomes one
// integrand_spec per s, all with the same table_index.
struct integrand_spec {
  std::string name;       // display name, unique in the scene (e.g. "genz_gaussian_s3")
  std::string base_name;  // the table's `name`, or its family; shared by a `dimensions` expansion
  std::string family;     // catalogue name
  std::size_t dimension = 1;  // 0 after parsing = the family's default; make_plan resolves it
  std::size_t ensemble = 1;   // K instances drawn from the scene seed, results averaged
  bool ensemble_given = false;
  reference_source reference = reference_source::exact;
  // reference_source::given: the value and its absolute uncertainty (≥ 0) as the file gives them.
  double reference_value = std::numeric_limits<double>::quiet_NaN();
  double reference_uncertainty = 0.0;
  // Family parameters passed through to the catalogue: numbers → scalars, arrays → vectors,
  // strings → strings.
  std::map<std::string, double, std::less<>> scalars;
  std::map<std::string, std::vector<double>, std::less<>> vectors;
  std::map<std::string, std::string, std::less<>> strings;

  std::size_t table_index = 1;  // 1-based number of its [[integrand]] table in the file
  source_location table;        // the [[integrand]] header
  key_locations keys;
};

// One [[method]] of the scene: the keys every method has, and the method itself as its
// descriptor configured it from the table's other keys (methods/method.hpp).
struct method_spec {
  std::string name;   // a name of methods/registry.hpp
  std::string label;  // display name, unique in the scene (default: name + label_suffix())
  std::shared_ptr<const method> configured;
  std::uint64_t repetitions = 32;  // randomized methods: independent runs per cell
  bool repetitions_given = false;
  cell_control control = cell_control::fixed_size;
  std::vector<double> tolerances;  // control = tolerance: the targets, decreasing
  // tolerance_kind = "relative": each tolerance is a fraction of |I| (1e-6: six correct digits),
  // the absolute target of a cell being tolerance·|I| of its instance; "absolute" (default):
  // the tolerances are errors.
  bool relative_tolerance = false;
  std::vector<std::string> integrands;  // restriction to these integrand names; empty = all

  std::size_t table_index = 1;  // 1-based number of its [[method]] table
  source_location table;
  key_locations keys;

  method_kind kind() const { return configured->kind(); }
};

struct budget_spec {
  std::vector<std::uint64_t> N;                  // nominal evaluation counts, increasing
  std::optional<std::uint64_t> max_evaluations;  // per cell: evaluations × repetitions
  std::optional<double> max_seconds;             // whole run; enforced by the runner
  // Stable timing (analysis/cell_timing.hpp): each cell's first estimate is repeated until at
  // least this many seconds have passed; 0 = time the first call once. 10 ms: batches of ~1 ms,
  // a thousand times the clock's resolution and cost, and ≈ 11 s over the default scene's cells.
  double timing_min_seconds = 0.01;
  // Paired timing (scene/paired_timing.hpp): after the run, each time-to-error cell's two winners,
  // quadmc's best and the best peer, are timed again alternately this many rounds, one stable
  // timing each per round, and the page's ratio is the median of the rounds' ratios. 0 = off;
  // else at least min_paired_timing_rounds (valid_paired_timing_rounds). Only scenes whose page
  // has a time-to-error table with both sides pay for it.
  std::uint64_t paired_timing_rounds = 5;
  source_location N_location;
  source_location paired_timing_rounds_location;  // where the file set it (line 0: not set)
};

// budget.paired_timing_rounds: 0 (off) or min…max rounds. Five at least: the median of fewer
// alternating runs is moved by one disturbed round, which is what pairing is meant to outvote; at
// most 1000 (each round is two stable timings of at least timing_min_seconds).
inline constexpr std::uint64_t min_paired_timing_rounds = 5;
inline constexpr std::uint64_t max_paired_timing_rounds = 1000;
inline constexpr std::string_view paired_timing_rounds_expected =
    "0 (off) or a whole number of rounds from 5 to 1000";
constexpr bool valid_paired_timing_rounds(std::uint64_t rounds) noexcept {
  return rounds == 0 || (rounds >= min_paired_timing_rounds && rounds <= max_paired_timing_rounds);
}

struct output_spec {
  bool csv = true;
  bool markdown = true;
  bool plots = true;
};

struct scene {
  std::string file;  // as given to the parser; prefixes every message
  std::string name;
  std::string description;
  std::uint64_t seed = 0;
  // `rng`: the generator of the methods' random streams (Philox unless the scene names ARS).
  rng_kind rng = rng_kind::philox4x32_10;
  unsigned threads = 0;  // 0 = all cores
  std::vector<integrand_spec> integrands;
  std::vector<method_spec> methods;
  budget_spec budget;
  output_spec output;
};

}  // namespace quadmc
