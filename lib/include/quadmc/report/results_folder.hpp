// Writes a results folder: results/<scene>/{convergence.csv, slopes.csv, who_leads.csv, meta.csv,
// README.md}, and time_to_error_pairs.csv where the run paired time-to-error winners
// (time_to_error_table.hpp); the plots are added by bench/plot.py, run as
// plot_command_line(script, folder) after this.
//
// Use it once per run, after analyse_convergence on every series. Not for partial output: the
// files are written together from the same tables and run_info, so they never disagree.
#pragma once

#include "quadmc/analysis/convergence_table.hpp"
#include "quadmc/report/markdown_report.hpp"

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

// Which files to write (outputs not asked for are not written:
// docs/design.md#skip-what-a-scene-does-not-need). bench/plot.py reads the CSV files, so a scene
// that wants plots needs csv = true.
struct results_outputs {
  bool csv = true;       // convergence.csv, slopes.csv, who_leads.csv (who_leads.hpp),
                         // time_to_error_pairs.csv (with run_info::paired_timing's pairs) and
                         // meta.csv (provenance.hpp: what made them, from run_info::build)
  bool markdown = true;  // README.md
};

// Creates `folder` if needed and (over)writes the files asked for. Throws invalid_argument naming
// the file that cannot be written.
void write_results_folder(const std::filesystem::path& folder, const run_info& info,
                          std::span<const convergence_table> tables,
                          const results_outputs& outputs = {});

// True for the names of the files a run writes into a results folder: convergence.csv,
// slopes.csv, who_leads.csv, time_to_error_pairs.csv, meta.csv, README.md and plots (*.svg,
// including the names of earlier versions, and *.png: the summary figures of answer_first.hpp).
// The output-folder rules of `quadmc run` replace a folder only when every entry passes. Only the
// name: whether the entry is a regular file (a folder "figures.svg" is not a plot) is the
// caller's check, since it needs the file system.
bool is_results_file_name(std::string_view name);

// argv of the plot step: {python, script, folder}, e.g.
// {"/usr/bin/python3", "bench/plot.py", "results/default"}. Debian's python3 with
// python3-matplotlib (run.sh installs it), never a pyenv one.
std::vector<std::string> plot_command_line(const std::filesystem::path& script,
                                           const std::filesystem::path& folder,
                                           const std::string& python = "/usr/bin/python3");

}  // namespace quadmc
