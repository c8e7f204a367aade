// Points and rules from files as methods: `external_points` (equal weights, the sample mean of f
// over a user's point set) and `external_rule` (the same files with a last column of weights,
// vol·Σ w_i f(x_i) through rules/weighted_sum.hpp). The file format is sampling/point_file.hpp's.
//
// Use them to benchmark a sampler or a rule made outside the library beside the built-in ones.
// Not for sets the library can generate itself (sobol, halton, lattice, the tensor rules): those
// need no files and their streams are named by the scene's seed.
//
// Keys:
//   path    the file of each (N, realization): "{N}" and "{r}" (r = 0 … repetitions − 1) are
//           replaced by the numbers; relative to the scene file's folder, or absolute. Required.
//   points  explicit N per cell (an increasing list), replacing budget.N; without it each N of
//           budget.N is a cell. Either way N is the file's row count, never mapped to another.
// Realizations are replicates: the cell's error bars and coverage come from their spread
// (error_bars::replicates, docs/theory.md#replicate-error-bars), as for randomized quasi-Monte
// Carlo; repetitions = 1 is one deterministic run. The plan reads and checks every file of every
// cell before any work (check_inputs); the run reads its one file again, once per (cell,
// repetition), outside the per-sample loop, then evaluates f in the kernels' batches. The keys,
// sizes and file reading are external.hpp's, which importance and the irradiance methods share.
#include "external.hpp"
#include "families.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/summation.hpp"
#include "quadmc/estimators/monte_carlo.hpp"
#include "quadmc/methods/registry.hpp"
#include "quadmc/rules/weighted_sum.hpp"
#include "quadmc/sampling/point_file.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace quadmc::methods {
namespace {

// The N of one cell may not exceed what one file may hold in one column.
constexpr std::size_t max_point_counts = 256;

std::vector<std::uint64_t> read_increasing_points(option_reader& r) {
  const std::string what = fmt::format("a point count between 1 and {}", max_point_file_values);
  auto given = r.counts("points", 1, max_point_file_values, max_point_counts, what);
  if (!given) return {};
  for (std::size_t i = 1; i < given->size(); ++i) {
    if ((*given)[i] <= (*given)[i - 1]) {
      r.fail_element(
          "points", i,
          fmt::format("point counts must increase, got {} after {}", (*given)[i], (*given)[i - 1]));
    }
  }
  return std::move(*given);
}

// A file's nodes and weights as a weighted point set (rules/weighted_point_set.hpp): generate
// copies rows, so the kernel sums them in the file's order.
struct file_rule {
  const point_file_data* data;

  std::uint64_t size() const noexcept { return data->n; }
  std::size_t dimension() const noexcept { return data->s; }
  void generate(std::uint64_t first, std::span<double> nodes, std::span<double> weights) const {
    require_weighted_batch(data->s, data->n, first, nodes, weights);
    const double* x = data->x.data() + first * data->s;
    for (std::size_t k = 0; k < nodes.size(); ++k) nodes[k] = x[k];
    const double* w = data->w.data() + first;
    for (std::size_t k = 0; k < weights.size(); ++k) weights[k] = w[k];
  }
};

class external_method final : public method {
 public:
  external_method(const method_descriptor& d, point_file_columns columns,
                  point_file_options options)
      : method(d), columns_(columns), options_(std::move(options)) {}

  quadmc::error_bars error_bars() const override { return error_bars::replicates; }

  sizing size_for(std::uint64_t N, std::size_t) const override { return point_file_sizing(N); }

  std::vector<sizing> explicit_sizes(std::size_t) const override {
    return point_file_sizes(options_);
  }
  std::string explicit_sizes_key() const override { return "points"; }

  theoretical_rate theory(const integrand_class&) const override { return point_file_theory(); }

  bool shares_chunks() const override {
    return columns_ == point_file_columns::points
               ? sample_mean_shares_chunks
               : weighted_sum_shares_chunks<file_rule>(summation::pairwise);
  }

  void check_inputs(std::size_t s, const cell_size& size,
                    std::uint64_t repetitions) const override {
    for (std::uint64_t r = 0; r < repetitions; ++r) (void)read(size.evaluations, r, s);
  }

  repetition_result run(const method_cell& cell, const run_context& context) const override {
    const point_file_data data =
        read(cell.size.evaluations, cell.repetition, cell.function.dimension());
    repetition_result out;
    if (columns_ == point_file_columns::points) {
      // The sample mean of estimators/monte_carlo.hpp, the kernel of the built-in sets: the
      // same points give the same bits as the set that made them.
      const estimate e = monte_carlo(cell.function, file_points(data), context.threads);
      out.value = e.value;
      out.evaluations = e.evaluations;
      return out;
    }
    const rule_result r = weighted_sum(cell.function, file_rule{&data}, context.threads);
    neumaier_sum abs_weights;
    for (const double w : data.w) abs_weights.add(std::abs(w));
    out.value = r.value;
    out.evaluations = r.evaluations;
    out.absolute_weight_sum = abs_weights.value();  // the rounding floor's Σ|w|
    return out;
  }

 private:
  point_file_data read(std::uint64_t N, std::uint64_t r, std::size_t s) const {
    return read_cell_file(options_, columns_, N, r, s);
  }

  point_file_columns columns_;
  point_file_options options_;
};

constexpr std::array<option_doc, 2> external_option_docs{point_file_path_doc,
                                                         point_file_points_doc};
constexpr std::array<cell_control, 1> fixed_only{cell_control::fixed_size};

const std::array<method_descriptor, 2> descriptors{{
    {"external_points",
     "equal-weight points read from files (CSV or .npy), one per N and realization; error bars "
     "from replicates",
     method_kind::randomized, external_option_docs, fixed_only,
     [](const method_descriptor& d, option_reader& r) -> std::unique_ptr<const method> {
       return std::make_unique<external_method>(d, point_file_columns::points,
                                                read_point_file_options(r));
     }},
    {"external_rule",
     "nodes and weights read from files (last column the weight, any sign): vol·Σ w f; error "
     "bars from replicates",
     method_kind::randomized, external_option_docs, fixed_only,
     [](const method_descriptor& d, option_reader& r) -> std::unique_ptr<const method> {
       return std::make_unique<external_method>(d, point_file_columns::points_and_weights,
                                                read_point_file_options(r));
     }},
}};

}  // namespace

point_file_options read_point_file_options(option_reader& r) {
  point_file_options o;
  auto path = r.string("path", "a file path template with {N} and {r}");
  if (!path) r.fail_missing("path", "expected a file path template with {N} and {r}");
  for (const std::string_view needed : {"{N}", "{r}"}) {
    if (path->find(needed) == std::string::npos) {
      r.fail("path", fmt::format("expected a template with {{N}} and {{r}}, got \"{}\" without {}",
                                 *path, needed));
    }
  }
  o.path = std::move(*path);
  o.folder = r.folder();
  o.points = read_increasing_points(r);
  return o;
}

sizing point_file_sizing(std::uint64_t N) {
  if (N > max_point_file_values) {
    return {std::nullopt, fmt::format("N = {} is above the {} values a point file may hold", N,
                                      max_point_file_values)};
  }
  return {cell_size{N, 0, 0, 0}, {}};
}

std::vector<sizing> point_file_sizes(const point_file_options& o) {
  std::vector<sizing> out;
  for (const std::uint64_t n : o.points) out.push_back({cell_size{n, 0, 0, 0}, {}});
  return out;
}

point_file_data read_cell_file(const point_file_options& o, point_file_columns columns,
                               std::uint64_t N, std::uint64_t r, std::size_t s) {
  return read_point_file(point_file_path(o.path, N, r, o.folder), columns, N, s);
}

point_file_data read_uniform_file(const point_file_options& o, std::uint64_t N, std::uint64_t r,
                                  std::size_t uniforms, std::string_view who,
                                  std::string_view why) {
  // Read with any s, then refuse another count here: the file's own check would blame the
  // integrand's dimension, which is not what these columns are (the warp's input is).
  const std::filesystem::path file = point_file_path(o.path, N, r, o.folder);
  point_file_data data = read_point_file(file, point_file_columns::points, N, 0);
  if (data.s != uniforms) {
    throw invalid_argument(fmt::format("point file {}", file.string()),
                           fmt::format("{} columns", data.s),
                           fmt::format("{} ({} {}: point_set = \"{}\" needs s = {})", uniforms, who,
                                       why, external_point_set, uniforms));
  }
  return data;
}

theoretical_rate point_file_theory() {
  return {std::nullopt,
          "points from a file: no rate is known for them; the replicates' spread gives the "
          "error bars",
          "docs/theory.md#replicate-error-bars"};
}

std::span<const method_descriptor> external_methods() noexcept {
  return descriptors;
}

}  // namespace quadmc::methods
