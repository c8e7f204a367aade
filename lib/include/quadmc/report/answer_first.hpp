// The answer at the top of a results page: at most five lines, right under the title and the
// scene's description, that say what the page's own tables say, so that a reader who opens the
// page to learn where quadrature beats Monte Carlo finds it on the first screen. Generated from
// the "Who leads at equal N" tables (who_leads.hpp) and the slope verdicts, never typed; the
// figures they link are drawn by bench/plot.py under the names below (keep the two in step).
//
// The lines, each present only when it has something to say:
//  1. smooth integrands (analytic, smooth), each family's smallest s: which method leads, on which
//     families, from which N;
//  2. the same at each family's largest s, for families run in several dimensions;
//  3. integrands that are not smooth (C0, singular, discontinuous), smallest and largest s;
//  4. how many slopes agree with theory, how many differ with a computed reason, which disagree
//     without one (the page's Findings, linked);
//  5. the two summary figures, where the run draws plots.
// A row's leader is the method that wins the last ladder N before the rounding floor and every N
// back to the one named ("from N = …"; "at every N" when that is the first); a row whose last two
// such N have different winners has no steady leader and says so. A win by a rounding-floor point
// (rounding_floor.hpp) is where the floor starts, not a lead: below it the methods differ by
// rounding (it counts for the leader only as the N where the leader itself got there first). A page
// without "Who leads" tables (one method per family, or only tolerance cells) says so in line 1 and
// what it has instead.
//
// Use it through render_results_markdown; the function is public for tests and other pages. Not
// for comparing runs (compare.hpp).
#pragma once

#include "quadmc/analysis/convergence_table.hpp"
#include "quadmc/report/who_leads.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

// The two summary figures, each as .svg and .png (bench/plot.py writes them from slopes.csv and
// who_leads.csv): every series' fitted slope against its theory, coloured by verdict, and the
// "Who leads at equal N" tables as a picture (only when there is a table). No per-series plot
// name starts like these (they start with "error_" or "work_precision_", markdown_report.hpp).
inline constexpr std::string_view slope_figure_stem = "slope_against_theory";
inline constexpr std::string_view who_leads_figure_stem = "who_leads";

// The lines, without Markdown list markers; at most five, at least one.
std::vector<std::string> answer_first_lines(std::span<const convergence_table> tables,
                                            std::span<const family_leaders> families, bool figures);

}  // namespace quadmc
