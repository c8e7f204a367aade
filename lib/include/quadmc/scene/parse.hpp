// Reading a scene file (TOML, via toml++ 3.3) into a validated quadmc::scene.
//
// Use parse_scene_file for files and parse_scene for text held in memory (tests, stdin). Every
// problem is a quadmc::scene_error whose message is one line "file:line:column: key 'k': …".
// The parser checks everything that does not need the integrand catalogue: syntax, unknown keys,
// types, ranges, and the combinations the scene itself makes impossible. make_plan (plan.hpp)
// then asks the catalogue about families and their parameters and checks method × integrand
// pairings, with the same error format. Source: TOML v1.0.0, https://toml.io/en/v1.0.0.
//
// ---------------------------------------------------------------------------------------------
// Scene file reference (copied into the README)
// ---------------------------------------------------------------------------------------------
// Top level
//   name = "example"      results go to results/<name>/; letters, digits, '_', '-', '.'.
//                         Optional: defaults to the file name without extension.
//   description = "…"     optional free text, printed as Markdown under the title of the results
//                         folder's README.md (not in the CSV files).
//   seed = 42             integer ≥ 0 (default 0): the key of every random stream of the run.
//   threads = 2           integer 0…4096 (default 0 = all cores). Results do not depend on it.
//
// [[integrand]]           one table per integrand (at least one)
//   family = "genz_gaussian"  required; any name `quadmc list` prints.
//   dimension = 3             s, 1…1024; or
//   dimensions = [1, 2, 4, 8] shorthand: one integrand per s (same parameters, own name).
//                             At most one of the two; neither = the family's default s (1 for
//                             the 1D classics, 2 for the irradiance integrands).
//   name = "g"                display name (unique, ≤ 128 characters). Default:
//                             "<family>_s<s>" ("<family>" when s is the family default); with
//                             `dimensions`, "<name>_s<s>".
//   ensemble = 16             K ≥ 1 (default 1): K random instances of the family, drawn from the
//                             scene seed (instance k gets seed stream_id({seed, integrand, k}));
//                             errors are averaged over the ensemble. Parameters given explicitly
//                             are shared by every instance; the others are drawn per instance.
//                             make_plan bounds Σ K (65536) and Σ K·s (2^20) over the scene.
//   reference = 0.7468        the value every error is measured from instead of the family's
//                             exact one (a finite number), or "computed": make_plan computes it
//                             (scene/computed_reference.hpp, s ≤ 10). Not with ensemble > 1,
//                             nor as a number with a `dimensions` list of several s.
//   reference_uncertainty = 1e-12  with a number `reference` only: its absolute uncertainty
//                             (≥ 0, default 0). Errors below 10 times it are floor points
//                             (docs/theory.md#references-without-a-closed-form).
//   a = [1.0, 2.0, 0.5]       any other key is a family parameter, passed to the catalogue:
//   u = [0.3, 0.6, 0.45]      a number → scalar, an array of numbers → vector (length s where
//   cut = [1, 2]              the family says so), a string → string (one of the key's choices,
//   coefficient_decay =       e.g. Genz coefficient_decay). Omitted ones are drawn from the seed
//     "quadratic"             and the plan prints the values drawn. The catalogue rejects
//                             unknown keys, wrong kinds and strings outside the choices.
//
// [[method]]              one table per method (at least one). The keys every method has:
//   name = "midpoint"     required; a method of methods/registry.hpp (`quadmc list` prints them
//                         with their own keys, which their descriptors read and check).
//   label = "midpoint_a"  display name (unique, ≤ 128 characters); needed when one method
//                         appears twice. Default: the name plus what the options add, e.g.
//                         "_<accumulator>", "_<warp>", "_<point_set>" (method::label_suffix).
//   integrands = ["g"]    restrict the method to these integrands (display names, or the
//                         `name` of a `dimensions` table for all its expansions). Default: all.
//   repetitions = 64      randomized methods: independent runs per cell, 1…10^9 (default 32),
//                         at most 2^25 over all cells (the runner keeps each result). A
//                         deterministic method runs once per cell; the plan notes the key is
//                         ignored.
//   control = "fixed"     how its cells run, one the method supports (`quadmc list`; the first
//                         it lists is its default): "fixed" (N mapped to a size used exactly),
//                         "budget" (N is the most it may spend), "tolerance" (until its own
//                         error estimate is at most each of `tolerances`).
//   tolerances = [1e-3, 1e-6]   control = "tolerance" only, required there: absolute errors,
//                         positive and decreasing, ≤ 256. Each is a cell that may spend
//                         budget.max_evaluations (shared by the repetitions), else 2^30
//                         evaluations per repetition.
// The methods' own keys, e.g. `panels` and `accumulator` of the tensor rules, `m` of
// gauss_legendre, `warp` and `point_set` of importance, `point_set` of the irradiance estimators:
//   panels = [2, 4, 8]    explicit n per axis (an integer or an increasing list of ≤ 256),
//                         replacing budget.N for this method; even for Simpson.
//   m = 3                 Gauss–Legendre nodes per panel, one of 2 3 4 5 7 10 15 20 25 30.
//   point_set = "jittered"  the pattern of the uniform points fed to the warp (a name of
//                         estimators/point_set_catalogue.hpp, independent by default); counts
//                         are mapped as for the method over that set (N → k^s for jittered).
//   warp = "power"        importance (required): a 1D density on [0,1], so s = 1 only;
//   warp = { name = "power", exponent = 2.0 }      p(x) = (k+1) x^k, −1 < k ≤ 1e5 (default 1)
//   warp = { name = "exponential", rate = 1.0 }    the truncated exponential on [0,1] (C++
//                         truncated_exponential_warp): p(x) = λ e^{λx}/(e^λ − 1), 0 < |λ| ≤ 700
//                         (default 1). Beyond these the warp is not accurate: every sample of
//                         x^k rounds to 1 for k ≳ 1e16, and e^λ overflows above 709.78
//                         (sampling/inversion_warps.hpp derives both bounds).
//
// [budget]                required
//   N = [64, 256, 1024]   nominal evaluation counts, strictly increasing, 1…2^53; or
//   N = { from = 64, to = 1048576, factor = 4 }   geometric: from·factor^k ≤ to (factor > 1, may
//                         be fractional: values are rounded and repeats dropped). ≤ 256 values,
//                         reached in ≤ 4096 steps k (factor ≥ (to/from)^(1/4096)).
//                         Each method maps N to a count it can use (plan.hpp).
//   max_evaluations = 1e8 per cell, evaluations × repetitions; cells above it are skipped with
//                         the reason. An integer or an integral float (1e8). Default: no limit.
//   max_seconds = 600     whole run, positive; the runner stops starting new cells after it.
//   timing_min_seconds = 0.01   stable timing per cell (analysis/cell_timing.hpp): the first
//                         estimate is repeated until this much time has passed; 0 ≤ value ≤ 60,
//                         0 = the first call timed once. Default 0.01.
//   paired_timing_rounds = 5   paired timing (scene/paired_timing.hpp): where the page has a
//                         time-to-error table (tolerance cells and `peer_*` methods), each cell's
//                         quadmc best and best peer are timed again after the run, alternately
//                         (quadmc, peer, quadmc, peer, …), this many rounds of one stable timing
//                         each; the page's ratio is the median of the rounds' ratios, with their
//                         min–max. An integer, 0 (off) or 5…1000. Default 5.
//
// [output]                optional; which files to write (each default true)
//   csv = true, markdown = true, plots = true     plots are drawn from the CSV: plots = true
//                         with csv = false is an error (at output.plots).
//
// Limits (scene_limits below; plan.hpp's plan_limits bound what make_plan builds). Each is an
// error naming the key, never a silent cut, and keeps the work and memory of parsing bounded
// whatever the file's numbers say:
//   the file              at most 1 MiB, a regular file or a pipe (not /dev/zero, a terminal, a
//                         folder); read with a bounded loop, never past the limit.
//   nesting               at most 64 levels, counted before toml++ parses (it recurses per
//                         level): each part of a dotted key or table header and each array or
//                         inline table is one; a scene needs 4.
//   names                 integrand `name`s and method `label`s at most 128 characters (they
//                         become file names); `family` at most 128.
//   [[integrand]]         at most 32 keys per table; a parameter array at most 1024 numbers;
//                         4096 integrands in all after `dimensions` expand.
//   [[method]]            at most 1024 tables; `panels` and `integrands` lists at most 256 and
//                         4096 entries.
//   budget.N              at most 256 values (list or range), a range at most 4096 steps.
// make_plan (plan.hpp) then refuses, at the key concerned and before any work, what a run would
// refuse after it: an exact integral or a largest value max|f| beyond double's range, values too
// large for the run's sums of squares, a random cell with N·s > 2^62 (at budget.N), and plans of
// more than 2^20 cells or 2^25 repetitions in all.
//
// Pairings: a method that cannot integrate an integrand (romberg or importance with s ≠ 1, an
// irradiance estimator on a non-rendering integrand) is skipped for it, with the reason in the
// plan. It is an error only when the method's `integrands` list names an integrand none of
// whose expansions it can integrate: then the scene asks for something impossible.
// ---------------------------------------------------------------------------------------------
#pragma once

#include "quadmc/scene/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace quadmc {

// The parser's bounds (see "Limits" above): whatever a file says, parsing it costs work and
// memory in proportion to these, never to what the file's numbers ask for.
struct scene_limits {
  static constexpr std::size_t max_file_bytes = std::size_t{1} << 20;  // 1 MiB
  static constexpr std::size_t max_nesting = 64;
  static constexpr std::size_t max_name_length = 128;
  static constexpr std::size_t max_integrands = 4096;  // after `dimensions` expansion
  static constexpr std::size_t max_integrand_keys = 32;
  static constexpr std::size_t max_methods = 1024;
  static constexpr std::size_t max_ladder = 256;           // N values, panel counts
  static constexpr std::uint64_t max_ladder_steps = 4096;  // k of from·factor^k
  static constexpr std::size_t max_dimension = 1024;
};

// The keys the parser accepts in each table of a scene, exactly as it checks them: `table` is ""
// for the top level, "integrand", "method", "budget", "output", or "budget.N" for the range
// { from, to, factor }. A method's own keys are its descriptor's `options` (methods/registry.hpp)
// and an integrand's family parameters its catalogue entry's keys (functions/catalogue.hpp), so
// with those this is every key a scene may hold (`quadmc list` and the README test read it).
struct scene_table_keys {
  std::string_view table;
  std::span<const std::string_view> keys;
};
std::span<const scene_table_keys> scene_keys() noexcept;

// `file_name` is used in messages only (and as the default scene name).
scene parse_scene(std::string_view toml_text, std::string_view file_name);

// Whether `name` may be a folder or file name part of results/: letters, digits, '_', '-', '.',
// and not "." or ".." (which are made of them but name a folder itself and its parent).
bool is_portable_name(std::string_view name) noexcept;

// The results folder name of a scene file without `name`: the file name without its extension
// when that is portable; otherwise each other byte becomes '_' and "-" and 8 hex digits of a hash
// of the file name follow ("my results.toml" → "my_results-…"), so that two files whose names
// differ only in such bytes get folders of their own (README, "Scene files"). `when_empty` for a
// file name with nothing before the extension (a scene read from standard input).
std::string scene_name_from_file(const std::filesystem::path& file,
                                 std::string_view when_empty = "scene");

// Reads and parses `path`; a file that cannot be read is a scene_error at line 0.
scene parse_scene_file(const std::filesystem::path& path);

// The text of a scene file, read within the limits above (a regular file or a pipe, at most
// 1 MiB); anything else is a scene_error at line 0. For other TOML files of the command that
// follow the same rules (the render scenes of `quadmc render`).
std::string read_scene_file(const std::filesystem::path& path);

}  // namespace quadmc
