#include "catalogue_listing.hpp"

#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/methods/registry.hpp"
#include "quadmc/scene/parse.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <iterator>
#include <vector>

namespace quadmc_cli {

std::string catalogue_listing() {
  std::string out;
  auto line = std::back_inserter(out);
  fmt::format_to(line, "integrands ([[integrand]] family = …):\n");
  for (const auto& e : quadmc::integrand_catalogue()) {
    fmt::format_to(line, "  {:<24} {:<14} {}\n", e.name, e.smoothness, e.description);
    if (!e.parameters.empty())
      fmt::format_to(line, "  {:<24} {:<14} keys: {}\n", "", "", e.parameters);
  }
  std::vector<std::string_view> common;
  for (const quadmc::scene_table_keys& t : quadmc::scene_keys()) {
    if (t.table != "method") continue;
    for (const std::string_view k : t.keys) {
      if (k != "name") common.push_back(k);
    }
  }
  fmt::format_to(line, "\nmethods ([[method]] name = …; every method also takes {}):\n",
                 fmt::join(common, ", "));
  for (const quadmc::method_descriptor* m : quadmc::method_registry()) {
    std::vector<std::string_view> controls;
    for (const quadmc::cell_control c : m->controls) controls.push_back(quadmc::to_string(c));
    fmt::format_to(line, "  {:<30} {:<13} {}\n", m->name,
                   m->kind == quadmc::method_kind::deterministic ? "deterministic" : "randomized",
                   m->description);
    fmt::format_to(line, "      control = {}\n", fmt::join(controls, " | "));
    for (const quadmc::option_doc& o : m->options) {
      fmt::format_to(line, "      {} = {}\n", o.key, o.meaning);
    }
  }
  fmt::format_to(line, "\npoint sets ([[method]] point_set = …, for importance/irradiance):\n");
  for (const auto& p : quadmc::point_set_catalogue()) {
    fmt::format_to(line, "  {:<30} {}\n", p.name, p.description);
    // The largest s its tables hold (Boost's Sobol' directions, the lattice's generating vector,
    // the Halton primes); the plan skips a larger integrand with this reason, `quadmc points`
    // refuses it (point_set_catalogue.hpp, dimension_problem).
    if (p.max_dimension != 0) fmt::format_to(line, "      s ≤ {}\n", p.max_dimension);
  }
  fmt::format_to(line, "  {:<30} {}\n", quadmc::external_point_set,
                 quadmc::external_point_set_description);
  fmt::format_to(line, "\nwarps ([[method]] warp = …, for importance):\n");
  for (const quadmc::warp_descriptor& w : quadmc::importance_warps()) {
    fmt::format_to(line, "  {:<30} {}; {{ name = \"{}\", {} = … }} (default {:g})\n", w.name,
                   w.description, w.name, w.parameter, w.default_value);
  }
  return out;
}

std::string slope_summary(std::span<const quadmc::convergence_table> tables) {
  std::string out;
  auto line = std::back_inserter(out);
  fmt::format_to(line, "{:<28} {:>2}  {:<30} {:>22}  {:>8}  {}\n", "integrand", "s", "method",
                 "slope [95% CI]", "theory", "verdict");
  for (const auto& t : tables) {
    const std::string slope = t.fit.ok() ? fmt::format("{:+.3f} [{:+.3f}, {:+.3f}]", t.fit.slope,
                                                       t.fit.ci_low, t.fit.ci_high)
                                         : std::string("(too few points)");
    const std::string theory =
        t.theory.slope ? fmt::format("{:+.3f}", *t.theory.slope) : std::string("—");
    fmt::format_to(line, "{:<28} {:>2}  {:<30} {:>22}  {:>8}  {}\n", t.integrand, t.s, t.method,
                   slope, theory, quadmc::to_string(t.verdict));
  }
  return out;
}

}  // namespace quadmc_cli
