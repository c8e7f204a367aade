// The targets and their marks; what and why: targets.hpp.
#include "targets.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

namespace quadmc::peers {

const char* symbol(mark m) noexcept {
  switch (m) {
    case mark::met:
      return "✅";
    case mark::missed:
      return "❌";
    case mark::not_measurable:
      return "⚠";
    case mark::not_counted:
      return "";
  }
  return "";
}

bool starved(run_share r) noexcept {
  // NaN compares false: an unknown share is never the reason for ⚠.
  return r.cores < 0.75 * static_cast<double>(r.threads);
}

mark judge(double ratio, double goal, run_share numerator, run_share denominator) noexcept {
  if (starved(numerator) || starved(denominator)) return mark::not_measurable;
  return ratio >= goal ? mark::met : mark::missed;
}

namespace {

// A run's share of the machine, "?" when unknown (a subprocess).
std::string cores_text(double cores) {
  return std::isnan(cores) ? std::string("?") : fmt::format("{:.2f}", cores);
}

}  // namespace

std::vector<target_spec> performance_targets(std::uint64_t two_thread_min_n) {
  const std::vector<std::string> genz{"genz_oscillatory", "genz_gaussian"};
  const std::vector<std::string> points{"(points only)"};
  const std::string mc = "quadmc plain MC";
  std::vector<target_spec> t;
  auto per_evaluation = [&](const std::string& method, double goal,
                            std::vector<std::size_t> counted_s = {}) {
    t.push_back({fmt::format("{} / plain MC (1 thread each)", method), "throughput", method, 1, mc,
                 1, goal, genz, std::move(counted_s), 0, false, ""});
  };
  per_evaluation("quadmc jittered", 0.85);
  per_evaluation("quadmc Latin hypercube", 0.7);
  per_evaluation("quadmc tensor Simpson", 1.5, {2, 4, 8});
  per_evaluation("quadmc tensor trapezoid", 1.5, {2, 4, 8});
  per_evaluation("quadmc sobol lms_shift", 1.0);
  per_evaluation("quadmc sobol fast_owen", 1.0);
  per_evaluation("quadmc sobol owen", 0.5);
  per_evaluation("quadmc lattice shift", 1.5);
  // Plain MC against the integrand alone at s = 8, under each generator: at s = 8 plain MC draws
  // eight uniforms per point, and Philox's cost several times the integrand's there
  // (bench/peers/profile_notes.md), ARS's a few AES instructions per block
  // (docs/theory.md#counter-based-generators).
  for (const auto& [label, method] :
       {std::pair{"plain MC (1 thread) / integrand only (batch in cache)", mc},
        std::pair{"plain MC with ARS (1 thread) / integrand only (batch in cache)",
                  std::string(plain_mc_ars_method)}}) {
    t.push_back(
        {label, "throughput", method, 1, integrand_only_method, 1, 0.5, genz, {8}, 0, false, ""});
  }
  for (const char* m :
       {"quadmc plain MC", "quadmc jittered", "quadmc Latin hypercube", "quadmc tensor Simpson",
        "quadmc tensor trapezoid", "quadmc sobol lms_shift", "quadmc sobol fast_owen",
        "quadmc sobol owen", "quadmc halton owen", "quadmc lattice shift"}) {
    t.push_back({fmt::format("{}: 2 threads / 1 thread", m),
                 "throughput",
                 m,
                 2,
                 m,
                 1,
                 1.9,
                 genz,
                 {},
                 two_thread_min_n,
                 true,
                 integrand_only_method});
  }
  t.push_back({"Sobol' points: quadmc sobol lms_shift / scipy Sobol(scramble=True)",
               "points",
               "quadmc sobol lms_shift",
               1,
               "scipy Sobol scrambled",
               1,
               3.0,
               points,
               {},
               0,
               false,
               ""});
  t.push_back({"Sobol' points: quadmc sobol lms_shift / Boost.Random sobol_engine",
               "points",
               "quadmc sobol lms_shift",
               1,
               "Boost.Random sobol_engine",
               1,
               2.0,
               points,
               {},
               0,
               false,
               ""});
  t.push_back({"Sobol' points: quadmc sobol none / Boost.Random sobol_engine",
               "points",
               "quadmc sobol none",
               1,
               "Boost.Random sobol_engine",
               1,
               2.0,
               points,
               {},
               0,
               false,
               ""});
  // The first goals that still stand beside the current ones.
  t.push_back({"plain MC (1 thread) / scalar reference loop",
               "throughput",
               mc,
               1,
               "scalar reference loop",
               1,
               1.0,
               genz,
               {},
               0,
               false,
               ""});
  t.push_back({"plain MC (1 thread) / GSL plain",
               "throughput",
               mc,
               1,
               "GSL plain",
               1,
               2.0,
               genz,
               {},
               0,
               false,
               ""});
  t.push_back({"plain MC (1 thread) / Boost naive_monte_carlo (1 thread)",
               "throughput",
               mc,
               1,
               "Boost naive_monte_carlo",
               1,
               2.0,
               genz,
               {},
               0,
               false,
               ""});
  return t;
}

std::vector<target_line> evaluate_targets(const std::vector<target_spec>& specs,
                                          const std::vector<row>& rows,
                                          const std::vector<std::size_t>& dimensions) {
  using key = std::tuple<std::string, std::string, unsigned, std::string, std::size_t>;
  std::map<key, const row*> index;
  for (const row& r : rows) index[{r.run, r.method, r.threads, r.integrand, r.s}] = &r;
  auto find = [&](const std::string& run, const std::string& method, unsigned threads,
                  const std::string& integrand, std::size_t s) -> const row* {
    const auto it = index.find({run, method, threads, integrand, s});
    return it == index.end() ? nullptr : it->second;
  };
  std::vector<target_line> lines;
  for (const target_spec& spec : specs) {
    for (const std::string& integrand : spec.integrands) {
      target_line line{spec, integrand, {}};
      for (std::size_t s : dimensions) {
        target_cell cell;
        cell.s = s;
        const row* a = find(spec.run, spec.numerator, spec.numerator_threads, integrand, s);
        const row* b = find(spec.run, spec.denominator, spec.denominator_threads, integrand, s);
        if (a != nullptr && b != nullptr && a->seconds > 0.0 && b->seconds > 0.0) {
          cell.ratio = a->rate / b->rate;
          cell.numerator = {a->cpu_seconds / a->seconds, a->threads};
          cell.denominator = {b->cpu_seconds / b->seconds, b->threads};
          if (!spec.reference.empty()) {
            const row* ra = find(spec.run, spec.reference, spec.numerator_threads, integrand, s);
            const row* rb = find(spec.run, spec.reference, spec.denominator_threads, integrand, s);
            if (ra != nullptr && rb != nullptr && ra->seconds > 0.0 && rb->seconds > 0.0) {
              cell.reference = ra->rate / rb->rate;
            }
          }
          const bool s_counted =
              spec.counted_s.empty() ||
              std::find(spec.counted_s.begin(), spec.counted_s.end(), s) != spec.counted_s.end();
          const double smallest = std::min(a->evaluations, b->evaluations);
          if (!s_counted) {
            cell.note = fmt::format("s = {} not in the goal", s);
          } else if (smallest < static_cast<double>(spec.min_evaluations)) {
            cell.note = fmt::format("N = {:.0f} < {}", smallest, spec.min_evaluations);
          } else {
            cell.m = judge(*cell.ratio, spec.goal, cell.numerator, cell.denominator);
          }
        }
        line.cells.push_back(cell);
      }
      lines.push_back(std::move(line));
    }
  }
  return lines;
}

target_tally tally(const std::vector<target_line>& lines) {
  target_tally t;
  for (const target_line& l : lines) {
    for (const target_cell& c : l.cells) {
      if (!c.ratio) continue;
      t.met += c.m == mark::met ? 1 : 0;
      t.missed += c.m == mark::missed ? 1 : 0;
      t.not_measurable += c.m == mark::not_measurable ? 1 : 0;
    }
  }
  return t;
}

std::string targets_table(const std::vector<target_line>& lines,
                          const std::vector<std::size_t>& dimensions) {
  std::ostringstream o;
  o << "| ratio | integrand | goal |";
  for (std::size_t s : dimensions) o << " s = " << s << " |";
  o << "\n|---|---|---|";
  for (std::size_t i = 0; i < dimensions.size(); ++i) o << "---|";
  o << "\n";
  for (const target_line& l : lines) {
    std::string goal = fmt::format("≥ {}×", l.spec.goal);
    if (const std::uint64_t n = l.spec.min_evaluations; n > 0) {
      goal += std::has_single_bit(n) ? fmt::format(" (N ≥ 2^{})", std::countr_zero(n))
                                     : fmt::format(" (N ≥ {})", n);
    }
    o << "| " << l.spec.label << " | " << l.integrand << " | " << goal << " |";
    for (const target_cell& c : l.cells) {
      if (!c.ratio) {
        o << " — |";
        continue;
      }
      o << fmt::format(" {:.2f}×", *c.ratio);
      if (c.m == mark::not_counted) {
        o << " (" << c.note << ")";
      } else {
        o << " " << symbol(c.m);
      }
      if (l.spec.show_cores || c.m == mark::not_measurable) {
        o << fmt::format(" ({} / {} cores", cores_text(c.numerator.cores),
                         cores_text(c.denominator.cores));
        if (c.reference) o << fmt::format("; integrand alone {:.2f}×", *c.reference);
        o << ")";
      }
      o << " |";
    }
    o << "\n";
  }
  return o.str();
}

bool memory_constant(const rss_row& r, long bound_kib) noexcept {
  if (r.kib.size() < 2) return false;
  return r.kib.back() - r.kib.front() < bound_kib;
}

}  // namespace quadmc::peers
