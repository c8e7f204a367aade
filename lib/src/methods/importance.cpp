// Importance sampling of a 1D integrand with a warp of sampling/inversion_warps.hpp as a method:
// the warp's uniforms come from any point set (`point_set`, independent by default), so the
// density and the stratification can be studied apart. With point_set = "external_points" they
// are the rows of a user's 1-column files (external.hpp: `path`, `points`), run through the same
// kernel, so a set's points read back from files give that set's bits.
#include "families.hpp"

#include "quadmc/methods/registry.hpp"
#include "quadmc/sampling/inversion_warps.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <cmath>
#include <memory>

namespace quadmc::methods {
namespace {

// A warp a scene may name (registry.hpp's warp_descriptor): its one parameter, the parameter's
// default and its valid range (the warps' own bounds, sampling/inversion_warps.hpp explains
// them, checked when the scene is read so that a run never reaches a warp that refuses its
// parameter).
using warp_choice = warp_descriptor;

std::string warp_names() {
  std::vector<std::string_view> names;
  for (const warp_choice& w : importance_warps()) names.push_back(w.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

const warp_choice* find_warp(std::string_view name) {
  for (const warp_choice& w : importance_warps()) {
    if (w.name == name) return &w;
  }
  return nullptr;
}

double read_warp_parameter(option_reader& t, const warp_choice& w) {
  if (w.kind == unit_warp_kind::power) {
    const std::string what = fmt::format(
        "an exponent -1 < k <= {:g} (larger k round every sample to 1)", power_warp::max_exponent);
    const auto k = t.number(w.parameter, what);
    if (!k) return w.default_value;
    if (!(*k > -1.0 && *k <= power_warp::max_exponent)) {
      t.fail(w.parameter, fmt::format("expected {}, got {}", what, *k));
    }
    return *k;
  }
  const std::string what =
      fmt::format("a rate 0 < |l| <= {:g} (e^l must stay a finite, normal double)",
                  truncated_exponential_warp::max_abs_rate);
  const auto rate = t.number(w.parameter, what);
  if (!rate) return w.default_value;
  if (!(*rate != 0.0 && std::abs(*rate) <= truncated_exponential_warp::max_abs_rate)) {
    t.fail(w.parameter, fmt::format("expected {}, got {}", what, *rate));
  }
  return *rate;
}

// `warp = "power"` or `warp = { name = "power", exponent = 2.0 }`; required.
std::pair<const warp_choice*, double> read_warp(option_reader& r) {
  const std::string names = warp_names();
  if (!r.has("warp")) {
    r.fail_missing("warp", fmt::format("missing required key for importance (one of: {})", names));
  }
  if (r.is_table("warp")) {
    const std::unique_ptr<option_reader> t =
        r.table("warp", "a warp name or a table { name = …, <parameter> = … }");
    const auto name = t->string("name", "a warp name");
    if (!name) t->fail_missing("name", fmt::format("missing `name` (one of: {})", names));
    const warp_choice* w = find_warp(*name);
    if (w == nullptr) t->fail("name", fmt::format("expected one of: {}, got \"{}\"", names, *name));
    const double parameter = read_warp_parameter(*t, *w);
    const std::array<std::string_view, 2> accepted{"name", w->parameter};
    t->reject_unread(fmt::format("warp '{}'", w->name), accepted);
    return {w, parameter};
  }
  const auto name = r.string("warp", "a warp name or a table { name = …, <parameter> = … }");
  const warp_choice* w = find_warp(*name);
  if (w == nullptr) r.fail("warp", fmt::format("expected one of: {}, got \"{}\"", names, *name));
  return {w, w->default_value};
}

class importance_method final : public method {
  // The warp is a 1D density: one u per sample, so a file of uniforms has one column.
  static constexpr uniform_use uniforms{1, "importance", "warps one uniform per sample"};

 public:
  importance_method(const method_descriptor& d, const warp_choice& warp, double parameter,
                    point_set_choice points)
      : method(d), warp_(&warp), parameter_(parameter), points_(points) {}

  std::string label_suffix() const override {
    return points_.given ? fmt::format("_{}_{}", warp_->name, points_.name())
                         : fmt::format("_{}", warp_->name);
  }

  std::optional<std::string> incompatibility(const integrand_traits& f) const override {
    if (f.s == 1) return std::nullopt;
    return fmt::format("the '{}' warp is a 1D density; the integrand has s = {}", warp_->name, f.s);
  }

  sizing size_for(std::uint64_t N, std::size_t s) const override { return points_.size_for(N, s); }
  std::vector<sizing> explicit_sizes(std::size_t) const override {
    return points_.explicit_sizes();
  }
  std::string explicit_sizes_key() const override { return points_.explicit_sizes_key(); }

  quadmc::error_bars error_bars() const override { return points_.error_bars(); }

  theoretical_rate theory(const integrand_class& f) const override {
    if (points_.file) return point_file_theory();
    return root_n_rate(f, "(∫f²/p − I²)/N; zero variance (no slope, rounding floor) iff p ∝ f ≥ 0",
                       "docs/theory.md#importance; [Ramamoorthi 2009, §4.1]");
  }

  bool shares_chunks() const override { return sample_mean_shares_chunks; }

  void check_inputs(std::size_t, const cell_size& size, std::uint64_t repetitions) const override {
    check_uniform_files(points_, uniforms, size, repetitions);
  }

  repetition_result run(const method_cell& cell, const run_context& context) const override {
    const unit_warp warp{warp_->kind, parameter_};
    if (points_.file) {
      const point_file_data u = read_uniform_file(points_, uniforms, cell);
      return from_estimate(
          importance_over_file(cell.function, warp, file_points(u), context.threads));
    }
    return from_estimate(points_.set->importance(cell.function, warp,
                                                 {context.seed, cell.stream, context.rng},
                                                 cell.size.evaluations, context.threads));
  }

 private:
  const warp_choice* warp_;
  double parameter_;
  point_set_choice points_;
};

constexpr std::array<option_doc, 4> option_docs{{
    {"warp",
     "required: \"power\", \"exponential\", or { name = \"power\", exponent = k } (p(x) = (k+1) "
     "x^k on [0,1], -1 < k <= 1e5, default 1) / { name = \"exponential\", rate = l } (the "
     "truncated exponential p(x) = l e^(l x)/(e^l - 1) on [0,1], 0 < |l| <= 700, default 1); the "
     "label gets \"_<warp>\""},
    {"point_set",
     "the pattern of the uniforms fed to the warp (independent [default], jittered, unjittered, "
     "padded_jittered, latin_hypercube, sobol, halton, lattice: their default randomization, "
     "counts mapped as for that method; or external_points: the rows of the files of `path`, 1 "
     "column, error bars from replicates); the label then gets \"_<warp>_<point_set>\""},
    {"path",
     "point_set = \"external_points\" only (then required): the file of uniforms per (N, "
     "realization), 1 column, a template with {N} and {r} as for the external_points method"},
    {"points",
     "point_set = \"external_points\" only: explicit N per cell (an integer or an increasing "
     "list), replacing budget.N"},
}};
constexpr std::array<cell_control, 1> fixed_only{cell_control::fixed_size};

const std::array<method_descriptor, 1> descriptors{{
    {"importance", "importance sampling with a 1D warp (s = 1)", method_kind::randomized,
     option_docs, fixed_only,
     [](const method_descriptor& d, option_reader& r) -> std::unique_ptr<const method> {
       const auto [warp, parameter] = read_warp(r);
       return std::make_unique<importance_method>(d, *warp, parameter, read_point_set(r));
     }},
}};

}  // namespace

std::span<const method_descriptor> importance_methods() noexcept {
  return descriptors;
}

}  // namespace quadmc::methods

namespace quadmc {

namespace {
constexpr std::array<warp_descriptor, 2> warps{{
    {"power", "p(x) = (k+1) x^k on [0,1], -1 < k <= 1e5", unit_warp_kind::power, "exponent", 1.0},
    {"exponential", "truncated exponential p(x) = l e^(l x)/(e^l - 1) on [0,1], 0 < |l| <= 700",
     unit_warp_kind::truncated_exponential, "rate", 1.0},
}};
}  // namespace

std::span<const warp_descriptor> importance_warps() noexcept {
  return warps;
}

}  // namespace quadmc
