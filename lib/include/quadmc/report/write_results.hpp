// A scene's results written as its results folder: convergence.csv, slopes.csv, meta.csv,
// README.md (and time_to_error_pairs.csv where the run paired time-to-error winners) and, when
// asked, the SVG plots, by the staging, lock, interruption and replace rules
// of staged_output.hpp. What `quadmc run` writes, for any program that ran scene/run_scene.hpp.
//
// Use write_results(folder, results, options) for one call; stage_results before the run and
// write_results(staged, results, options) after it when a refusal of the folder (a lock held, a
// name too long, a folder that is not a results folder) must cost nothing, as in the command. Not
// for the gallery's or the render's folders (their own files, through staged_output directly).
#pragma once

#include "quadmc/report/provenance.hpp"
#include "quadmc/report/staged_output.hpp"
#include "quadmc/scene/plan.hpp"
#include "quadmc/scene/run_scene.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

struct results_options {
  provenance build;    // what made the results (meta.csv, the page's header): the program's own
  unsigned ranks = 1;  // processes that ran the cells (the page's header)
  // bench/plot.py, which draws the SVGs from the CSV files; empty: no plots, whatever the scene's
  // [output] plots says (the page then links none).
  std::filesystem::path plot_script;
};

// Whether a run of `p` with `options` writes any file: [output] turns csv, markdown and plots off
// (the folder is then left alone and needs no staging).
bool writes_results(const plan& p, const results_options& options);

// The names of the files a run of `p` writes, for the checks made before it (a superset: the
// who-leads figure of answer_first.hpp is listed though a page without a table has none).
std::vector<std::string> result_file_names(const plan& p, const results_options& options);

// The staged folder of a run of `p`: `out` when given ("--out" in messages), else
// results/<scene name> (staged_output.hpp, results_folder_path). Null when the run writes nothing.
std::unique_ptr<staged_output> stage_results(const plan& p, const std::string& out,
                                             const results_options& options);

// What a run that writes nothing says instead of "wrote <folder>".
inline constexpr std::string_view nothing_written =
    "wrote nothing: [output] turns csv, markdown and plots off";

// Writes the files into the staged folder, draws the plots and commits. Returns "wrote <folder>"
// (and the link it went through); a warning about old results not removed completely goes to
// `warning` when given.
std::string write_results(staged_output& staged, const scene_results& results,
                          const results_options& options, std::string* warning = nullptr);
// Stages `folder`, then as above.
std::string write_results(const std::filesystem::path& folder, const scene_results& results,
                          const results_options& options, std::string* warning = nullptr);

}  // namespace quadmc
