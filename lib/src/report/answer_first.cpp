// The answer at the top of a results page (report/answer_first.hpp).
#include "quadmc/report/answer_first.hpp"

#include "quadmc/analysis/slope_verdict.hpp"
#include "quadmc/report/time_to_error_table.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>

namespace quadmc {
namespace {

// A name as the tables print it, in code spans so that a '*' or '_' in it stays text.
std::string name(std::string_view text) {
  return fmt::format("`{}`", text);
}

// What one row (family, s) of a "Who leads" table says (the rule in answer_first.hpp).
struct row_answer {
  std::string where;              // "`gaussian` (s = 8)"
  std::optional<std::string> by;  // the steady leader; nullopt: none
  std::string from;               // " from N = 1024", " at every N", ""
};

row_answer answer_of(const family_leaders& f, const leaders_row& r) {
  row_answer a{fmt::format("{} (s = {})", name(f.family), r.s), std::nullopt, ""};
  struct won {
    std::uint64_t n;
    const leader* by;
  };
  std::vector<won> before_floor;
  std::optional<std::uint64_t> floor_from;
  const leader* first_at_floor = nullptr;  // the method that reached the floor first
  for (std::size_t k = 0; k < f.ladder.size(); ++k) {
    if (!r.cells[k]) continue;
    if (r.cells[k]->at_floor) {
      floor_from = f.ladder[k];
      first_at_floor = &*r.cells[k];
      break;
    }
    before_floor.push_back({f.ladder[k], &*r.cells[k]});
  }
  const std::string floor =
      floor_from ? fmt::format(" until the rounding floor at N = {}", *floor_from) : "";
  if (before_floor.empty()) {
    a.from = fmt::format(" (at the rounding floor from N = {})", floor_from.value_or(0));
    return a;
  }
  const std::string& last = before_floor.back().by->method;
  std::size_t first = before_floor.size() - 1;
  while (first > 0 && before_floor[first - 1].by->method == last) --first;
  // The method that reaches the rounding floor first extends its run by that N.
  const bool to_floor = first_at_floor != nullptr && first_at_floor->method == last;
  const std::size_t run = before_floor.size() - first + (to_floor ? 1 : 0);
  if (run < 2 && before_floor.size() > 1) return a;  // the last two N have different winners
  a.by = last;
  a.from = (first == 0 ? std::string(" at every N")
                       : fmt::format(" from N = {}", before_floor[first].n)) +
           floor;
  return a;
}

// "`simpson` leads `gaussian` (s = 1) from N = 16, `oscillatory` (s = 2) at every N; `smolyak`
// leads …; no steady leader on …": rows grouped by leader, the leader of most rows first.
std::string leaders_sentence(const std::vector<row_answer>& rows) {
  std::vector<std::pair<std::string, std::vector<const row_answer*>>> by;
  std::vector<const row_answer*> unsteady;
  for (const row_answer& r : rows) {
    if (!r.by) {
      unsteady.push_back(&r);
      continue;
    }
    auto it = std::find_if(by.begin(), by.end(), [&](const auto& g) { return g.first == *r.by; });
    if (it == by.end()) {
      by.emplace_back(*r.by, std::vector<const row_answer*>{});
      it = by.end() - 1;
    }
    it->second.push_back(&r);
  }
  std::stable_sort(by.begin(), by.end(),
                   [](const auto& a, const auto& b) { return a.second.size() > b.second.size(); });
  std::vector<std::string> parts;
  for (const auto& [method, led] : by) {
    std::vector<std::string> where;
    for (const row_answer* r : led) where.push_back(r->where + r->from);
    parts.push_back(fmt::format("{} leads {}", name(method), fmt::join(where, ", ")));
  }
  if (!unsteady.empty()) {
    std::vector<std::string> where;
    for (const row_answer* r : unsteady) where.push_back(r->where + r->from);
    parts.push_back(fmt::format("no steady leader on {}", fmt::join(where, ", ")));
  }
  return fmt::format("{}.", fmt::join(parts, "; "));
}

bool smooth(smoothness s) {
  return s == smoothness::analytic || s == smoothness::smooth;
}

std::string slopes_line(std::span<const convergence_table> tables) {
  std::size_t agree = 0;
  std::vector<std::pair<slope_verdict, std::size_t>> explained;  // verdict, count
  std::vector<std::pair<slope_verdict, std::size_t>> unjudged;
  std::vector<std::string> findings;
  for (const convergence_table& t : tables) {
    std::vector<std::pair<slope_verdict, std::size_t>>* counts = nullptr;
    switch (t.verdict) {
      case slope_verdict::agrees:
        agree += 1;
        continue;
      case slope_verdict::steeper:
      case slope_verdict::shallower:
      case slope_verdict::above_envelope:
        // The page's Findings: a slope no computed reason explains, or a point above its bound.
        findings.push_back(fmt::format("{} (s = {}) {} {}", name(t.integrand), t.s, name(t.method),
                                       to_string(t.verdict)));
        continue;
      case slope_verdict::no_theory:
      case slope_verdict::no_fit:
        counts = &unjudged;
        break;
      case slope_verdict::within_envelope:
      case slope_verdict::superconvergent:
      case slope_verdict::pre_asymptotic:
      case slope_verdict::at_floor:
        counts = &explained;
        break;
    }
    auto it = std::find_if(counts->begin(), counts->end(),
                           [&](const auto& c) { return c.first == t.verdict; });
    if (it == counts->end()) {
      counts->emplace_back(t.verdict, 1);
    } else {
      it->second += 1;
    }
  }
  auto listed = [](const std::vector<std::pair<slope_verdict, std::size_t>>& counts) {
    std::vector<std::string> out;
    for (const auto& [verdict, count] : counts) {
      out.push_back(fmt::format("{} {}", to_string(verdict), count));
    }
    return fmt::format("{}", fmt::join(out, ", "));
  };
  std::string line =
      fmt::format("**Slopes:** {} of {} series agree with theory", agree, tables.size());
  if (!explained.empty()) {
    std::size_t n = 0;
    for (const auto& c : explained) n += c.second;
    line += fmt::format("; {} differ from it with a computed reason ({})", n, listed(explained));
  }
  if (!unjudged.empty()) {
    std::size_t n = 0;
    for (const auto& c : unjudged) n += c.second;
    line += fmt::format("; {} {} not judged ({})", n, n == 1 ? "is" : "are", listed(unjudged));
  }
  // At most four named: the Findings section lists every one.
  constexpr std::size_t named = 4;
  if (findings.empty()) {
    line += "; none disagrees without a computed reason ([Findings](#findings): none).";
  } else {
    const std::size_t shown = std::min(named, findings.size());
    std::vector<std::string> some(findings.begin(), findings.begin() + static_cast<long>(shown));
    line += fmt::format(
        "; {} {} with no computed reason ([Findings](#findings)): {}{}.", findings.size(),
        findings.size() == 1 ? "disagrees" : "disagree", fmt::join(some, ", "),
        findings.size() > shown ? fmt::format(" and {} more", findings.size() - shown) : "");
  }
  return line;
}

}  // namespace

std::vector<std::string> answer_first_lines(std::span<const convergence_table> tables,
                                            std::span<const family_leaders> families,
                                            bool figures) {
  std::vector<std::string> lines;
  std::vector<row_answer> small_s, large_s, rough;
  for (const family_leaders& f : families) {
    if (f.rows.empty()) continue;
    auto& first = smooth(f.regularity) ? small_s : rough;
    first.push_back(answer_of(f, f.rows.front()));
    if (f.rows.size() > 1) {
      (smooth(f.regularity) ? large_s : rough).push_back(answer_of(f, f.rows.back()));
    }
  }
  if (!small_s.empty()) {
    lines.push_back(
        "**Smooth integrands (analytic, smooth), each family's smallest s, at equal "
        "N:** " +
        leaders_sentence(small_s));
  }
  if (!large_s.empty()) {
    lines.push_back("**Their largest s:** " + leaders_sentence(large_s));
  }
  if (!rough.empty()) {
    lines.push_back(
        "**Integrands that are not smooth (C0, singular, discontinuous), smallest and "
        "largest s:** " +
        leaders_sentence(rough));
  }
  if (families.empty()) {
    // What the page has instead of the tables the other lines summarise.
    std::size_t groups = 0;
    for (std::size_t k = 0; k < tables.size(); ++k) {
      const bool first = std::none_of(
          tables.begin(), tables.begin() + static_cast<long>(k), [&](const convergence_table& t) {
            return t.integrand == tables[k].integrand && t.s == tables[k].s;
          });
      if (first) groups += 1;
    }
    const bool to_error = !time_to_error_markdown(tables).empty();
    lines.push_back(fmt::format(
        "**Who leads:** no \"Who leads at equal N\" table (no integrand family has two methods at "
        "one N of a ladder); the page has {} {} of {} (integrand, s) {}, each with its own table "
        "below{}.",
        tables.size(), "series", groups, groups == 1 ? "group" : "groups",
        to_error ? ", and the [time to error](#time-to-error) of each method beside the peers"
                 : ""));
  }
  lines.push_back(slopes_line(tables));
  if (figures) {
    std::string line = fmt::format(
        "**Figures:** [every fitted slope against its theory]({0}.svg) ([PNG]({0}.png))",
        slope_figure_stem);
    if (!families.empty()) {
      line +=
          fmt::format(", [who leads at equal N]({0}.svg) ([PNG]({0}.png))", who_leads_figure_stem);
    }
    lines.push_back(line + ".");
  }
  return lines;
}

}  // namespace quadmc
