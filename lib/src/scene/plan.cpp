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
#include <limits>
#include <optional>

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

bool restricted_to(const method_spec& method, const integrand_spec& f) {
  if (method.integrands.empty()) return true;
  return std::any_of(method.integrands.begin(), method.integrands.end(),
                     [&](const std::string& n) { return n == f.name || n == f.base_name; });
}

source_location key_location(const key_locations& keys, std::string_view key,
                             const source_location& fallback) {
  const auto it = keys.find(key);
  return it == keys.end() ? fallback : it->second;
}

// A name in a method's `integrands` list that matches only integrands the method cannot
// integrate is an impossible pairing the scene asked for explicitly: an error, not a skip.
void check_explicit_pairings(const scene& sc) {
  for (const auto& method : sc.methods) {
    const method_info& info = *find_method(method.name);
    for (std::size_t i = 0; i < method.integrands.size(); ++i) {
      const std::string& n = method.integrands[i];
      std::optional<std::string> reason;
      bool any_compatible = false;
      for (const auto& f : sc.integrands) {
        if (f.name != n && f.base_name != n) continue;
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
  for (std::size_t k = 0; k < f.ensemble; ++k) {
    params.seed = stream_id({sc.seed, index, k});
    try {
      plan_instance inst{index, k, params.seed, params, make_integrand(f.family, params), {}};
      inst.params.dimension = inst.function.dimension();
      if (genz) {
        genz_parameters drawn =
            genz_random_parameters(*genz, inst.function.dimension(), params.seed);
        if (!f.vectors.contains("a")) inst.drawn.emplace("a", std::move(drawn.a));
        if (!f.vectors.contains("u")) inst.drawn.emplace("u", std::move(drawn.u));
      }
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

// The cells of one (integrand, method) pair for instance 0, and its skips.
void plan_pair(const scene& sc, std::size_t fi, std::size_t mi, std::vector<plan_cell>& cells,
               std::vector<plan_skip>& skips) {
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
  for (std::size_t fi = 0; fi < input.integrands.size(); ++fi) {
    build_instances(p.source, fi, p.instances);
  }
  const scene& sc = p.source;
  check_explicit_pairings(sc);
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

  for (std::size_t fi = 0; fi < sc.integrands.size(); ++fi) {
    const integrand_spec& f = sc.integrands[fi];
    std::vector<plan_cell> pair_cells;
    for (std::size_t mi = 0; mi < sc.methods.size(); ++mi) {
      const method_spec& method = sc.methods[mi];
      if (!restricted_to(method, f)) continue;  // not asked for: neither a cell nor a skip
      if (const auto why = incompatibility(method, *find_method(method.name), f)) {
        p.skips.push_back({fmt::format("{} × {}", method.label, f.name), *why});
        continue;
      }
      plan_pair(sc, fi, mi, pair_cells, p.skips);
    }
    // Every instance of an ensemble runs the same cells; only the integrand (and its streams)
    // differ.
    for (std::size_t k = 0; k < f.ensemble; ++k) {
      for (plan_cell c : pair_cells) {
        c.instance = k;
        c.stream_parts = {c.integrand, k, c.method, c.nominal_N};
        p.total_evaluations =
            saturating_sum(p.total_evaluations, saturating_product(c.evaluations, c.repetitions));
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
