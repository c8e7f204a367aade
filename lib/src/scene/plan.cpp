// Planning: scene → cells and skips (plan.hpp), and the `quadmc plan` listing.
#include "quadmc/scene/plan.hpp"

#include "quadmc/core/integer_powers.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/scene/paired_timing.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <bit>
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

// What a method may ask of an integrand before it is built: its family, s and whether it is a
// rendering integrand (catalogue.hpp). s = 0 (the family's default) resolves to the family's
// fixed dimension when it has one.
integrand_traits traits_of(const integrand_spec& f) {
  const catalogue_entry* entry = find_family(f.family);
  integrand_traits t;
  t.family = f.family;
  t.rendering = entry != nullptr && entry->rendering;
  t.s = f.dimension != 0                             ? f.dimension
        : entry != nullptr && entry->fixed_dimension ? entry->fixed_dimension
                                                     : 1;
  return t;
}

// Why `method` cannot integrate `f`, or nullopt when it can.
std::optional<std::string> incompatibility(const method_spec& method, const integrand_spec& f) {
  return method.configured->incompatibility(traits_of(f));
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
        const auto why = incompatibility(method, f);
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

// The parameters of f drawn from the seed (catalogue_entry::drawn): those the family draws and
// the scene does not give (a drawn scalar, as disk_random's r, is a vector of one value), each
// with its values for instance seed `seed`. Empty when every
// instance of an ensemble is the same integrand.
drawn_parameters drawn_for(const integrand_spec& f, std::size_t s, std::uint64_t seed) {
  drawn_parameters out;
  const catalogue_entry* entry = find_family(f.family);
  if (entry == nullptr || entry->drawn == nullptr) return out;
  integrand_params params;
  params.dimension = s;
  params.seed = seed;
  params.strings = f.strings;  // how a draw is shaped (Genz coefficient_decay)
  for (auto& [key, values] : entry->drawn(params)) {
    if (!f.vectors.contains(key) && !f.scalars.contains(key)) out.emplace(key, std::move(values));
  }
  return out;
}

bool draws_parameters(const integrand_spec& f, std::size_t s) {
  return !drawn_for(f, s, 0).empty();
}

// How many cells a method makes per instance of an integrand: its explicit sizes, its
// tolerances, or the N ladder.
std::uint64_t cells_per_instance(const scene& sc, const method_spec& m, std::size_t s) {
  if (m.control == cell_control::tolerance) return m.tolerances.size();
  const std::size_t explicit_sizes = m.configured->explicit_sizes(s).size();
  return explicit_sizes != 0 ? explicit_sizes : sc.budget.N.size();
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
  // A given or computed reference replaces the exact value (resolve_references): an integrand
  // without one (NaN, an outside project's family, functions/catalogue.hpp add_integrands) is
  // measured from it.
  if (std::isnan(info.exact) && f.reference == reference_source::exact) {
    throw scene_error(f.table, prefix,
                      fmt::format("{} has no exact integral ({}): give `reference = <number>` "
                                  "with `reference_uncertainty`, or `reference = \"computed\"`",
                                  instance_name(f, inst), info.reference));
  }
  if (!std::isfinite(info.exact) && !std::isnan(info.exact)) {
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
    const catalogue_entry* entry = find_family(f.family);
    const bool vertex_sum = entry != nullptr && entry->vertex_sum_reference;
    if (vertex_sum && s <= 20) {
      const std::uint64_t built = draws_parameters(f, s) ? K : 1;
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
      per_instance += cells_per_instance(sc, sc.methods[mi], s);
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

  const catalogue_entry* entry = find_family(f.family);
  if (entry == nullptr) {
    std::string names;
    for (const auto& e : integrand_catalogue()) {
      names += fmt::format("{}{}", names.empty() ? "" : ", ", e.name);
    }
    throw scene_error(key_location(f.keys, "family", f.table), prefix + ".family",
                      fmt::format("unknown family \"{}\"; expected one of: {}", f.family, names));
  }
  integrand_params params;
  params.dimension = f.dimension;
  for (const auto& [k, v] : f.scalars) params.scalars.emplace(k, v);
  for (const auto& [k, v] : f.vectors) params.vectors.emplace(k, v);
  params.strings = f.strings;
  if (const auto problem = find_key_problem(*entry, params)) {
    throw scene_error(key_location(f.keys, problem->key, f.table),
                      fmt::format("{}.{}", prefix, problem->key), problem->message);
  }
  const bool draws = draws_parameters(f, dimension_bound(f));
  const std::size_t first = out.size();
  // Instance k draws from (seed, family, s, k) only, never from the integrand's position in the
  // scene: the same family at the same s is the same instance in any scene with that seed.
  const std::size_t s = resolved_dimension(*entry, f.dimension);
  for (std::size_t k = 0; k < f.ensemble; ++k) {
    params.seed = stream_id({sc.seed, name_id(f.family), s, k});
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
      inst.drawn = drawn_for(f, inst.function.dimension(), params.seed);
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
  if (c.level >= 0) return fmt::format("level {}, {} evaluations", c.level, c.evaluations);
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

// tolerance_kind = "relative" asks for tolerance·|I| of every instance: with I = 0 that target is
// 0, which no estimate reaches, and with a non-finite I it is no number, so both are refused here
// rather than run to the budget.
void check_relative_tolerance(const plan& p, const integrand_spec& f, std::size_t fi,
                              const method_spec& method) {
  for (const auto& inst : p.instances) {
    if (inst.integrand != fi) continue;
    const double exact = p.reference_of(inst);
    if (std::isfinite(exact) && exact != 0.0) continue;
    throw scene_error(
        key_location(method.keys, "tolerance_kind", method.table),
        fmt::format("method[{}].tolerance_kind", method.table_index),
        fmt::format("\"relative\" needs I ≠ 0, but integrand '{}'{} has I = {}: its targets "
                    "tolerance·|I| would be {}; use \"absolute\" or leave it out with `integrands`",
                    f.name, f.ensemble > 1 ? fmt::format(" (instance {})", inst.instance + 1) : "",
                    exact, std::isfinite(exact) ? "0" : "no number"));
  }
}

// The cells of one (integrand, method) pair for instance 0, and its skips.
void plan_pair(const scene& sc, std::size_t fi, std::size_t mi, double scale,
               std::vector<plan_cell>& cells, std::vector<plan_skip>& skips) {
  const integrand_spec& f = sc.integrands[fi];
  const method_spec& method = sc.methods[mi];
  const quadmc::method& m = *method.configured;
  const std::size_t s = f.dimension;
  const bool rule = method.kind() == method_kind::deterministic;
  const std::uint64_t repetitions = rule ? 1 : method.repetitions;
  auto what = [&](std::uint64_t N) {
    return fmt::format("{} × {}, N = {}", method.label, f.name, N);
  };

  std::vector<std::pair<std::uint64_t, plan_cell>> kept;  // (nominal N, cell) for duplicates
  // `note`: what the method says of this size (a sparse grid at its last level).
  auto consider = [&](std::uint64_t N, plan_cell c, const std::string& note = {}) {
    for (const auto& [earlier, k] : kept) {
      if (k.evaluations == c.evaluations && k.per_axis == c.per_axis && k.level == c.level) {
        skips.push_back(
            {what(N), fmt::format("same {} as N = {} ({}{})", rule ? "grid" : "strata", earlier,
                                  describe_grid(c), note.empty() ? "" : ": " + note)});
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
    // The files a method reads (external points) are read and checked now, before any work.
    try {
      m.check_inputs(s, c.size(), c.repetitions);
    } catch (const invalid_argument& e) {
      // At the `path` key the files come from, where the method has one.
      const bool at_path = method.keys.contains("path");
      throw scene_error(key_location(method.keys, "path", method.table),
                        fmt::format("method[{}]{}", method.table_index, at_path ? ".path" : ""),
                        e.what());
    }
    kept.emplace_back(N, c);
    cells.push_back(c);
  };

  plan_cell base;
  base.integrand = fi;
  base.method = mi;
  base.dimension = s;
  base.repetitions = repetitions;
  base.control = method.control;
  auto sized = [&](plan_cell c, const cell_size& size) {
    c.per_axis = size.per_axis;
    c.points_per_axis = size.points_per_axis;
    c.evaluations = size.evaluations;
    c.order = size.order;
    c.level = size.level;
    return c;
  };

  if (method.control == cell_control::tolerance) {
    // Each tolerance is a cell that may spend up to the budget per repetition: the scene's
    // max_evaluations shared by the repetitions, else plan_limits::default_tolerance_budget.
    const std::uint64_t budget = sc.budget.max_evaluations
                                     ? *sc.budget.max_evaluations / repetitions
                                     : plan_limits::default_tolerance_budget;
    const sizing largest = m.tolerance_size_for(budget, s);
    for (const double tolerance : method.tolerances) {
      const std::string at =
          fmt::format("{} × {}, tolerance = {}", method.label, f.name, tolerance);
      if (!largest.size) {
        skips.push_back(
            {at, fmt::format("within the budget of {} evaluations: {}", budget, largest.reason)});
        continue;
      }
      plan_cell c = sized(base, *largest.size);
      c.tolerance = tolerance;
      check_cell(sc, f, method, rule, scale, c.evaluations, c);
      cells.push_back(c);
    }
    return;
  }
  const std::vector<sizing> explicit_sizes = m.explicit_sizes(s);
  if (!explicit_sizes.empty()) {
    for (const sizing& size : explicit_sizes) {
      if (!size.size) {
        skips.push_back({fmt::format("{} × {}", method.label, f.name), size.reason});
        continue;
      }
      plan_cell c = sized(base, *size.size);
      c.nominal_N = c.evaluations;
      consider(c.nominal_N, c);
    }
    return;
  }
  for (std::uint64_t N : sc.budget.N) {
    const sizing size = m.size_for(N, s);
    if (!size.size) {
      skips.push_back({what(N), size.reason});
      continue;
    }
    plan_cell c = sized(base, *size.size);
    c.nominal_N = N;
    consider(N, c, size.reason);
  }
}

// A given or computed reference replaces the exact value in mean_reference (the parser refused
// both for an ensemble, so the integrand has one instance); a note says the exact value exists.
void resolve_references(plan& p) {
  const scene& sc = p.source;
  p.references.assign(sc.integrands.size(), plan_reference{});
  for (std::size_t fi = 0; fi < sc.integrands.size(); ++fi) {
    const integrand_spec& f = sc.integrands[fi];
    plan_reference& ref = p.references[fi];
    ref.source = f.reference;
    ref.value = p.mean_reference[fi];
    if (f.reference == reference_source::exact) continue;
    const std::string prefix = fmt::format("integrand[{}].reference", f.table_index);
    const source_location where = key_location(f.keys, "reference", f.table);
    const plan_instance* inst = nullptr;
    for (const auto& i : p.instances) {
      if (i.integrand == fi) inst = &i;
    }
    if (inst == nullptr || f.ensemble != 1) {
      throw scene_error(where, prefix, "only for a single integrand (ensemble = 1)");
    }
    const integrand_info& info = inst->function.info();
    if (f.reference == reference_source::given) {
      ref.value = f.reference_value;
      ref.uncertainty = f.reference_uncertainty;
    } else {
      if (f.dimension > max_computed_reference_dimension) {
        throw scene_error(where, prefix,
                          fmt::format("\"computed\" is for s ≤ {} (Genz–Malik needs 2^s + 2s² + "
                                      "2s + 1 evaluations per region), but {} has s = {}",
                                      max_computed_reference_dimension, f.name, f.dimension));
      }
      try {
        ref.computed = compute_reference(inst->function);
      } catch (const std::exception& e) {
        throw scene_error(
            where, prefix,
            fmt::format("computing the reference of {} failed: {}", f.name, e.what()));
      }
      if (!std::isfinite(ref.computed->value) || !std::isfinite(ref.computed->uncertainty)) {
        throw scene_error(where, prefix,
                          fmt::format("the computed reference of {} is {} ± {}: not finite", f.name,
                                      ref.computed->value, ref.computed->uncertainty));
      }
      ref.value = ref.computed->value;
      ref.uncertainty = ref.computed->uncertainty;
    }
    p.mean_reference[fi] = ref.value;
    const std::string exact =
        std::isnan(info.exact)
            ? fmt::format("the family has no exact value ({})", info.reference)
            : fmt::format("the family's exact value {:.17g} ({}) exists and is not used",
                          info.exact, info.reference);
    p.notes.push_back(fmt::format(
        "{}:{}: integrand[{}] ({}): errors are measured from the {} reference {:.17g} ± {:.2g}; {}",
        sc.file, where.line, f.table_index, f.name,
        f.reference == reference_source::given ? "given" : "computed", ref.value, ref.uncertainty,
        exact));
  }
}

// budget.paired_timing_rounds of a scene built in C++ (the parser refuses the same values in a
// file, at their line).
void check_paired_timing_rounds(const scene& sc) {
  const budget_spec& b = sc.budget;
  if (valid_paired_timing_rounds(b.paired_timing_rounds)) return;
  const source_location where =
      b.paired_timing_rounds_location.line != 0 ? b.paired_timing_rounds_location : b.N_location;
  throw scene_error(
      where, "budget.paired_timing_rounds",
      fmt::format("expected {}, got {}", paired_timing_rounds_expected, b.paired_timing_rounds));
}

}  // namespace

std::string plan_reference::describe() const {
  switch (source) {
    case reference_source::exact:
      return {};
    case reference_source::given:
      return fmt::format("given, uncertainty {:.2g}", uncertainty);
    case reference_source::computed:
      return "computed: " + (computed ? computed->describe() : std::string("?"));
  }
  return {};
}

const plan_instance& plan::instance_of(const plan_cell& c) const {
  for (const auto& i : instances) {
    if (i.integrand == c.integrand && i.instance == c.instance) return i;
  }
  throw invalid_argument("cell.integrand", fmt::format("{}/{}", c.integrand, c.instance),
                         "a cell of this plan");
}

double plan::reference_of(const plan_instance& inst) const {
  if (inst.integrand < references.size() &&
      references[inst.integrand].source != reference_source::exact) {
    return references[inst.integrand].value;
  }
  return inst.function.info().exact;
}

plan make_plan(const scene& input) {
  check_paired_timing_rounds(input);
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
    // No exact value (NaN, refused by check_reference unless a reference replaces it): the
    // reference joins the scale below.
    double m = std::isnan(info.exact) ? 0.0 : std::abs(info.exact);
    if (const auto& peak = info.derivative_bound[0]) {
      m = std::max(m, *peak * info.domain.volume());
    }
    scale[inst.integrand] = std::max(scale[inst.integrand], m);
  }
  for (std::size_t fi = 0; fi < sc.integrands.size(); ++fi) {
    const integrand_spec& f = sc.integrands[fi];
    p.mean_reference[fi] /= static_cast<double>(f.ensemble);
    if (f.reference == reference_source::exact && !std::isfinite(p.mean_reference[fi])) {
      throw scene_error(key_location(f.keys, "ensemble", f.table),
                        fmt::format("integrand[{}].ensemble", f.table_index),
                        fmt::format("the mean of the {} instances' exact integrals of {} "
                                    "overflows double; choose parameters with smaller integrals",
                                    f.ensemble, f.name));
    }
  }
  resolve_references(p);
  for (std::size_t fi = 0; fi < sc.integrands.size(); ++fi) {
    scale[fi] = std::max(scale[fi], std::abs(p.mean_reference[fi]));
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
    if (method.kind() == method_kind::deterministic && method.repetitions_given) {
      p.notes.push_back(
          fmt::format("{}:{}: method[{}] ({}): repetitions = {} ignored: a "
                      "deterministic rule runs once per N",
                      sc.file, key_location(method.keys, "repetitions", method.table).line,
                      method.table_index, method.label, method.repetitions));
    }
    if (!method.configured->explicit_sizes(1).empty()) {
      // Named by the method's own key: a rule's panels per axis, a quasi-Monte Carlo set's points.
      const std::string key = method.configured->explicit_sizes_key();
      p.notes.push_back(fmt::format("{}:{}: method[{}] ({}): explicit {} replace budget.N", sc.file,
                                    key_location(method.keys, key, method.table).line,
                                    method.table_index, method.label, key));
    }
    if (method.control == cell_control::tolerance) {
      p.notes.push_back(fmt::format(
          "method[{}] ({}): control = tolerance{}: one cell per tolerance, each spending at most "
          "{} evaluations per repetition",
          method.table_index, method.label,
          method.relative_tolerance ? " (relative: each tolerance times |I|)" : "",
          sc.budget.max_evaluations
              ? fmt::format(
                    "budget.max_evaluations / repetitions = {}",
                    *sc.budget.max_evaluations /
                        (method.kind() == method_kind::deterministic ? 1 : method.repetitions))
              : fmt::format("{} (no budget.max_evaluations)",
                            plan_limits::default_tolerance_budget)));
    }
  }

  // What a time-to-error scene costs after its cells (scene/paired_timing.hpp), said before the
  // run: the progress bar is full while it runs.
  if (may_pair_time_to_error(sc)) {
    const std::uint64_t rounds = sc.budget.paired_timing_rounds;
    p.notes.push_back(
        rounds == 0
            ? std::string("time to error: budget.paired_timing_rounds = 0: the ratios of quadmc's "
                          "best to the best peer are of single stable timings, no paired timing")
            : fmt::format("time to error: after the cells, quadmc's best and the best peer of "
                          "each (integrand, tolerance) both reach are timed again alternately, "
                          "budget.paired_timing_rounds = {} rounds of one stable timing each; "
                          "the page's ratio is their median",
                          rounds));
  }

  std::uint64_t repetitions = 0;
  for (std::size_t fi = 0; fi < sc.integrands.size(); ++fi) {
    const integrand_spec& f = sc.integrands[fi];
    std::vector<plan_cell> pair_cells;
    for (std::size_t mi = 0; mi < sc.methods.size(); ++mi) {
      const method_spec& method = sc.methods[mi];
      if (!restricted_to(restriction[mi], f)) continue;  // not asked for: neither a cell nor a skip
      if (const auto why = incompatibility(method, f)) {
        p.skips.push_back({fmt::format("{} × {}", method.label, f.name), *why});
        continue;
      }
      if (method.relative_tolerance) check_relative_tolerance(p, f, fi, method);
      plan_pair(sc, fi, mi, scale[fi], pair_cells, p.skips);
    }
    // Every instance of an ensemble runs the same cells; only the integrand (and its streams)
    // differ.
    for (std::size_t k = 0; k < f.ensemble; ++k) {
      for (plan_cell c : pair_cells) {
        c.instance = k;
        c.stream_parts = {
            name_id(f.name), k, name_id(sc.methods[c.method].label),
            std::isnan(c.tolerance) ? c.nominal_N : std::bit_cast<std::uint64_t>(c.tolerance)};
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
  line(fmt::format(
      "seed {}, rng {}, threads {}, max_evaluations per cell {}, max_seconds {}, "
      "timing_min_seconds {}",
      sc.seed, to_string(sc.rng),
      sc.threads == 0 ? std::string("0 (all cores)") : fmt::format("{}", sc.threads),
      sc.budget.max_evaluations ? fmt::format("{}", *sc.budget.max_evaluations)
                                : std::string("unlimited"),
      sc.budget.max_seconds ? fmt::format("{}", *sc.budget.max_seconds) : std::string("unlimited"),
      sc.budget.timing_min_seconds));
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
    line(head + (std::isnan(info.exact) ? std::string(", no exact value)")
                                        : fmt::format(", exact = {:.17g})", info.exact)));
    if (inst.integrand < p.references.size() &&
        p.references[inst.integrand].source != reference_source::exact) {
      const plan_reference& ref = p.references[inst.integrand];
      line(fmt::format("    reference = {:.17g} ± {:.2g} ({}); the errors are measured from it",
                       ref.value, ref.uncertainty, ref.describe()));
    }
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
    const std::string N = std::isnan(c.tolerance) ? fmt::format("{}", c.nominal_N)
                                                  : fmt::format("tol {:g}", c.tolerance);
    line(fmt::format("  {:<{}} {:>4} {:<{}} {:>16} {:>8} {:>16} {:>6} {:>5}", name, name_width,
                     c.dimension, sc.methods[c.method].label, label_width, N,
                     // A sparse grid has no n per axis; its level stands there instead.
                     c.level >= 0      ? fmt::format("L={}", c.level)
                     : c.per_axis == 0 ? std::string("-")
                                       : fmt::format("{}", c.per_axis),
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
