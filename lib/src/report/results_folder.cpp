// write_results_folder: the text files of a results folder (results_folder.hpp).
#include "quadmc/report/results_folder.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/report/provenance.hpp"
#include "quadmc/report/results_csv.hpp"
#include "quadmc/report/time_to_error_table.hpp"
#include "quadmc/report/who_leads.hpp"

#include <fstream>

namespace quadmc {
namespace {

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw invalid_argument("file", file.string(), "a writable path");
}

}  // namespace

void write_results_folder(const std::filesystem::path& folder, const run_info& info,
                          std::span<const convergence_table> tables,
                          const results_outputs& outputs) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec)
    throw invalid_argument("folder", folder.string(), "a creatable directory: " + ec.message());
  // meta.csv with any output: it says what wrote the folder, and it is what a later run checks
  // before it replaces the folder (report/results_staging.hpp).
  write_text(folder / meta_csv_file, meta_csv_text(info.build));
  if (outputs.csv) {
    write_text(folder / "convergence.csv", convergence_csv_text(info.scene, tables));
    write_text(folder / "slopes.csv", slopes_csv_text(info.scene, tables));
    // The "Who leads" tables of the page as data, for bench/plot.py's summary figure.
    write_text(folder / who_leads_csv_file, who_leads_csv_text(info.scene, who_leads(tables)));
    // Only where the run paired time-to-error winners: a scene without peers writes what it
    // wrote before the paired timing existed.
    if (!info.paired_timing.pairs.empty()) {
      write_text(folder / time_to_error_pairs_csv_file,
                 time_to_error_pairs_csv_text(info.scene, info.paired_timing.pairs));
    }
  }
  if (outputs.markdown) write_text(folder / "README.md", render_results_markdown(info, tables));
}

bool is_results_file_name(std::string_view name) {
  return name == "convergence.csv" || name == "slopes.csv" || name == meta_csv_file ||
         name == who_leads_csv_file || name == time_to_error_pairs_csv_file ||
         name == "README.md" ||
         (name.size() > 4 && (name.ends_with(".svg") || name.ends_with(".png")));
}

std::vector<std::string> plot_command_line(const std::filesystem::path& script,
                                           const std::filesystem::path& folder,
                                           const std::string& python) {
  return {python, script.string(), folder.string()};
}

}  // namespace quadmc
