// Planning: scene → cells and skips (plan.hpp), and the `quadmc plan` listing.
#include "quadmc/scene/plan.hpp"

#include "quadmc/core/rng.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/functions/genz.hpp"
#include "quadmc/scene/methods.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace quadmc {

namespace {

constexpr std::uint64_t saturated = std::numeric_limits<std::uint64_t>::max();

std::uint64_t saturating_product(std::uint64_t a, std::uint64_t b) noexcept {
  if (a != 0 && b > saturated / a) return saturated;
  return a * b;
}

std::uint64_t saturating_sum(std::uint64_t a, std::uint64_t b) noexcept {
  return b > saturated - a ? saturated : a + b;
}

// Families the irradiance estimators apply to: the rendering integrands of functions/
// irradiance.hpp (catalogue.hpp), whose irradiance_setup the estimators sample.
bool is_irradiance_family(std::string_view family) noexcept {
  return family == "irradiance_hemisphere" || family == "irradiance_area";
}

// Why `method` cannot integrate `f`, or nullopt when it can.
std::optional<std::string> incompatibility(const method_spec& method, const method_info& info,
                                           const integrand_spec& f) {
  switch (info.applies_to) {
    case integrand_requirement::any:
      return std::nullopt;
    case integrand_requirement::one_dimensional:
      if (f.dimension == 1) return std::nullopt;
      if (method.name == "importance") {
        return fmt::format("the '{}' warp is a 1D density; the integrand has s = {}", method.warp,
                           f.dimension);
      }
      return fmt::format("{} is one-dimensional; the integrand has s = {}", method.name,
                         f.dimension);
    case integrand_requirement::irradiance:
      if (is_irradiance_family(f.family)) return std::nullopt;
      return fmt::format("{} estimates irradiance; '{}' is not a rendering integrand", method.name,
                         f.family);
  }
  return std::nullopt;
}

// Each method's `integrands` list as a set (empty = every integrand): make_plan asks whether a
// method takes an integrand for every pair, up to 4096 × 1024 of them.
using name_set = std::set<std::string_view, std::less<>>;

std::vector<name_set> restrictions_of(const scene& sc) {
  std::vector<name_set> out;
  for (const auto& method : sc.methods) {
    out.emplace_back(method.integrands.begin(), method.integrands.end());
  }
  return out;
}

bool restricted_to(const name_set& names, const integrand_spec& f) {
  return names.empty() || names.contains(f.name) || names.contains(f.base_name);
}

source_location key_location(const key_locations& keys, std::string_view key,
                             const source_location& fallback) {
  const auto it = keys.find(key);
  return it == keys.end() ? fallback : it->second;
}

// A name in a method's `integrands` list that matches only integrands the method cannot
// integrate is an impossible pairing the scene asked for explicitly: an error, not a skip.
void check_explicit_pairings(const scene& sc) {
  // Integrands by every name a list may use, so each check visits only the integrands it names.
  std::map<std::string_view, std::vector<std::size_t>, std::less<>> by_name;
  for (std::size_t fi = 0; fi < sc.integrands.size(); ++fi) {
    const integrand_spec& f = sc.integrands[fi];
    by_name[f.name].push_back(fi);
    if (f.base_name != f.name) by_name[f.base_name].push_back(fi);
  }
  for (const auto& method : sc.methods) {
    const method_info& info = *find_method(method.name);
    name_set seen;
    for (std::size_t i = 0; i < method.integrands.size(); ++i) {
      const std::string& n = method.integrands[i];
      if (!seen.insert(n).second) continue;  // a repeated name says nothing new
      std::optional<std::string> reason;
      bool any_compatible = false;
      const auto named = by_name.find(n);
      if (named == by_name.end()) continue;  // the parser checked that every name exists
      for (const std::size_t fi : named->second) {
        const integrand_spec& f = sc.integrands[fi];
        const auto why = incompatibility(method, info, f);
        if (why) {
          reason = why;
        } else {
          any_compatible = true;
        }
      }
      if (!any_compatible && reason) {
        throw scene_error(key_location(method.keys, "integrands", method.table),
                          fmt::format("method[{}].integrands[{}]", method.table_index, i + 1),
                          fmt::format("{} cannot integrate '{}': {}", method.label, n, *reason));
      }
    }
  }
}

// The parameter name of a catalogue message, e.g. "a" in "a[2]" or "u (centre)".
std::string_view leading_identifier(std::string_view parameter) {
  std::size_t end = 0;
  while (end < parameter.size() &&
         (std::isalnum(static_cast<unsigned char>(parameter[end])) != 0 || parameter[end] == '_')) {
    ++end;
  }
  return parameter.substr(0, end);
}

// The Genz family named `family`, if it is one: its omitted a and u are drawn from the seed by
// genz_random_parameters (the catalogue's documented rule), which the plan repeats to print them.
std::optional<genz_family> genz_family_named(std::string_view family) {
  for (int f = 0; f < 6; ++f) {
    if (to_string(static_cast<genz_family>(f)) == family) return static_cast<genz_family>(f);
  }
  return std::nullopt;
}

std::string list_of(std::span<const std::string_view> keys) {
  std::string out;
  for (std::string_view k : keys) out += fmt::format("{}{}", out.empty() ? "" : ", ", k);
  return out.empty() ? "none" : out;
}

// Whether the instances of an ensemble differ: only the Genz families draw parameters (a and u
// when the scene omits them, genz_random_parameters); every other family ignores the seed.
bool draws_parameters(const integrand_spec& f) {
  return genz_family_named(f.family) && (!f.vectors.contains("a") || !f.vectors.contains("u"));
}

// s as the catalogue will resolve it: 0 is the family default (1, or 2 for irradiance); 2 is
// the larger, so the size estimates below never undercount.
std::uint64_t dimension_bound(const integrand_spec& f) {
  return f.dimension == 0 ? 2 : f.dimension;
}

std::string instance_name(const integrand_spec& f, const plan_instance& inst) {
  return f.ensemble > 1
             ? fmt::format("{} (instance {} of {})", f.name, inst.instance + 1, f.ensemble)
             : f.name;
}

// What the run and its analysis need finite, checked once per built instance: the exact
// integral (every error is measured from it) and, where the family knows it, max|f| (the values
// a rule or a sample can reach).
void check_reference(const integrand_spec& f, const std::string& prefix,
                     const plan_instance& inst) {
  const integrand_info& info = inst.function.info();
  if (!std::isfinite(info.exact)) {
    throw scene_error(f.table, prefix,
                      fmt::format("exact integral is {} for {} ({}): the parameters give an "
                                  "integral beyond double's range; choose smaller ones",
                                  info.exact, instance_name(f, inst), info.reference));
  }
  if (const auto& peak = info.derivative_bound[0]; peak && !std::isfinite(*peak)) {
    throw scene_error(f.table, prefix,
                      fmt::format("max|f| is {} for {}: its values overflow double; choose "
                                  "smaller parameters",
                                  *peak, instance_name(f, inst)));
  }
}

// The plan's size, estimated from the scene alone and checked before anything is built: every
// bound of plan_limits, each reported at the integrand that crosses it.
void check_plan_size(const scene& sc, const std::vector<name_set>& restriction) {
  std::uint64_t instances = 0, coordinates = 0, terms = 0, cells = 0;
  for (const integrand_spec& f : sc.integrands) {
    const std::string prefix = fmt::format("integrand[{}]", f.table_index);
    const std::string key = f.ensemble_given
                                ? "ensemble"
                                : (f.keys.contains("dimensions") ? "dimensions" : "dimension");
    auto fail = [&](std::string_view message) {
      const bool located = f.keys.contains(key);
      throw scene_error(located ? f.keys.at(key) : f.table, located ? prefix + "." + key : prefix,
                        message);
    };
    const std::uint64_t s = dimension_bound(f);
    const std::uint64_t K = f.ensemble;
    instances += K;
    if (instances > plan_limits::max_instances) {
      fail(fmt::format("{} (ensemble = {}) brings the scene to {} integrand instances; at most {}",
                       f.name, K, instances, plan_limits::max_instances));
    }
    coordinates += K * s;
    if (coordinates > plan_limits::max_coordinates) {
      fail(
          fmt::format("{} (ensemble = {}, s = {}) brings the scene to {} instance coordinates "
                      "(Σ ensemble × s); at most {}",
                      f.name, K, s, coordinates, plan_limits::max_coordinates));
    }
    // The families' own limit (s ≤ 20) rejects larger s before any term is summed.
    const bool vertex_sum = f.family == "genz_corner_peak" || f.family == "half_space";
    if (vertex_sum && s <= 20) {
      const std::uint64_t built = draws_parameters(f) ? K : 1;
      terms += built << s;
      if (terms > plan_limits::max_reference_terms) {
        fail(
            fmt::format("{}: {} instance(s) of {} at s = {} need {} terms of its 2^s-vertex "
                        "closed form in all, about {:.0f} s of planning; at most {}",
                        f.name, built, f.family, s, terms, 1.4e-6 * static_cast<double>(terms),
                        plan_limits::max_reference_terms));
      }
    }
    std::uint64_t per_instance = 0;
    for (std::size_t mi = 0; mi < sc.methods.size(); ++mi) {
      if (!restricted_to(restriction[mi], f)) continue;
      const method_spec& m = sc.methods[mi];
      per_instance += m.panels.empty() ? sc.budget.N.size() : m.panels.size();
    }
    cells += per_instance * K;
    if (cells > plan_limits::max_cells) {
      const bool ensemble = K > 1;
      const source_location& where =
          ensemble ? key_location(f.keys, "ensemble", f.table) : sc.budget.N_location;
      throw scene_error(where, ensemble ? prefix + ".ensemble" : "budget.N",
                        fmt::format("{}: {} (method, N) pairs × {} instances bring the scene to "
                                    "{} cells; at most {} (fewer N values, methods or instances)",
                                    f.name, per_instance, K, cells, plan_limits::max_cells));
    }
  }
}

// Builds every instance of integrand `index`, resolving a default dimension, and re-raises the
// catalogue's complaints with the position of the [[integrand]] key they concern.
void build_instances(scene& sc, std::size_t index, std::vector<plan_instance>& out) {
  integrand_spec& f = sc.integrands[index];
  const std::string prefix = fmt::format("integrand[{}]", f.table_index);

  const auto catalogue = integrand_catalogue();
  const auto entry = std::find_if(catalogue.begin(), catalogue.end(),
                                  [&](const catalogue_entry& e) { return e.name == f.family; });
  if (entry == catalogue.end()) {
    std::string names;
    for (const auto& e : catalogue) names += fmt::format("{}{}", names.empty() ? "" : ", ", e.name);
    throw scene_error(key_location(f.keys, "family", f.table), prefix + ".family",
                      fmt::format("unknown family \"{}\"; expected one of: {}", f.family, names));
  }
  auto contains = [](std::span<const std::string_view> keys, std::string_view k) {
    return std::find(keys.begin(), keys.end(), k) != keys.end();
  };
  auto reject = [&](std::string_view key, std::string_view message) {
    throw scene_error(key_location(f.keys, key, f.table), fmt::format("{}.{}", prefix, key),
                      message);
  };
  const std::string keys_of_family = fmt::format(
      "arrays: {}; numbers: {}", list_of(entry->vector_keys), list_of(entry->scalar_keys));
  for (const auto& [k, v] : f.vectors) {
    if (contains(entry->vector_keys, k)) continue;
    if (contains(entry->scalar_keys, k)) {
      reject(k, fmt::format("expected a number for {}, got an array", f.family));
    }
    reject(k, fmt::format("unknown key: not a parameter of {} (its parameters: {})", f.family,
                          keys_of_family));
  }
  for (const auto& [k, v] : f.scalars) {
    if (contains(entry->scalar_keys, k)) continue;
    if (contains(entry->vector_keys, k)) {
      reject(k, fmt::format("expected an array of numbers for {}, got {}", f.family, v));
    }
    reject(k, fmt::format("unknown key: not a parameter of {} (its parameters: {})", f.family,
                          keys_of_family));
  }

  integrand_params params;
  params.dimension = f.dimension;
  for (const auto& [k, v] : f.scalars) params.scalars.emplace(k, v);
  for (const auto& [k, v] : f.vectors) params.vectors.emplace(k, v);
  const auto genz = genz_family_named(f.family);
  const bool draws = draws_parameters(f);
  const std::size_t first = out.size();
  for (std::size_t k = 0; k < f.ensemble; ++k) {
    params.seed = stream_id({sc.seed, index, k});
    if (k > 0 && !draws) {
      // Nothing is drawn from the seed: instance k is instance 0 (any_integrand shares it), and
      // a family whose reference costs 2^s terms is not summed K times.
      plan_instance copy = out[first];
      copy.instance = k;
      copy.seed = params.seed;
      copy.params.seed = params.seed;
      out.push_back(std::move(copy));
      continue;
    }
    try {
      plan_instance inst{index, k, params.seed, params, make_integrand(f.family, params), {}};
      inst.params.dimension = inst.function.dimension();
      if (genz) {
        genz_parameters drawn =
            genz_random_parameters(*genz, inst.function.dimension(), params.seed);
        if (!f.vectors.contains("a")) inst.drawn.emplace("a", std::move(drawn.a));
        if (!f.vectors.contains("u")) inst.drawn.emplace("u", std::move(drawn.u));
      }
      check_reference(f, prefix, inst);
      out.push_back(std::move(inst));
    } catch (const scene_error&) {
      throw;
    } catch (const invalid_argument& e) {
      const std::string key(leading_identifier(e.parameter()));
      const bool is_key = !key.empty() && f.keys.contains(key);
      throw scene_error(is_key ? f.keys.at(key) : f.table, is_key ? prefix + "." + key : prefix,
                        e.what());
    }
  }
  // s = 0 asked for the family's default; from here on the plan uses the real s.
  if (f.dimension == 0) f.dimension = out.back().function.dimension();
}

std::string describe_grid(const plan_cell& c) {
  if (c.points_per_axis != 0) {
    return fmt::format("n = {} per axis, {} evaluations", c.per_axis, c.evaluations);
  }
  return fmt::format("k = {} per axis, {} points", c.per_axis, c.evaluations);
}

// The checks a cell that will run must pass (plan.hpp): N·s within one random stream's counters,
// and values the run's sums can hold. `scale` is M = max over instances of max(|I|, max|f|·V).
void check_cell(const scene& sc, const integrand_spec& f, const method_spec& method, bool rule,
                double scale, std::uint64_t N, const plan_cell& c) {
  const std::uint64_t s = f.dimension;
  if (!rule && c.evaluations > (std::uint64_t{1} << 62) / s) {
    throw scene_error(
        sc.budget.N_location, "budget.N",
        fmt::format("N = {}: {} × {} would draw {} points in s = {}, but a random point set "
                    "needs N·s ≤ 2^62 (the counters of one Philox stream), so N ≤ {} for this "
                    "integrand",
                    N, method.label, f.name, c.evaluations, s, (std::uint64_t{1} << 62) / s));
  }
  // A Monte Carlo estimate sums N values Y = f·V and N squared deviations, each up to (2M)²; the
  // batch-merge formula (Chan, Golub & LeVeque) at most doubles that, so 8·M²·N < DBL_MAX keeps
  // every partial sum finite. A rule's value is at most M and its error est − I at most 2M.
  constexpr double largest = std::numeric_limits<double>::max();
  const double limit =
      rule ? largest / 4.0 : std::sqrt(largest / (8.0 * static_cast<double>(c.evaluations)));
  if (!(scale <= limit)) {
    const std::string prefix = fmt::format("integrand[{}]", f.table_index);
    const std::string values =
        std::isfinite(scale) ? fmt::format("up to {:.3g}", scale) : std::string("beyond 1.8e308");
    throw scene_error(
        f.table, prefix,
        rule ? fmt::format("values {} (max(|I|, max|f|·volume)) overflow {}'s error est − I "
                           "above {:.3g}; choose parameters with smaller values",
                           values, method.label, limit)
             : fmt::format("values {} (max(|I|, max|f|·volume)) are too large for {} at N = {}: "
                           "its sums of {} values and squared deviations overflow double above "
                           "{:.3g}; choose parameters with smaller values",
                           values, method.label, N, c.evaluations, limit));
  }
}

// The cells of one (integrand, method) pair for instance 0, and its skips.
void plan_pair(const scene& sc, std::size_t fi, std::size_t mi, double scale,
               std::vector<plan_cell>& cells, std::vector<plan_skip>& skips) {
  const integrand_spec& f = sc.integrands[fi];
  const method_spec& method = sc.methods[mi];
  const method_info& info = *find_method(method.name);
  const auto s = static_cast<unsigned>(f.dimension);
  const bool rule = info.kind == method_kind::deterministic_rule;
  const std::uint64_t repetitions = rule ? 1 : method.repetitions;
  const count_constraint counts =
      method.point_set.empty() ? info.counts : find_point_set(method.point_set)->counts;
  auto what = [&](std::uint64_t N) {
    return fmt::format("{} × {}, N = {}", method.label, f.name, N);
  };

  std::vector<std::pair<std::uint64_t, plan_cell>> kept;  // (nominal N, cell) for duplicates
  auto consider = [&](std::uint64_t N, plan_cell c) {
    for (const auto& [earlier, k] : kept) {
      if (k.evaluations == c.evaluations && k.per_axis == c.per_axis) {
        skips.push_back({what(N), fmt::format("same {} as N = {} ({})", rule ? "grid" : "strata",
                                              earlier, describe_grid(c))});
        return;
      }
    }
    const std::uint64_t cost = saturating_product(c.evaluations, c.repetitions);
    if (sc.budget.max_evaluations && cost > *sc.budget.max_evaluations) {
      skips.push_back(
          {what(N),
           rule ? fmt::format("{} evaluations exceed budget.max_evaluations = {}", c.evaluations,
                              *sc.budget.max_evaluations)
                : fmt::format("{} evaluations × {} repetitions = {} exceed "
                              "budget.max_evaluations = {}",
                              c.evaluations, c.repetitions, cost, *sc.budget.max_evaluations)});
      return;
    }
    check_cell(sc, f, method, rule, scale, N, c);
    kept.emplace_back(N, c);
    cells.push_back(c);
  };

  plan_cell base;
  base.integrand = fi;
  base.method = mi;
  base.dimension = f.dimension;
  base.repetitions = repetitions;

  if (!method.panels.empty()) {
    for (std::uint64_t n : method.panels) {
      const auto grid = tensor_grid_with_panels(info, n, s, method.m);
      if (!grid) {
        skips.push_back({fmt::format("{} × {}, n = {}", method.label, f.name, n),
                         fmt::format("{}^{} evaluations do not fit in 64 bits",
                                     points_per_axis(info, n, method.m), s)});
        continue;
      }
      plan_cell c = base;
      c.nominal_N = grid->evaluations;
      c.per_axis = grid->panels;
      c.points_per_axis = grid->points_per_axis;
      c.evaluations = grid->evaluations;
      c.order = grid->order;
      consider(c.nominal_N, c);
    }
    return;
  }
  for (std::uint64_t N : sc.budget.N) {
    plan_cell c = base;
    c.nominal_N = N;
    if (counts == count_constraint::tensor_grid) {
      const auto grid = largest_tensor_grid(info, N, s, method.m);
      if (!grid) {
        const std::uint64_t n_min = (method.name == "simpson" || method.name == "romberg") ? 2 : 1;
        const std::uint64_t p = points_per_axis(info, n_min, method.m);
        const auto smallest = checked_power(p, s);
        skips.push_back({what(N), smallest
                                      ? fmt::format("N is below the smallest grid, {}^{} = "
                                                    "{} evaluations",
                                                    p, s, *smallest)
                                      : fmt::format("N is below the smallest grid, {}^{}", p, s)});
        continue;
      }
      c.per_axis = grid->panels;
      c.points_per_axis = grid->points_per_axis;
      c.evaluations = grid->evaluations;
      c.order = grid->order;
    } else {
      const stratified_count sc_count = stratified_count_for(counts, N, s);
      c.per_axis = sc_count.per_axis;
      c.evaluations = sc_count.evaluations;
    }
    consider(N, c);
  }
}

}  // namespace

const plan_instance& plan::instance_of(const plan_cell& c) const {
  for (const auto& i : instances) {
    if (i.integrand == c.integrand && i.instance == c.instance) return i;
  }
  throw invalid_argument("cell.integrand", fmt::format("{}/{}", c.integrand, c.instance),
                         "a cell of this plan");
}

plan make_plan(const scene& input) {
  plan p;
  p.source = input;
  const std::vector<name_set> restriction = restrictions_of(p.source);
  check_plan_size(p.source, restriction);
  for (std::size_t fi = 0; fi < input.integrands.size(); ++fi) {
    build_instances(p.source, fi, p.instances);
  }
  const scene& sc = p.source;
  check_explicit_pairings(sc);

  // Ī per integrand (the runner's reference), and M = max(|I_k|, max|f|·V) for check_cell.
  p.mean_reference.assign(sc.integrands.size(), 0.0);
  std::vector<double> scale(sc.integrands.size(), 0.0);
  for (const auto& inst : p.instances) {
    const integrand_info& info = inst.function.info();
    p.mean_reference[inst.integrand] += info.exact;
    double m = std::abs(info.exact);
    if (const auto& peak = info.derivative_bound[0]) {
      m = std::max(m, *peak * info.domain.volume());
    }
    scale[inst.integrand] = std::max(scale[inst.integrand], m);
  }
  for (std::size_t fi = 0; fi < sc.integrands.size(); ++fi) {
    const integrand_spec& f = sc.integrands[fi];
    p.mean_reference[fi] /= static_cast<double>(f.ensemble);
    if (!std::isfinite(p.mean_reference[fi])) {
      throw scene_error(key_location(f.keys, "ensemble", f.table),
                        fmt::format("integrand[{}].ensemble", f.table_index),
                        fmt::format("the mean of the {} instances' exact integrals of {} "
                                    "overflows double; choose parameters with smaller integrals",
                                    f.ensemble, f.name));
    }
  }
  for (const auto& inst : p.instances) {
    const integrand_spec& f = sc.integrands[inst.integrand];
    if (inst.instance == 1 && inst.drawn.empty()) {
      // Every parameter is explicit (or the family draws none): the K instances coincide and the
      // ensemble only multiplies the cost.
      p.notes.push_back(
          fmt::format("{}:{}: integrand[{}] ({}): ensemble = {} but no parameter is "
                      "drawn from the seed, so every instance is the same integrand",
                      sc.file, key_location(f.keys, "ensemble", f.table).line, f.table_index,
                      f.name, f.ensemble));
    }
  }

  for (const auto& method : sc.methods) {
    const method_info& info = *find_method(method.name);
    if (info.kind == method_kind::deterministic_rule && method.repetitions_given) {
      p.notes.push_back(
          fmt::format("{}:{}: method[{}] ({}): repetitions = {} ignored: a "
                      "deterministic rule runs once per N",
                      sc.file, key_location(method.keys, "repetitions", method.table).line,
                      method.table_index, method.label, method.repetitions));
    }
    if (!method.panels.empty()) {
      p.notes.push_back(fmt::format("method[{}] ({}): explicit panels replace budget.N",
                                    method.table_index, method.label));
    }
  }

  std::uint64_t repetitions = 0;
  for (std::size_t fi = 0; fi < sc.integrands.size(); ++fi) {
    const integrand_spec& f = sc.integrands[fi];
    std::vector<plan_cell> pair_cells;
    for (std::size_t mi = 0; mi < sc.methods.size(); ++mi) {
      const method_spec& method = sc.methods[mi];
      if (!restricted_to(restriction[mi], f)) continue;  // not asked for: neither a cell nor a skip
      if (const auto why = incompatibility(method, *find_method(method.name), f)) {
        p.skips.push_back({fmt::format("{} × {}", method.label, f.name), *why});
        continue;
      }
      plan_pair(sc, fi, mi, scale[fi], pair_cells, p.skips);
    }
    // Every instance of an ensemble runs the same cells; only the integrand (and its streams)
    // differ.
    for (std::size_t k = 0; k < f.ensemble; ++k) {
      for (plan_cell c : pair_cells) {
        c.instance = k;
        c.stream_parts = {c.integrand, k, c.method, c.nominal_N};
        p.total_evaluations =
            saturating_sum(p.total_evaluations, saturating_product(c.evaluations, c.repetitions));
        repetitions = saturating_sum(repetitions, c.repetitions);
        if (repetitions > plan_limits::max_repetitions) {
          const method_spec& m = sc.methods[c.method];
          throw scene_error(
              key_location(m.keys, "repetitions", m.table),
              fmt::format("method[{}].repetitions", m.table_index),
              fmt::format("the cells up to {} × {} already hold {} repetitions; "
                          "the runner keeps a result per repetition, at most {} "
                          "(fewer repetitions, N values or instances)",
                          m.label, f.name, repetitions, plan_limits::max_repetitions));
        }
        p.cells.push_back(c);
      }
    }
  }

  const std::pair<const char*, bool> outputs[] = {
      {"csv", sc.output.csv}, {"markdown", sc.output.markdown}, {"plots", sc.output.plots}};
  for (const auto& [name, wanted] : outputs) {
    if (!wanted) {
      p.skips.push_back(
          {fmt::format("output {}", name), fmt::format("not asked for (output.{} = false)", name)});
    }
  }
  return p;
}

std::string format_plan(const plan& p) {
  const scene& sc = p.source;
  std::string out;
  auto line = [&out](std::string_view text) {
    out += text;
    out += '\n';
  };
  line(fmt::format("plan for scene '{}' ({})", sc.name, sc.file));
  line(fmt::format("seed {}, threads {}, max_evaluations per cell {}, max_seconds {}", sc.seed,
                   sc.threads == 0 ? std::string("0 (all cores)") : fmt::format("{}", sc.threads),
                   sc.budget.max_evaluations ? fmt::format("{}", *sc.budget.max_evaluations)
                                             : std::string("unlimited"),
                   sc.budget.max_seconds ? fmt::format("{}", *sc.budget.max_seconds)
                                         : std::string("unlimited")));
  std::string written;
  if (sc.output.csv) written += " csv";
  if (sc.output.markdown) written += " markdown";
  if (sc.output.plots) written += " plots";
  line(fmt::format("outputs:{}", written.empty() ? " none" : written));

  line("");
  line("integrands");
  for (const auto& inst : p.instances) {
    const integrand_spec& f = sc.integrands[inst.integrand];
    const auto& info = inst.function.info();
    std::string head = fmt::format("  {} (family {}, s = {}", f.name, f.family, f.dimension);
    if (f.ensemble > 1) head += fmt::format(", instance {} of {}", inst.instance + 1, f.ensemble);
    line(head + fmt::format(", exact = {:.17g})", info.exact));
    for (const auto& [key, values] : inst.drawn) {
      line(fmt::format("    {} = [{:.17g}]  (drawn from seed {:#018x})", key,
                       fmt::join(values, ", "), inst.seed));
    }
  }

  line("");
  line(fmt::format("cells ({}, {} evaluations in all)", p.cells.size(), p.total_evaluations));
  // Column widths from the contents, so long labels never shift the numbers.
  std::size_t name_width = 9;
  std::size_t label_width = 6;
  for (const auto& f : sc.integrands) name_width = std::max(name_width, f.name.size() + 4);
  for (const auto& m : sc.methods) label_width = std::max(label_width, m.label.size());
  line(fmt::format("  {:<{}} {:>4} {:<{}} {:>16} {:>8} {:>16} {:>6} {:>5}", "integrand", name_width,
                   "s", "method", label_width, "N", "n/axis", "evaluations", "reps", "order"));
  for (const auto& c : p.cells) {
    const integrand_spec& f = sc.integrands[c.integrand];
    std::string name = f.name;
    if (f.ensemble > 1) name += fmt::format("#{}", c.instance + 1);
    line(fmt::format("  {:<{}} {:>4} {:<{}} {:>16} {:>8} {:>16} {:>6} {:>5}", name, name_width,
                     c.dimension, sc.methods[c.method].label, label_width, c.nominal_N,
                     c.per_axis == 0 ? std::string("-") : fmt::format("{}", c.per_axis),
                     c.evaluations, c.repetitions,
                     c.order == 0 ? std::string("-") : fmt::format("{}", c.order)));
  }

  line("");
  line(fmt::format("skipped ({})", p.skips.size()));
  for (const auto& s : p.skips) line(fmt::format("  {}: {}", s.what, s.reason));
  if (!p.notes.empty()) {
    line("");
    line("notes");
    for (const auto& n : p.notes) line(fmt::format("  {}", n));
  }
  return out;
}

}  // namespace quadmc
