// Scene parsing: toml++ document → quadmc::scene (parse.hpp documents every key).
//
// Every check reports through the scene layer's TOML reader (toml_reader.hpp), so every message
// has the one shape "file:line:column: key 'path': expected …, got …" and points at the key (not
// the value), which is where an editor's cursor should land.
#include "quadmc/scene/parse.hpp"

#include "quadmc/methods/registry.hpp"
#include "quadmc/scene/toml_text.hpp"

#include "toml_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>

namespace quadmc {

namespace {

// The keys each table of a scene may hold, as the checks below use them (scene_keys() lists
// them). A method's own keys are its descriptor's options; an integrand's other keys are its
// family's parameters (catalogue_entry's keys).
constexpr std::array<std::string_view, 9> top_level_keys{
    "name", "description", "seed", "rng", "threads", "integrand", "method", "budget", "output"};
constexpr std::array<std::string_view, 7> integrand_keys{
    "family", "name", "dimension", "dimensions", "ensemble", "reference", "reference_uncertainty"};
// The keys every [[method]] table may hold; the rest are the method's own (its descriptor's).
constexpr std::array<std::string_view, 7> common_method_keys{
    "name", "label", "integrands", "repetitions", "control", "tolerances", "tolerance_kind"};
constexpr std::array<std::string_view, 5> budget_keys{"N", "max_evaluations", "max_seconds",
                                                      "timing_min_seconds", "paired_timing_rounds"};
constexpr std::array<std::string_view, 3> range_keys{"from", "to", "factor"};
constexpr std::array<std::string_view, 3> output_keys{"csv", "markdown", "plots"};
constexpr std::array<scene_table_keys, 6> key_tables{{
    {"", top_level_keys},
    {"integrand", integrand_keys},
    {"method", common_method_keys},
    {"budget", budget_keys},
    {"budget.N", range_keys},
    {"output", output_keys},
}};

// Counts above 2^53 are not exactly representable as doubles, which the analysis layer uses for
// N; point sets also need N·s < 2^62 (sampling/point_set.hpp), which make_plan checks per cell.
constexpr std::uint64_t max_count = std::uint64_t{1} << 53;
constexpr std::size_t max_dimension = scene_limits::max_dimension;
constexpr std::size_t max_ladder = scene_limits::max_ladder;

using scene_toml::entry;
using scene_reader = scene_toml::reader;

// ---------------------------------------------------------------------------------------------
// [[integrand]]

// `reference` and `reference_uncertainty` (docs/theory.md#references-without-a-closed-form): a
// value to measure the errors from instead of the family's exact one, or "computed". Refused for
// an ensemble, whose reference is the mean of its K instances' exact integrals: one number given
// for K different integrals would measure K − 1 of them against the wrong value.
// A number is one integral, so it is refused too for a `dimensions` list of several s.
void parse_reference(const scene_reader& r, const toml::table& t, const std::string& prefix,
                     std::size_t dimension_count, integrand_spec& spec) {
  const auto reference = r.find(t, "reference", prefix);
  const auto uncertainty = r.find(t, "reference_uncertainty", prefix);
  if (!reference) {
    if (uncertainty) {
      r.fail(*uncertainty, "only with a number `reference` (the value it is the uncertainty of)");
    }
    return;
  }
  const std::string_view what = "a finite number or \"computed\"";
  if (reference->value->is_string()) {
    if (r.string(*reference, what) != "computed") r.expected(*reference, what);
    spec.reference = reference_source::computed;
    if (uncertainty) {
      r.fail(*uncertainty,
             "not with reference = \"computed\" (the computation states its own uncertainty)");
    }
  } else {
    spec.reference_value = r.number(*reference, what);
    spec.reference = reference_source::given;
    if (uncertainty) {
      const std::string_view absolute =
          "a finite number ≥ 0 (the reference's absolute uncertainty)";
      const double u = r.number(*uncertainty, absolute);
      if (!(u >= 0.0)) r.expected(*uncertainty, absolute);
      spec.reference_uncertainty = u;
    }
    if (dimension_count > 1) {
      r.fail(*reference,
             fmt::format("a number is one integral, not one for each of the {} dimensions "
                         "listed; use \"computed\" or one [[integrand]] table per s",
                         dimension_count));
    }
  }
  if (spec.ensemble > 1) {
    r.fail(*reference,
           fmt::format("only for a single integrand, not with ensemble = {}: an ensemble's "
                       "reference is the mean of its instances' exact integrals",
                       spec.ensemble));
  }
}

// `taken` maps each display name in `out` to its index there.
void parse_integrand(const scene_reader& r, const toml::table& t, std::size_t index,
                     std::vector<integrand_spec>& out, std::map<std::string, std::size_t>& taken) {
  const std::string prefix = fmt::format("integrand[{}]", index);
  integrand_spec base;
  base.table_index = index;
  base.table = r.at(t.source());
  base.keys = r.locations(t);

  // Every key is copied into each integrand a `dimensions` list expands to: the count is
  // bounded so that a long table cannot multiply into gigabytes.
  if (t.size() > scene_limits::max_integrand_keys) {
    r.fail(base.table, prefix,
           fmt::format("{} keys in one [[integrand]] table; at most {} (family, name, dimension, "
                       "ensemble and the family's parameters)",
                       t.size(), scene_limits::max_integrand_keys));
  }
  const auto family = r.find(t, "family", prefix);
  if (!family) r.fail(base.table, prefix + ".family", "missing required key (a catalogue name)");
  base.family = r.string(*family, "a family name (`quadmc list` prints them)");
  if (base.family.empty() || base.family.size() > scene_limits::max_name_length) {
    r.expected(*family, "a family name (`quadmc list` prints them)");
  }

  std::optional<std::string> given_name;
  if (const auto e = r.find(t, "name", prefix)) given_name = r.display_name(*e);

  std::vector<std::size_t> dimensions;
  const auto dim = r.find(t, "dimension", prefix);
  const auto dims = r.find(t, "dimensions", prefix);
  if (dim && dims) r.fail(*dims, "give either `dimension` or `dimensions`, not both");
  // Neither: s = 0 asks the catalogue for the family's default (1, or 2 for irradiance);
  // make_plan fills in the real s.
  if (!dim && !dims) dimensions.push_back(0);
  const std::string_view dim_expected = "a dimension between 1 and 1024";
  if (dim) dimensions.push_back(r.count(*dim, 1, max_dimension, dim_expected));
  if (dims) {
    const toml::array& a = r.array(*dims, "a non-empty array of dimensions");
    for (std::size_t i = 0; i < a.size(); ++i) {
      const entry element = scene_reader::element(*dims, i);
      const std::size_t s = r.count(element, 1, max_dimension, dim_expected);
      if (std::find(dimensions.begin(), dimensions.end(), s) != dimensions.end()) {
        r.fail(element, fmt::format("dimension {} is listed twice", s));
      }
      dimensions.push_back(s);
    }
  }
  if (const auto e = r.find(t, "ensemble", prefix)) {
    base.ensemble = r.count(*e, 1, 1'000'000, "an ensemble size between 1 and 1000000");
    base.ensemble_given = true;
  }

  parse_reference(r, t, prefix, dimensions.size(), base);

  // Every other key is a family parameter; the catalogue decides which ones the family takes.
  for (auto&& [key, value] : t) {
    const std::string_view k = key.str();
    if (std::find(integrand_keys.begin(), integrand_keys.end(), k) != integrand_keys.end()) {
      continue;
    }
    const entry e{&key, &value, scene_reader::path(prefix, k)};
    const std::string what =
        fmt::format("a number, an array of numbers or a string (a parameter of {})", base.family);
    if (value.is_number()) {
      base.scalars.emplace(toml_original_text(k), r.number(e, what));
    } else if (const auto* a = value.as_array()) {
      if (a->empty()) r.expected(e, what);
      // A vector parameter has one entry per coordinate (the catalogue checks the exact length).
      if (a->size() > max_dimension) {
        r.fail(e, fmt::format("an array of {} numbers; a parameter has at most {} (one per "
                              "dimension)",
                              a->size(), max_dimension));
      }
      std::vector<double> v;
      for (std::size_t i = 0; i < a->size(); ++i) {
        const entry element = scene_reader::element(e, i);
        v.push_back(r.number(element, "a finite number"));
      }
      base.vectors.emplace(toml_original_text(k), std::move(v));
    } else if (value.is_string()) {
      // Which strings the key takes is the catalogue's rule (find_key_problem), as for the others.
      base.strings.emplace(toml_original_text(k), r.string(e, what));
    } else {
      r.expected(e, what);
    }
  }

  base.base_name = given_name.value_or(base.family);
  if (out.size() + dimensions.size() > scene_limits::max_integrands) {
    r.fail(dims ? r.at(*dims) : base.table, dims ? dims->path : prefix,
           fmt::format("the scene would have {} integrands (after `dimensions` lists expand); at "
                       "most {}",
                       out.size() + dimensions.size(), scene_limits::max_integrands));
  }
  for (std::size_t s : dimensions) {
    integrand_spec spec = base;
    spec.dimension = s;
    if (given_name && !dims) {
      spec.name = *given_name;
    } else {
      spec.name = s == 0 ? base.base_name : fmt::format("{}_s{}", base.base_name, s);
    }
    if (const auto it = taken.find(spec.name); it != taken.end()) {
      const integrand_spec& other = out[it->second];
      r.fail(spec.table, prefix + ".name",
             fmt::format("integrand name '{}' is already used by integrand[{}] (line {}); set "
                         "a distinct `name`",
                         spec.name, other.table_index, other.table.line));
    }
    taken.emplace(spec.name, out.size());
    out.push_back(std::move(spec));
  }
}

// ---------------------------------------------------------------------------------------------
// [[method]]

// A [[method]] table as the option_reader its descriptor reads (methods/option_reader.hpp):
// every failure is a scene_error at the key, so the descriptors' messages have the file, line
// and key of every other scene message.
class toml_option_reader final : public option_reader {
 public:
  toml_option_reader(const scene_reader& r, const toml::table& t, std::string prefix)
      : r_(&r), t_(&t), prefix_(std::move(prefix)) {}

  std::string path() const override { return prefix_; }
  std::filesystem::path folder() const override {
    return std::filesystem::path(r_->file()).parent_path();
  }
  bool has(std::string_view key) const override { return t_->contains(key); }

  std::optional<std::uint64_t> count(std::string_view key, std::uint64_t lo, std::uint64_t hi,
                                     std::string_view what) override {
    const auto e = take(key);
    if (!e) return std::nullopt;
    return r_->count(*e, lo, hi, what);
  }
  std::optional<double> number(std::string_view key, std::string_view what) override {
    const auto e = take(key);
    if (!e) return std::nullopt;
    return r_->number(*e, what);
  }
  std::optional<std::string> string(std::string_view key, std::string_view what) override {
    const auto e = take(key);
    if (!e) return std::nullopt;
    return r_->string(*e, what);
  }
  std::optional<bool> boolean(std::string_view key) override {
    const auto e = take(key);
    if (!e) return std::nullopt;
    return r_->boolean(*e);
  }
  std::optional<std::vector<std::uint64_t>> counts(std::string_view key, std::uint64_t lo,
                                                   std::uint64_t hi, std::size_t max_values,
                                                   std::string_view what) override {
    const auto e = take(key);
    if (!e) return std::nullopt;
    std::vector<std::uint64_t> out;
    for_each_element(*e, max_values, what, [&](const entry& element) {
      out.push_back(r_->count(element, lo, hi, what));
    });
    return out;
  }
  std::optional<std::vector<double>> numbers(std::string_view key, std::size_t max_values,
                                             std::string_view what) override {
    const auto e = take(key);
    if (!e) return std::nullopt;
    std::vector<double> out;
    for_each_element(*e, max_values, what,
                     [&](const entry& element) { out.push_back(r_->number(element, what)); });
    return out;
  }
  bool is_table(std::string_view key) const override {
    const auto it = t_->find(key);
    return it != t_->end() && it->second.is_table();
  }
  std::unique_ptr<option_reader> table(std::string_view key, std::string_view what) override {
    const auto e = take(key);
    if (!e) fail_missing(key, fmt::format("missing {}", what));
    return std::make_unique<toml_option_reader>(*r_, r_->table(*e, what), e->path);
  }
  std::exception_ptr error(where at, std::string_view key, std::size_t index,
                           std::string_view message) const override {
    const std::string path = scene_reader::path(prefix_, key);
    const auto e = r_->find(*t_, key, prefix_);
    if (at == where::missing || !e) {
      return std::make_exception_ptr(
          scene_error(r_->at(t_->source()), toml_original_text(path), toml_original_text(message)));
    }
    // An element of an array value; a single value stands for its own array of one.
    const bool array = e->value->is_array();
    const std::string shown =
        at == where::element && array ? fmt::format("{}[{}]", path, index + 1) : path;
    return std::make_exception_ptr(
        scene_error(r_->at(*e), toml_original_text(shown), toml_original_text(message)));
  }
  void reject_unread(std::string_view what, std::span<const std::string_view> accepted) override {
    for (auto&& [key, value] : *t_) {
      if (read_.contains(key.str())) continue;
      if (std::find(accepted.begin(), accepted.end(), key.str()) != accepted.end()) continue;
      r_->fail(
          r_->at(key.source()), scene_reader::path(prefix_, key.str()),
          fmt::format("unknown key in {}; expected one of: {}", what, fmt::join(accepted, ", ")));
    }
  }

 private:
  std::optional<entry> take(std::string_view key) {
    auto e = r_->find(*t_, key, prefix_);
    if (e) read_.insert(std::string(key));
    return e;
  }

  // A value or an array of values, each handed to `one` with its own path ("panels[2]").
  template <class One>
  void for_each_element(const entry& e, std::size_t max_values, std::string_view what,
                        One&& one) const {
    const auto* a = e.value->as_array();
    if (a == nullptr) {
      one(e);
      return;
    }
    if (a->empty()) r_->expected(e, fmt::format("{} or a non-empty array of them", what));
    if (a->size() > max_values) r_->fail(e, fmt::format("more than {} values", max_values));
    for (std::size_t i = 0; i < a->size(); ++i) {
      one(scene_reader::element(e, i));
    }
  }

  const scene_reader* r_;
  const toml::table* t_;
  std::string prefix_;
  std::set<std::string, std::less<>> read_;
};

// `control` and `tolerances` (methods/method.hpp): how the method's cells are run. A control the
// method does not support is an error naming the ones it does.
void parse_control(const scene_reader& r, const toml::table& t, const std::string& prefix,
                   const method_descriptor& descriptor, method_spec& m) {
  m.control = descriptor.controls.front();
  std::vector<std::string_view> names;
  for (const cell_control c : descriptor.controls) names.push_back(to_string(c));
  const std::string supported = fmt::format("{}", fmt::join(names, ", "));
  if (const auto e = r.find(t, "control", prefix)) {
    const std::string what = fmt::format("one of: {} ({} supports these)", supported, m.name);
    const std::string given = r.string(*e, what);
    bool found = false;
    for (const cell_control c : descriptor.controls) {
      if (to_string(c) == given) {
        m.control = c;
        found = true;
      }
    }
    if (!found) r.expected(*e, what);
  }
  const auto tolerances = r.find(t, "tolerances", prefix);
  const auto kind = r.find(t, "tolerance_kind", prefix);
  if (m.control != cell_control::tolerance) {
    if (tolerances) r.fail(*tolerances, "only with control = \"tolerance\"");
    if (kind) r.fail(*kind, "only with control = \"tolerance\"");
    return;
  }
  if (kind) {
    const std::string_view what =
        "one of: absolute (the tolerances are errors), relative (fractions of |I|)";
    const std::string given = r.string(*kind, what);
    if (given != "absolute" && given != "relative") r.expected(*kind, what);
    m.relative_tolerance = given == "relative";
  }
  if (!tolerances) {
    r.fail(m.table, prefix + ".tolerances",
           "missing required key for control = \"tolerance\" (the errors to reach, decreasing)");
  }
  const toml::array& a = r.array(*tolerances, "a non-empty array of tolerances");
  if (a.size() > max_ladder) r.fail(*tolerances, fmt::format("more than {} values", max_ladder));
  for (std::size_t i = 0; i < a.size(); ++i) {
    const entry element = scene_reader::element(*tolerances, i);
    const double tol = r.number(element, "a tolerance > 0 (an absolute error)");
    if (!(tol > 0.0)) r.expected(element, "a tolerance > 0 (an absolute error)");
    if (!m.tolerances.empty() && tol >= m.tolerances.back()) {
      r.fail(element,
             fmt::format("tolerances must decrease, got {} after {}", tol, m.tolerances.back()));
    }
    m.tolerances.push_back(tol);
  }
}

// The names a method's `integrands` list may use: display names and the `name` of a
// `dimensions` table. A set, so that long lists cost n·log n, not n × integrands.
using integrand_names = std::set<std::string, std::less<>>;

integrand_names names_of(const std::vector<integrand_spec>& integrands) {
  integrand_names names;
  for (const auto& f : integrands) {
    names.insert(f.name);
    names.insert(f.base_name);
  }
  return names;
}

method_spec parse_method(const scene_reader& r, const toml::table& t, std::size_t index,
                         const std::vector<integrand_spec>& integrands,
                         const integrand_names& names) {
  const std::string prefix = fmt::format("method[{}]", index);
  method_spec m;
  m.table_index = index;
  m.table = r.at(t.source());
  m.keys = r.locations(t);

  const auto name = r.find(t, "name", prefix);
  if (!name) {
    r.fail(m.table, prefix + ".name",
           fmt::format("missing required key (one of: {})", method_names()));
  }
  m.name = r.string(*name, "a method name");
  const method_descriptor* descriptor = find_method(m.name);
  if (descriptor == nullptr) {
    if (auto why = unavailable_method(m.name)) r.fail(*name, *why);
    r.expected(*name, fmt::format("one of: {}", method_names()));
  }

  // Unknown keys first, before any value is judged: a typo ("repetition") must not fall back to
  // a default, and it is the likelier mistake when both are present.
  std::vector<std::string_view> accepted(common_method_keys.begin(), common_method_keys.end());
  for (const option_doc& o : descriptor->options) accepted.push_back(o.key);
  toml_option_reader options(r, t, prefix);
  options.reject_unread(fmt::format("a '{}' method", m.name), accepted);

  if (const auto e = r.find(t, "repetitions", prefix)) {
    m.repetitions = r.count(*e, 1, 1'000'000'000, "a positive integer");
    m.repetitions_given = true;
  }
  parse_control(r, t, prefix, *descriptor, m);
  m.configured = descriptor->create(*descriptor, options);
  if (const auto no = m.configured->refuses(m.control)) {
    if (no->key == "control") {
      if (const auto e = r.find(t, "control", prefix)) r.fail(*e, no->message);
      r.fail(m.table, prefix + ".control", no->message);
    }
    options.fail(no->key, no->message);
  }

  if (const auto e = r.find(t, "integrands", prefix)) {
    const toml::array& a = r.array(*e, "a non-empty array of integrand names");
    if (a.size() > scene_limits::max_integrands) {
      r.fail(*e, fmt::format("more than {} names", scene_limits::max_integrands));
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
      const entry element = scene_reader::element(*e, i);
      std::string n = r.string(element, "an integrand name");
      if (!names.contains(n)) {
        std::string known;
        constexpr std::size_t shown = 16;  // the message stays one readable line
        for (std::size_t k = 0; k < integrands.size() && k < shown; ++k) {
          known += (known.empty() ? "" : ", ") + integrands[k].name;
        }
        if (integrands.size() > shown) known += fmt::format(", … ({} in all)", integrands.size());
        r.fail(element, fmt::format("no integrand is named '{}' (integrands: {})", n, known));
      }
      m.integrands.push_back(std::move(n));
    }
  }

  if (const auto e = r.find(t, "label", prefix)) {
    m.label = r.display_name(*e);
  } else {
    m.label = m.name + m.configured->label_suffix();
  }
  return m;
}

// ---------------------------------------------------------------------------------------------
// [budget], [output]

std::vector<std::uint64_t> parse_ladder(const scene_reader& r, const entry& e) {
  const std::string_view what = "a count between 1 and 2^53";
  std::vector<std::uint64_t> ladder;
  if (const auto* a = e.value->as_array()) {
    if (a->empty()) r.expected(e, "a non-empty array of counts");
    if (a->size() > max_ladder) r.fail(e, fmt::format("more than {} values", max_ladder));
    for (std::size_t i = 0; i < a->size(); ++i) {
      const entry element = scene_reader::element(e, i);
      const std::uint64_t n = r.count(element, 1, max_count, what);
      if (!ladder.empty() && n <= ladder.back()) {
        r.fail(element, fmt::format("values must increase, got {} after {}", n, ladder.back()));
      }
      ladder.push_back(n);
    }
    return ladder;
  }
  const auto* t = e.value->as_table();
  if (t == nullptr) r.expected(e, "an array of counts or { from = …, to = …, factor = … }");
  r.check_keys(*t, range_keys, e.path, "a geometric range");
  const auto from = r.find(*t, "from", e.path);
  const auto to = r.find(*t, "to", e.path);
  const auto factor = r.find(*t, "factor", e.path);
  for (const auto& [k, found] : {std::pair{"from", from}, {"to", to}, {"factor", factor}}) {
    if (!found) r.fail(e, fmt::format("missing `{}` in the range", k));
  }
  const std::uint64_t lo = r.count(*from, 1, max_count, what);
  const std::uint64_t hi = r.count(*to, 1, max_count, what);
  if (hi < lo) r.expected(*to, fmt::format("a count ≥ from = {}", lo));
  const double f = r.number(*factor, "a factor > 1");
  if (!(f > 1.0)) r.expected(*factor, "a factor > 1");
  if (f == std::floor(f) && f < static_cast<double>(max_count)) {
    // Integral factor: exact integer products, so N = 4^k hits perfect powers exactly.
    const auto q = static_cast<std::uint64_t>(f);
    for (std::uint64_t n = lo;; n *= q) {
      ladder.push_back(n);
      if (ladder.size() > max_ladder) break;
      if (n > hi / q) break;
    }
  } else {
    // The loop below would run k = 0 … ⌈ln(to/from)/ln(factor)⌉ before leaving the range, and
    // rounding can repeat values for many steps (factor = 1.0000000001 from 1 to 10^6: 1.4·10^11
    // steps for 256 distinct values, minutes of work), so the count of steps is bounded first.
    // log1p(f − 1): f − 1 is exact for f ≤ 2 (Sterbenz), and log1p keeps its relative accuracy.
    const double ratio = static_cast<double>(hi) / static_cast<double>(lo);
    const double steps = std::ceil(std::log(ratio) / std::log1p(f - 1.0));
    if (!(steps <= static_cast<double>(scene_limits::max_ladder_steps))) {
      r.fail(
          *factor,
          fmt::format("factor = {} needs {:.3g} steps from {} to {}; at most {} "
                      "(a factor ≥ {:.6g} covers this range)",
                      f, steps, lo, hi, scene_limits::max_ladder_steps,
                      std::pow(ratio, 1.0 / static_cast<double>(scene_limits::max_ladder_steps))));
    }
    // One step more than the estimate, in case ⌈·⌉ rounded down a value that still fits.
    const auto last = static_cast<int>(steps) + 1;
    for (int k = 0; k <= last; ++k) {
      const double x = std::round(static_cast<double>(lo) * std::pow(f, k));
      if (x > static_cast<double>(hi)) break;
      const auto n = static_cast<std::uint64_t>(x);
      if (ladder.empty() || n > ladder.back()) ladder.push_back(n);
      if (ladder.size() > max_ladder) break;
    }
  }
  if (ladder.size() > max_ladder) {
    r.fail(e, fmt::format("the range gives more than {} values; use a larger factor", max_ladder));
  }
  return ladder;
}

budget_spec parse_budget(const scene_reader& r, const entry& e) {
  const toml::table& t = r.table(e, "a [budget] table");
  r.check_keys(t, budget_keys, "budget", "[budget]");
  budget_spec b;
  const auto N = r.find(t, "N", "budget");
  if (!N) r.fail(r.at(t.source()), "budget.N", "missing required key (the N ladder)");
  b.N = parse_ladder(r, *N);
  b.N_location = r.at(*N);
  if (const auto m = r.find(t, "max_evaluations", "budget")) {
    b.max_evaluations = r.count(*m, 1, std::numeric_limits<std::int64_t>::max(),
                                "a whole number of evaluations from 1 to 2^63 − 1");
  }
  if (const auto s = r.find(t, "max_seconds", "budget")) {
    const double v = r.number(*s, "a positive number of seconds");
    if (!(v > 0.0)) r.expected(*s, "a positive number of seconds");
    b.max_seconds = v;
  }
  if (const auto s = r.find(t, "timing_min_seconds", "budget")) {
    const double v = r.number(*s, "a number of seconds between 0 and 60");
    if (!(v >= 0.0 && v <= 60.0)) r.expected(*s, "a number of seconds between 0 and 60");
    b.timing_min_seconds = v;
  }
  if (const auto e = r.find(t, "paired_timing_rounds", "budget")) {
    // A TOML integer: a count of rounds, not a number that happens to be whole. make_plan checks
    // the same range for scenes built in C++.
    const std::uint64_t rounds =
        r.integer(*e, 0, max_paired_timing_rounds, paired_timing_rounds_expected);
    if (!valid_paired_timing_rounds(rounds)) r.expected(*e, paired_timing_rounds_expected);
    b.paired_timing_rounds = rounds;
    b.paired_timing_rounds_location = r.at(*e);
  }
  return b;
}

output_spec parse_output(const scene_reader& r, const entry& e) {
  const toml::table& t = r.table(e, "an [output] table");
  r.check_keys(t, output_keys, "output", "[output]");
  output_spec o;
  if (const auto v = r.find(t, "csv", "output")) o.csv = r.boolean(*v);
  if (const auto v = r.find(t, "markdown", "output")) o.markdown = r.boolean(*v);
  if (const auto v = r.find(t, "plots", "output")) o.plots = r.boolean(*v);
  // The plots are drawn from convergence.csv (bench/plot.py reads it from the results folder).
  if (o.plots && !o.csv) {
    const auto plots = r.find(t, "plots", "output");
    const auto csv = r.find(t, "csv", "output");
    r.fail(plots ? r.at(*plots) : r.at(t.source()), "output.plots",
           fmt::format("plots need the CSV they are drawn from, but output.csv = false (line {}); "
                       "set plots = false or csv = true",
                       r.at(*csv).line));
  }
  return o;
}

// ---------------------------------------------------------------------------------------------

scene parse_root(const scene_reader& r, const toml::table& root) {
  const source_location file_start{r.file(), 1, 1};
  if (root.empty()) {
    r.fail(file_start, "",
           "empty scene: expected at least [[integrand]], [[method]] and [budget] tables");
  }
  r.check_keys(root, top_level_keys, "", "the scene");

  scene sc;
  sc.file = r.file();
  if (const auto e = r.find(root, "name", "")) {
    sc.name = r.display_name(*e, false);
  } else {
    sc.name = scene_name_from_file(r.file());
  }
  if (const auto e = r.find(root, "description", "")) sc.description = r.string(*e, "a string");
  if (const auto e = r.find(root, "seed", "")) {
    sc.seed = r.count(*e, 0, std::numeric_limits<std::int64_t>::max(), "an integer ≥ 0");
  }
  if (const auto e = r.find(root, "rng", "")) {
    // The generator of every random stream of the methods (core/rng.hpp); the integrands' own
    // random parameters stay Philox, so both generators see the same integrands.
    const std::string what = fmt::format("one of: {}", rng_kind_names());
    const std::string given = r.string(*e, what);
    try {
      sc.rng = parse_rng_kind(given);
    } catch (const invalid_argument&) {
      r.expected(*e, what);
    }
  }
  if (const auto e = r.find(root, "threads", "")) {
    sc.threads = static_cast<unsigned>(
        r.count(*e, 0, 4096, "a thread count between 0 (all cores) and 4096"));
  }

  const auto integrands = r.find(root, "integrand", "");
  if (!integrands) {
    r.fail(file_start, "integrand", "missing: a scene needs at least one [[integrand]] table");
  }
  const toml::array& integrand_tables = r.tables(*integrands, "integrand");
  std::map<std::string, std::size_t> taken;
  for (std::size_t i = 0; i < integrand_tables.size(); ++i) {
    parse_integrand(r, *integrand_tables.get(i)->as_table(), i + 1, sc.integrands, taken);
  }

  const auto methods = r.find(root, "method", "");
  if (!methods)
    r.fail(file_start, "method", "missing: a scene needs at least one [[method]] table");
  const toml::array& method_tables = r.tables(*methods, "method");
  const integrand_names names = names_of(sc.integrands);
  if (method_tables.size() > scene_limits::max_methods) {
    const auto& extra = *method_tables.get(scene_limits::max_methods)->as_table();
    r.fail(r.at(extra.source()), fmt::format("method[{}]", scene_limits::max_methods + 1),
           fmt::format("{} [[method]] tables; at most {}", method_tables.size(),
                       scene_limits::max_methods));
  }
  for (std::size_t i = 0; i < method_tables.size(); ++i) {
    method_spec m = parse_method(r, *method_tables.get(i)->as_table(), i + 1, sc.integrands, names);
    for (const auto& other : sc.methods) {
      if (other.label == m.label) {
        r.fail(m.table, fmt::format("method[{}].label", i + 1),
               fmt::format("method label '{}' is already used by method[{}] (line {}); set a "
                           "distinct `label`",
                           m.label, other.table_index, other.table.line));
      }
    }
    sc.methods.push_back(std::move(m));
  }

  const auto budget = r.find(root, "budget", "");
  if (!budget) r.fail(file_start, "budget", "missing required table [budget] (with N)");
  sc.budget = parse_budget(r, *budget);
  if (const auto e = r.find(root, "output", "")) sc.output = parse_output(r, *e);
  return sc;
}

}  // namespace

namespace {

bool is_portable_char(char c) noexcept {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.';
}

}  // namespace

bool is_portable_name(std::string_view name) noexcept {
  if (name.empty() || name == "." || name == "..") return false;
  return std::all_of(name.begin(), name.end(), is_portable_char);
}

// FNV-1a (32 bits: offset basis 2166136261, prime 16777619) over the file name's bytes: a hash
// fixed by its definition, the same on every machine, so the folder name is too.
std::string scene_name_from_file(const std::filesystem::path& file, std::string_view when_empty) {
  const std::string stem = file.stem().string();
  if (is_portable_name(stem)) return stem;
  if (stem.empty()) return std::string(when_empty);
  std::string name;
  std::uint32_t hash = 2166136261u;
  for (const char c : stem) {
    hash = (hash ^ static_cast<unsigned char>(c)) * 16777619u;
    name += is_portable_char(c) ? c : '_';
  }
  return fmt::format("{}-{:08x}", name, hash);
}

std::span<const scene_table_keys> scene_keys() noexcept {
  return key_tables;
}

scene parse_scene(std::string_view toml_text, std::string_view file_name) {
  const scene_reader reader{std::string(file_name)};
  if (toml_text.size() > scene_limits::max_file_bytes) {
    throw scene_error({std::string(file_name), 0, 0}, "",
                      fmt::format("the scene is {} bytes; a scene file has at most {} (1 MiB)",
                                  toml_text.size(), scene_limits::max_file_bytes));
  }
  return parse_root(reader, reader.parse(toml_text));
}

scene parse_scene_file(const std::filesystem::path& path) {
  return parse_scene(read_scene_file(path), path.string());
}

std::string read_scene_file(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  const std::string name = path.string();
  auto fail = [&](std::string_view message) -> scene_error {
    return scene_error({name, 0, 0}, "", message);
  };
  // Only regular files and pipes (`quadmc run <(generate-scene)`) are read, and never more than
  // the limit plus one byte: /dev/zero, /dev/urandom or a terminal would otherwise be read until
  // memory runs out or forever.
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw fail("cannot open the scene file");
  if (fs::is_directory(status)) throw fail("is a directory, not a scene file");
  if (!fs::is_regular_file(status) && !fs::is_fifo(status)) {
    throw fail(fmt::format("not a regular file (a {}); a scene is a TOML file of at most {} bytes",
                           fs::is_character_file(status) ? "character device"
                           : fs::is_block_file(status)   ? "block device"
                           : fs::is_socket(status)       ? "socket"
                                                         : "special file",
                           scene_limits::max_file_bytes));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw fail("cannot open the scene file");
  std::string text;
  std::array<char, 65536> buffer{};
  while (text.size() <= scene_limits::max_file_bytes) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    text.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
    if (!in) break;
  }
  if (in.bad()) throw fail("cannot read the scene file");
  if (text.size() > scene_limits::max_file_bytes) {
    throw fail(fmt::format("the scene file is larger than {} bytes (1 MiB), the limit",
                           scene_limits::max_file_bytes));
  }
  return text;
}

}  // namespace quadmc
