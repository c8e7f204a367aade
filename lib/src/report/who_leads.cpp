// The "Who leads at equal N" tables and who_leads.csv (report/who_leads.hpp).
#include "quadmc/report/who_leads.hpp"

#include "quadmc/report/csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace quadmc {

std::string family_stem(std::string_view integrand, std::size_t s) {
  const std::string suffix = fmt::format("_s{}", s);
  if (integrand.size() > suffix.size() && integrand.ends_with(suffix)) {
    return std::string(integrand.substr(0, integrand.size() - suffix.size()));
  }
  return std::string(integrand);
}

std::vector<family_leaders> who_leads(std::span<const convergence_table> tables) {
  std::vector<std::string> families;
  for (const convergence_table& t : tables) {
    const std::string f = family_stem(t.integrand, t.s);
    if (std::find(families.begin(), families.end(), f) == families.end()) families.push_back(f);
  }
  struct entry {
    const convergence_row* row;  // the method's cell of the largest ladder N' ≤ N
    const std::string* method;
  };
  std::vector<family_leaders> out;
  for (const std::string& family : families) {
    std::vector<const convergence_table*> members;
    for (const convergence_table& t : tables) {
      if (family_stem(t.integrand, t.s) == family) members.push_back(&t);
    }
    auto competitors = [&members](std::size_t s, std::uint64_t n) {
      std::vector<entry> at;
      for (const convergence_table* t : members) {
        if (t->s != s) continue;
        const convergence_row* best = nullptr;
        for (const convergence_row& row : t->rows) {
          if (row.n > 0 && row.n <= n && (best == nullptr || row.n > best->n)) best = &row;
        }
        if (best != nullptr) at.push_back({best, &t->method});
      }
      return at;
    };
    std::vector<std::size_t> dimensions;
    std::vector<std::uint64_t> ladder;
    for (const convergence_table* t : members) {
      for (const convergence_row& row : t->rows) {
        if (row.n == 0) continue;  // a cell run to a tolerance has no N
        if (competitors(t->s, row.n).size() < 2) continue;
        if (std::find(dimensions.begin(), dimensions.end(), t->s) == dimensions.end()) {
          dimensions.push_back(t->s);
        }
        if (std::find(ladder.begin(), ladder.end(), row.n) == ladder.end()) {
          ladder.push_back(row.n);
        }
      }
    }
    if (ladder.empty()) continue;
    std::sort(dimensions.begin(), dimensions.end());
    std::sort(ladder.begin(), ladder.end());
    family_leaders f{family, members.front()->regularity, ladder, {}};
    for (const std::size_t s : dimensions) {
      leaders_row r{s, {}};
      for (const std::uint64_t n : ladder) {
        const auto at = competitors(s, n);
        const bool ran =
            std::any_of(at.begin(), at.end(), [n](const entry& e) { return e.row->n == n; });
        if (at.size() < 2 || !ran) {
          r.cells.emplace_back();
          continue;
        }
        // The smallest error; a tie goes to the series listed first.
        const entry* best = &at.front();
        for (const entry& e : at) {
          if (e.row->stats.rmse < best->row->stats.rmse) best = &e;
        }
        r.cells.push_back(
            leader{*best->method, best->row->stats.rmse, best->row->n, best->row->floor});
      }
      f.rows.push_back(std::move(r));
    }
    out.push_back(std::move(f));
  }
  return out;
}

std::string who_leads_csv_text(std::string_view scene, std::span<const family_leaders> families) {
  std::string out = "scene,family,s,N,method,error,at_N,at_floor\n";
  for (const family_leaders& f : families) {
    for (const leaders_row& r : f.rows) {
      for (std::size_t k = 0; k < f.ladder.size(); ++k) {
        const std::optional<leader>& c = r.cells[k];
        // Shortest text that reads back to the same double, as results_csv.cpp writes numbers.
        const std::vector<std::string> fields = {
            std::string(scene),
            f.family,
            fmt::format("{}", r.s),
            fmt::format("{}", f.ladder[k]),
            c ? c->method : std::string(),
            c && !std::isnan(c->error) ? fmt::format("{}", c->error) : std::string(),
            c ? fmt::format("{}", c->at_n) : std::string(),
            c ? std::string(c->at_floor ? "1" : "0") : std::string()};
        out += csv_line(fields);
      }
    }
  }
  return out;
}

}  // namespace quadmc
