#include "catalogue_listing.hpp"

#include "quadmc/functions/catalogue.hpp"
#include "quadmc/scene/methods.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

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
  fmt::format_to(line, "\nmethods ([[method]] name = …):\n");
  for (const auto& m : quadmc::method_catalogue()) {
    fmt::format_to(line, "  {:<30} {:<7} {}\n", m.name,
                   m.kind == quadmc::method_kind::deterministic_rule ? "rule" : "random",
                   m.description);
  }
  fmt::format_to(line, "\npoint sets ([[method]] point_set = …, for importance/irradiance):\n");
  for (const auto& p : quadmc::point_set_catalogue()) {
    fmt::format_to(line, "  {:<30} {}\n", p.name, p.description);
  }
  fmt::format_to(line, "\nwarps ([[method]] warp = …, for importance):\n");
  for (const auto& w : quadmc::warp_catalogue()) {
    fmt::format_to(line, "  {:<30} {} (parameter {}, default {})\n", w.name, w.description,
                   w.parameter, w.default_value);
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
