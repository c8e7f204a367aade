// `quadmc points SET --n N --s S --seed K [--randomization R] [--rng NAME]`: the points of any
// point set of the catalogue (estimators/point_set_catalogue.hpp) as CSV, so that a user can take
// the suite's Sobol', Halton, lattice or stratified points to another tool.
//
// Output: a header x1,…,xs, then one line per point in index order, each coordinate the shortest
// decimal text that reads back to the same double (so another tool sees the same bits). To
// stdout, or with --out FILE to that file (written whole, or the command fails naming it).
// The points are those of stream `--stream` (default 0) of seed K drawn by the generator --rng
// names, philox4x32_10 (the default) or ars4x32_7 (core/rng.hpp,
// docs/theory.md#counter-based-generators), as a scene's `rng` names its methods': the same
// (SET, N, s, K, stream, rng, options) give bitwise the same file. Extra flags beyond the fixed
// form: --stream, --rng, and each key a set of the catalogue has as --key ('-' for '_'):
// --randomization and --periodization (a value), --allow-any-n and --drop-first-point (flags);
// the sets read their own values.
// With --report the command writes, instead of the points, what they are as a net and a packing
// (sampling/net_quality.hpp) and their L2 discrepancies (sampling/discrepancy.hpp), as CSV
// measure,value,note: the whole set's t-value (N = 2^m, s ≤ 4), the best and worst t over the
// projections on pairs of coordinates and the first worst pair (N = 2^m, s(s − 1)/2·N ≤ 2^24),
// the minimum distance over the densest packing's (N ≤ 2^14, s ≤ 8), the discrepancies
// (N ≤ 2^14); a measure beyond its bound has an empty value and the bound as its note. N ≤ 2^20.
// Exit status as for every subcommand: 1 for values the set refuses (an unknown set, a
// randomization it has not, N not 2^m for a randomized net) and an --rng naming no generator,
// 2 for usage errors (a missing or malformed flag).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace quadmc_cli {

struct points_request {
  std::string set;
  std::uint64_t n = 0;
  std::size_t s = 0;
  std::uint64_t seed = 0;
  std::uint64_t stream = 0;
  // --rng as given: parsed by run_points, so that a bad name is refused as a bad --randomization
  // is, in one line with exit status 1.
  std::string rng = "philox4x32_10";
  // The point sets' own options given (--randomization owen, --allow-any-n): key → value, "true"
  // for a flag; a key not given is absent (the set's default).
  std::map<std::string, std::string, std::less<>> set_options;
  std::string out;      // empty: stdout
  bool report = false;  // --report: the set's net quality and discrepancies, not its points
};

// Adds the `points` subcommand to `app`, filling `request` when it is parsed.
CLI::App* add_points_subcommand(CLI::App& app, points_request& request);

// Writes the points: through `write` (stdout) or to request.out. `write` returns false once the
// output failed (the caller reports it). Throws quadmc::invalid_argument for values the set
// refuses and std::runtime_error when --out cannot be written.
void run_points(const points_request& request, const std::function<bool(std::string_view)>& write);

}  // namespace quadmc_cli
