// `quadmc points`: see points_command.hpp.
#include "points_command.hpp"

#include "cli_validators.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/sampling/discrepancy.hpp"
#include "quadmc/sampling/net_quality.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc_cli {

namespace {

// A key some set of the catalogue has, with those sets, in listing order.
struct set_key {
  std::string_view key;
  bool flag = false;
  std::vector<const quadmc::point_set_entry*> sets;
};

std::vector<set_key> set_keys() {
  std::vector<set_key> out;
  for (const quadmc::point_set_entry& set : quadmc::point_set_catalogue()) {
    for (const quadmc::point_set_option& o : set.options) {
      auto it =
          std::find_if(out.begin(), out.end(), [&](const set_key& k) { return k.key == o.key; });
      if (it == out.end()) it = out.insert(out.end(), set_key{o.key, o.is_flag(), {}});
      it->sets.push_back(&set);
    }
  }
  return out;
}

// The command-line form of a key: allow_any_n → --allow-any-n.
std::string flag_of(std::string_view key) {
  std::string out = "--";
  for (const char c : key) out += c == '_' ? '-' : c;
  return out;
}

}  // namespace

CLI::App* add_points_subcommand(CLI::App& app, points_request& request) {
  auto* points = app.add_subcommand(
      "points", "Write the points of a point set as CSV (x1,...,xs per line), to stdout or --out");
  points->add_option("set", request.set, "Point set: a name of `quadmc list` (sobol, halton, ...)")
      ->required();
  points->add_option("--n", request.n, "Number of points N ≥ 1")
      ->required()
      ->check(non_negative_integer())
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 62));
  points->add_option("--s", request.s, "Dimension s ≥ 1")
      ->required()
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20));
  points->add_option("--seed", request.seed, "Seed K ≥ 0 (the key of the --rng generator)")
      ->required()
      ->check(non_negative_integer());
  points->add_option("--stream", request.stream, "Stream of the seed (default 0)")
      ->check(non_negative_integer());
  points
      ->add_option(
          "--rng", request.rng,
          fmt::format("Generator of the set's random numbers: one of {} (default {})",
                      quadmc::rng_kind_names(), quadmc::to_string(quadmc::rng_kind::philox4x32_10)))
      ->type_name("NAME");
  for (const set_key& k : set_keys()) {
    std::string help;
    for (std::size_t i = 0; i < k.sets.size(); ++i) {
      const quadmc::point_set_option& o = *k.sets[i]->option(k.key);
      help += fmt::format(
          "{}{}: {}", i == 0 ? "" : "; ", k.sets[i]->name,
          o.is_flag() ? o.meaning : fmt::format("{}", fmt::join(o.point_choices(), "|")));
    }
    const std::string key(k.key);
    if (k.flag) {
      points->add_flag_callback(
          flag_of(k.key), [&request, key] { request.set_options[key] = "true"; }, help);
    } else {
      points->add_option_function<std::string>(
          flag_of(k.key), [&request, key](const std::string& v) { request.set_options[key] = v; },
          help + " (default: the set's first)");
    }
  }
  points->add_option("--out", request.out, "Output file (default: stdout)")
      ->check(quadmc_cli::non_empty_path());
  points->add_flag("--report", request.report,
                   "Instead of the points: their t-values, minimum distance and L2 discrepancies "
                   "as CSV measure,value,note (N ≤ 2^20)");
  return points;
}

namespace {

// The options as the set reads them, every key and choice checked (checked_options), named as
// flags in its errors.
quadmc::point_set_options options_for(const quadmc::point_set_entry& set, const points_request& r) {
  std::vector<quadmc::named_option> given;
  for (const auto& [key, value] : r.set_options) given.push_back({key, value});
  return quadmc::checked_options(set, given, flag_of);
}

struct file_closer {
  void operator()(std::FILE* f) const noexcept { std::fclose(f); }
};

// Thrown from the batch callback when a write fails (a closed pipe: `quadmc points … | head`),
// so that generating stops at once instead of running through all N points unwritten.
struct output_gone {};

// Above this size the command says on stderr how much text it is about to write: at N = 2^40 a
// mistyped --n is terabytes.
constexpr double announced_bytes = 1e9;
// The longest text of one coordinate: "0." and 17 significant digits, or an exponent form.
constexpr double bytes_per_coordinate = 24.0;

// --report's bounds (points_command.hpp): the whole set's t-value up to s = 4, the pairs' while
// their count times N stays within 2^24 box counts per shape.
constexpr std::size_t report_whole_t_dimension = 4;
constexpr double report_pair_budget = 16777216.0;

// The CSV of --report for the points x (row-major, s per point).
std::string report_of(std::span<const double> x, std::size_t s) {
  const std::size_t n = x.size() / s;
  const bool dyadic = std::has_single_bit(n);
  std::string out = "measure,value,note\n";
  auto row = [&out](std::string_view measure, const std::string& value, std::string_view note) {
    out += fmt::format("{},{},{}\n", measure, value, note);
  };
  row("points", std::to_string(n), "");
  row("dimension", std::to_string(s), "");
  if (!dyadic) {
    row("t_value", "", "N is not a power of two");
  } else if (s > report_whole_t_dimension) {
    row("t_value", "", "s > 4");
  } else {
    row("t_value", std::to_string(*quadmc::net_t_value(x, s)), "");
  }
  const double pair_work =
      static_cast<double>(s) * static_cast<double>(s - 1) / 2.0 * static_cast<double>(n);
  if (s < 2 || !dyadic || pair_work > report_pair_budget) {
    const std::string_view why = s < 2     ? "s = 1"
                                 : !dyadic ? "N is not a power of two"
                                           : "s(s - 1)/2·N > 2^24";
    for (const std::string_view m : {"pair_t_best", "pair_t_worst", "worst_pair"}) {
      row(m, "", why);
    }
  } else {
    const quadmc::pair_t_values t = *quadmc::pairwise_t_values(x, s);
    row("pair_t_best", std::to_string(t.best), "");
    row("pair_t_worst", std::to_string(t.worst), "");
    row("worst_pair", fmt::format("{}-{}", t.worst_j + 1, t.worst_k + 1),
        "coordinates counted from 1");
  }
  const bool small = n <= quadmc::max_discrepancy_points;
  if (!small) {
    row("min_distance_ratio", "", "N > 2^14");
  } else if (s > 8) {
    row("min_distance_ratio", "", "s > 8 (no densest packing known)");
  } else {
    row("min_distance_ratio", fmt::format("{}", quadmc::normalized_min_distance(x, s)),
        "over the densest lattice packing's");
  }
  if (!small) {
    for (const std::string_view m : {"l2_star", "centered", "wraparound"}) {
      row(m, "", "N > 2^14");
    }
  } else {
    const quadmc::l2_discrepancies d = quadmc::discrepancies(x, s);
    row("l2_star", fmt::format("{}", d.l2_star), "");
    row("centered", fmt::format("{}", d.centered), "");
    row("wraparound", fmt::format("{}", d.wraparound), "");
  }
  return out;
}

}  // namespace

void run_points(const points_request& r, const std::function<bool(std::string_view)>& write) {
  const quadmc::point_set_entry* set = quadmc::find_point_set(r.set);
  if (set == nullptr) {
    throw quadmc::invalid_argument("point set", r.set,
                                   fmt::format("one of: {}", quadmc::point_set_names()));
  }
  const quadmc::point_set_options options = options_for(*set, r);
  const quadmc::sample_stream stream{r.seed, r.stream, quadmc::parse_rng_kind(r.rng, "--rng")};
  // The dimension first, so that a set that cannot have s dimensions blames --s, not --n.
  if (const std::string problem = quadmc::dimension_problem(*set, r.s, options); !problem.empty()) {
    throw quadmc::invalid_argument("--s", std::to_string(r.s), problem);
  }
  const std::string problem = quadmc::size_problem(*set, r.s, r.n, options);
  if (!problem.empty()) {
    throw quadmc::invalid_argument("--n", fmt::format("{} (s = {})", r.n, r.s), problem);
  }
  if (r.report && r.n > (std::uint64_t{1} << quadmc::max_net_log2_points)) {
    throw quadmc::invalid_argument("--n", std::to_string(r.n), "N ≤ 2^20 with --report");
  }

  std::unique_ptr<std::FILE, file_closer> file;
  if (!r.out.empty()) {
    file.reset(std::fopen(r.out.c_str(), "w"));
    if (!file) {
      throw std::runtime_error(
          fmt::format("--out {}: cannot open for writing: {}", r.out, std::strerror(errno)));
    }
  }
  auto emit = [&](std::string_view text) {
    if (file) {
      if (std::fwrite(text.data(), 1, text.size(), file.get()) != text.size()) {
        throw std::runtime_error(
            fmt::format("--out {}: write failed: {}", r.out, std::strerror(errno)));
      }
      return true;
    }
    return write(text);
  };
  const double bytes = static_cast<double>(r.n) * static_cast<double>(r.s) * bytes_per_coordinate;
  if (bytes > announced_bytes && !r.report) {
    const bool tera = bytes >= 1e12;
    fmt::print(stderr,
               "quadmc points: up to {:.3g} {} of text ({} points × {} coordinates) to {}\n",
               bytes / (tera ? 1e12 : 1e9), tera ? "TB" : "GB", r.n, r.s,
               r.out.empty() ? "standard output" : r.out);
  }
  if (r.report) {
    std::vector<double> x;
    x.reserve(r.n * r.s);
    set->points(
        r.s, r.n, stream,
        [&](std::uint64_t, std::span<const double> batch) {
          x.insert(x.end(), batch.begin(), batch.end());
        },
        options);
    if (!emit(report_of(x, r.s))) return;
  } else {
    std::string text;
    for (std::size_t j = 0; j < r.s; ++j) text += fmt::format("{}x{}", j == 0 ? "" : ",", j + 1);
    text += '\n';
    if (!emit(text)) return;
    try {
      set->points(
          r.s, r.n, stream,
          [&](std::uint64_t, std::span<const double> x) {
            text.clear();
            auto out = std::back_inserter(text);
            for (std::size_t k = 0; k < x.size(); ++k) {
              fmt::format_to(out, "{}{}", x[k], (k + 1) % r.s == 0 ? "\n" : ",");
            }
            if (!emit(text)) throw output_gone{};
          },
          options);
    } catch (const output_gone&) {
      return;  // `write` has recorded why; the caller reports it
    }
  }
  if (file && std::fclose(file.release()) != 0) {
    throw std::runtime_error(
        fmt::format("--out {}: close failed: {}", r.out, std::strerror(errno)));
  }
}

}  // namespace quadmc_cli
