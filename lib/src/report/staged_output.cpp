// The staged results folder of one run (report/staged_output.hpp).
#include "quadmc/report/staged_output.hpp"

#include "quadmc/report/interruption.hpp"
#include "quadmc/report/subprocess.hpp"

#include <fmt/format.h>

#include <utility>

namespace quadmc {

staged_output::staged_output(std::string kind, std::string parameter, std::string given,
                             const std::filesystem::path& folder,
                             const std::vector<std::string>& files,
                             results_file_predicate is_results_file)
    : kind_(std::move(kind)) {
  const auto held = interruption::hold();
  staging_ = std::make_unique<results_staging>(std::move(parameter), std::move(given), folder,
                                               files, is_results_file);
  interruption::set_cleanup([s = staging_.get(), kind = kind_] {
    s->finish();
    return fmt::format("removed this {}'s unfinished results; {} is untouched", kind,
                       s->folder().string());
  });
}

staged_output::~staged_output() {
  const auto held = interruption::hold();
  interruption::set_cleanup({});
  staging_.reset();
}

const std::filesystem::path& staged_output::staging() const noexcept {
  return staging_->staging();
}

void staged_output::write(const std::function<void(const std::filesystem::path&)>& write) {
  const auto held = interruption::hold();
  write(staging_->staging());
}

void staged_output::run_child(const std::vector<std::string>& argv) {
  run_subprocess(argv);
}

staged_output::committed staged_output::commit() {
  const auto held = interruption::hold();
  committed out;
  out.warning = staging_->commit();
  staging_->finish();
  out.written = "wrote " + staging_->folder().string();
  if (!staging_->link().empty())
    out.written += " (through the link " + staging_->link().string() + ")";
  interruption::set_cleanup(
      [kind = kind_, written = out.written] { return "the " + kind + " had already " + written; });
  return out;
}

}  // namespace quadmc
