// Plain Monte Carlo and the stratified patterns as methods: each is the sample mean of f over a
// point set of estimators/point_set_catalogue.hpp, named after it (plain_mc: independent points).
// N maps to the largest count the set holds (jittered and unjittered k^s, padded k², cmj k² or
// k(k + 1)). Also the `point_set` key of the methods that take one (families.hpp's
// read_point_set), a catalogue set or the user's files.
#include "families.hpp"
#include "stopping.hpp"

#include <fmt/format.h>

#include <array>
#include <memory>

namespace quadmc::methods {

std::string_view point_set_choice::name() const noexcept {
  return file ? external_point_set : set->name;
}

sizing point_set_choice::size_for(std::uint64_t N, std::size_t s) const {
  return file ? point_file_sizing(N) : point_set_sizing(*set, N, s);
}

std::vector<sizing> point_set_choice::explicit_sizes() const {
  return file ? point_file_sizes(*file) : std::vector<sizing>{};
}

quadmc::error_bars point_set_choice::error_bars() const noexcept {
  return file ? error_bars::replicates : error_bars_of(set->errors);
}

namespace {

// `path` and `points` belong to the files: beside a catalogue set (or none) they would be
// silently unused, so each is refused at its key.
void refuse_file_keys(option_reader& options, const point_set_choice& choice) {
  const std::string got = choice.given ? fmt::format("point_set = \"{}\"", choice.set->name)
                                       : std::string("no point_set (independent points)");
  for (const std::string_view key : {"path", "points"}) {
    if (!options.has(key)) continue;
    options.fail(key, fmt::format("expected only with point_set = \"{}\" (the files' rows as the "
                                  "uniforms), got it with {}",
                                  external_point_set, got));
  }
}

}  // namespace

point_set_choice read_point_set(option_reader& options) {
  point_set_choice out;
  out.set = find_point_set("independent");
  std::vector<std::string_view> names;
  for (const point_set_entry& e : point_set_catalogue()) names.push_back(e.name);
  names.push_back(external_point_set);
  if (auto name = options.choice("point_set", names)) {
    out.given = true;
    if (*name == external_point_set) {
      out.set = nullptr;
      out.file = read_point_file_options(options);
      return out;
    }
    out.set = find_point_set(*name);
  }
  refuse_file_keys(options, out);
  return out;
}

void check_uniform_files(const point_set_choice& points, const uniform_use& use,
                         const cell_size& size, std::uint64_t repetitions) {
  if (!points.file) return;
  for (std::uint64_t r = 0; r < repetitions; ++r) {
    (void)read_uniform_file(*points.file, size.evaluations, r, use.s, use.who, use.why);
  }
}

point_file_data read_uniform_file(const point_set_choice& points, const uniform_use& use,
                                  const method_cell& cell) {
  return read_uniform_file(*points.file, cell.size.evaluations, cell.repetition, use.s, use.who,
                           use.why);
}

sizing point_set_sizing(const point_set_entry& set, std::uint64_t N, std::size_t s) {
  const point_count_choice count = largest_point_count(set.counts, N, s);
  if (count.points > max_point_count(set)) {
    return {std::nullopt, fmt::format("N = {} is above the largest {} set, {} points", N, set.name,
                                      max_point_count(set))};
  }
  return {cell_size{count.points, count.per_axis, 0, 0}, {}};
}

repetition_result from_estimate(const estimate& e) {
  repetition_result out;
  out.value = e.value;
  out.std_error = e.std_error;
  out.evaluations = e.evaluations;
  out.error_estimate = e.std_error;
  return out;
}

namespace {

using theory_fn = theoretical_rate (*)(const integrand_class&);

class point_set_method final : public method {
 public:
  point_set_method(const method_descriptor& d, const point_set_entry& set, theory_fn theory,
                   stopping_choice stopping)
      : method(d), set_(&set), theory_(theory), stopping_(std::move(stopping)) {}

  std::string label_suffix() const override { return stopping_.label_suffix(); }

  std::optional<control_refusal> refuses(cell_control control) const override {
    return stopping_.refuses(control);
  }

  sizing size_for(std::uint64_t N, std::size_t s) const override {
    return point_set_sizing(*set_, N, s);
  }

  sizing tolerance_size_for(std::uint64_t budget, std::size_t s) const override {
    return stopping_sizing(stopping_, *set_, {}, budget, s);
  }

  theoretical_rate theory(const integrand_class& f) const override { return theory_(f); }

  bool shares_chunks() const override { return sample_mean_shares_chunks; }
  bool shares_chunks_at(cell_control control) const override {
    return control == cell_control::tolerance ? stopping_shares_chunks(stopping_, *set_)
                                              : shares_chunks();
  }

  repetition_result run(const method_cell& cell, const run_context& context) const override {
    if (cell.control == cell_control::tolerance) {
      return run_stopping(stopping_, *set_, {}, cell, context);
    }
    return from_estimate(set_->monte_carlo(cell.function, {context.seed, cell.stream, context.rng},
                                           cell.size.evaluations, context.threads));
  }

 private:
  const point_set_entry* set_;
  theory_fn theory_;
  stopping_choice stopping_;
};

theoretical_rate plain_theory(const integrand_class& f) {
  return root_n_rate(f, "σ/√N, finite variance assumed",
                     "docs/theory.md#plain-monte-carlo; [Ramamoorthi 2009, §2.2.2]");
}

// pbrt's unjittered stratified sampler puts one point at each cell centre: a midpoint grid
// (docs/theory.md#unjittered), shifted as a whole at random.
theoretical_rate unjittered_theory(const integrand_class& f) {
  theoretical_rate rate = composite_rule_rate(2, f);
  rate.note = "cell-centre grid = tensor midpoint rule; " + rate.note;
  return rate;
}

// In s ≤ 2 padding is one point per 2D stratum, jittered sampling itself (cmj: one per m × n cell,
// n = m or m + 1, so the cells' widths are O(N^−1/2) along both axes as the rate needs).
theoretical_rate padded_theory(const integrand_class& f) {
  if (f.s <= 2) return one_point_per_stratum_rate(f);
  return root_n_rate(
      f, "padding stratifies only 2D projections: plain MC rate unless f is a sum of 2D parts",
      "docs/theory.md#padded-jittered; [Pharr et al. 2023, §8.5]; [Veach 1997, eq. 2.26]");
}

// cmj in s = 2: every cell of row b shares the sub-cell offset σ(b) along x (and every cell of
// column a τ(a) along y), so the linear term of a smooth f does not cancel within a row: its
// error is (1/n)·Σ_b F(b)·δ_b with F(b) = ∫∂f/∂x dx along row b and δ_b a permutation of offsets
// of size 1/m, variance ≈ Var(F)/(12·n·m²) = O(N^(−3/2)): RMSE N^(−3/4), shallower than
// jittered's N^(−1), unless F is constant in y (docs/theory.md#correlated-multi-jittered). A jump
// keeps jittered's −3/4. In 1D cmj is jittered; beyond s = 2 it is padded.
theoretical_rate cmj_theory(const integrand_class& f) {
  if (f.s != 2) return padded_theory(f);
  if (auto none = infinite_variance_rate(f)) return *none;
  if (f.regularity == smoothness::discontinuous || f.regularity == smoothness::singular) {
    return one_point_per_stratum_rate(f);
  }
  return {-0.75,
          "offsets shared along each row and column: N^-3/4 unless the integral of df/dx along "
          "a row is the same for every row",
          "docs/theory.md#correlated-multi-jittered; [Kensler 2013]"};
}

// In one dimension a Latin hypercube is one point per stratum: jittered sampling exactly (its
// additive part is all of f, so Stein's residual vanishes: docs/theory.md#latin-hypercube).
theoretical_rate latin_hypercube_theory(const integrand_class& f) {
  if (f.s == 1) return one_point_per_stratum_rate(f);
  return root_n_rate(
      f, "removes the additive part of f; O(N^-1/2) in general",
      "docs/theory.md#latin-hypercube; [McKay et al. 1979]; [Stein 1987]; [Owen 1992]");
}

template <theory_fn Theory>
std::unique_ptr<const method> create_over(const method_descriptor& d, option_reader& r,
                                          std::string_view set) {
  const point_set_entry& points = *find_point_set(set);
  return std::make_unique<point_set_method>(d, points, Theory, read_stopping(r, points, {}));
}

// Each runs at its N, or to a tolerance by a stopping rule (stopping.hpp).
constexpr std::array<cell_control, 2> fixed_or_tolerance{cell_control::fixed_size,
                                                         cell_control::tolerance};

const std::array<method_descriptor, 6> descriptors{{
    {"plain_mc", "plain Monte Carlo with independent uniform points", method_kind::randomized,
     stopping_docs, fixed_or_tolerance,
     [](const method_descriptor& d, option_reader& r) {
       return create_over<plain_theory>(d, r, "independent");
     }},
    {"jittered", "jittered (stratified) sampling, one random point per cell, N = k^s",
     method_kind::randomized, stopping_docs, fixed_or_tolerance,
     [](const method_descriptor& d, option_reader& r) {
       return create_over<one_point_per_stratum_rate>(d, r, "jittered");
     }},
    {"unjittered", "one point at the centre of each cell of a randomly shifted k^s grid",
     method_kind::randomized, stopping_docs, fixed_or_tolerance,
     [](const method_descriptor& d, option_reader& r) {
       return create_over<unjittered_theory>(d, r, "unjittered");
     }},
    {"padded_jittered", "k x k jittered 2D strata padded across dimension pairs, N = k^2",
     method_kind::randomized, stopping_docs, fixed_or_tolerance,
     [](const method_descriptor& d, option_reader& r) {
       return create_over<padded_theory>(d, r, "padded_jittered");
     }},
    {"cmj",
     "correlated multi-jittered sampling (Kensler 2013), m x n cells padded across pairs, "
     "N = k^2 or k(k+1)",
     method_kind::randomized, stopping_docs, fixed_or_tolerance,
     [](const method_descriptor& d, option_reader& r) {
       return create_over<cmj_theory>(d, r, "cmj");
     }},
    {"latin_hypercube", "Latin hypercube sampling (McKay et al. 1979)", method_kind::randomized,
     stopping_docs, fixed_or_tolerance,
     [](const method_descriptor& d, option_reader& r) {
       return create_over<latin_hypercube_theory>(d, r, "latin_hypercube");
     }},
}};

}  // namespace

std::span<const method_descriptor> point_set_methods() noexcept {
  return descriptors;
}

}  // namespace quadmc::methods
