// The results folder of a run (`quadmc run`, `gallery`, `render`, write_results; through
// staged_output.hpp): which folder it is, whether this run may replace it, and how the new results
// take the place of the old ones without ever losing either, and without deleting anything this
// run did not create.
//
// Use it once per run that writes files: construct it before the run (every refusal then costs
// nothing), write into staging(), commit(), finish(). Not for runs that write nothing (every
// [output] off: they leave the folder alone and need none of this), nor for reading folders
// (report/results_csv.hpp).
//
// The rules:
// - The folder is `--out`, or results/<scene name>, made absolute and without a trailing
//   separator ("out/" and "out" are one folder; "." and "/" are refused). A symlink as its last
//   component is followed: the folder it points to is replaced, the link is kept. A dangling link
//   is refused.
// - Only a results folder is replaced: one whose every entry is a regular file with a name a run
//   writes (report/results_folder.hpp, is_results_file_name). A subfolder, even one named
//   "figures.svg", a symlink or any other file makes it "not a results folder" and the run is
//   refused before it starts, so `--out .` or `--out ~` is an error, not a deleted folder.
// - One run at a time per folder: an exclusive flock(2) on ".<name>.lock" beside it, taken before
//   the run and held to the end. A second run exits at once with an error naming the lock (it
//   does not wait: a run may take hours, and a queue of runs writing one folder is a mistake).
// - Every run stages into a folder of its own, ".<name>.partial-XXXXXX" (mkdtemp(3)) beside the
//   target: no two runs share it, and being on the same file system the final move is a rename.
//   Creating it before the run is also the check that the parent is writable.
// - commit() checks the folder again, under the lock: an entry added during the run that a run
//   does not write makes it refuse; the new results then stay in the staging folder, which the
//   error names.
// - The replacement is atomic: renameat2(2) RENAME_EXCHANGE swaps the new folder and the old one
//   (or, on a file system without it, the old one is renamed aside to ".<name>.old-XXXXXX" and the
//   new one renamed in). Only then is the old copy removed, and only its regular results files,
//   one by one; if anything stays (an undeletable file, something that appeared at the last
//   moment), the new results are in place all the same and commit() returns a warning naming the
//   leftover folder.
// - Never delete what this run did not create: on failure it removes its own staging folder, its
//   own lock file, and the parent folders it created (only while they are empty).
// - Checked before the run: every path component within the file system's NAME_MAX (255 bytes on
//   ext4, tmpfs, btrfs, xfs), the folder's name 16 bytes shorter so that ".<name>.partial-XXXXXX"
//   fits too, the names of the files the run will write (plots are named after integrands)
//   within NAME_MAX, the whole path within PATH_MAX, and an existing folder writable (its old
//   files are removed after the swap).
// A run killed by SIGKILL or a crash leaves its hidden staging folder and lock file: a later run
// locks the stale lock file fine (flock locks die with their process) and leaves it in place,
// since it did not create it.
#pragma once

#include "quadmc/report/results_folder.hpp"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

// Which names a folder of this command's results may hold (only those are replaced or removed):
// quadmc::is_results_file_name for `run`, the gallery's own names for `gallery`.
using results_file_predicate = bool (*)(std::string_view name);

// The folder a run writes: `out` when given, else results/<scene_name>; absolute, normalised and
// without a trailing separator (with "out/" the staging folder would otherwise be looked for
// inside the target). Throws quadmc::invalid_argument for the file system root.
std::filesystem::path results_folder_path(const std::string& out, const std::string& scene_name);

class results_staging {
 public:
  // `parameter` and `given` name the folder in messages ("--out", "mine/"); `folder` is the
  // absolute, normalised path (results_folder_path); `files` the names the run will write into
  // it. Throws quadmc::invalid_argument with a one-line message on any refusal above, having
  // removed whatever it created. `is_results_file` says which entries of an existing folder are
  // results this kind of run writes.
  results_staging(std::string parameter, std::string given, std::filesystem::path folder,
                  const std::vector<std::string>& files,
                  results_file_predicate is_results_file = &quadmc::is_results_file_name);
  results_staging(const results_staging&) = delete;
  results_staging& operator=(const results_staging&) = delete;
  ~results_staging() { finish(); }

  // The folder the results will be in (a symlink's target when --out named a link), and the link
  // itself (empty when there was none).
  const std::filesystem::path& folder() const noexcept { return folder_; }
  const std::filesystem::path& link() const noexcept { return link_; }
  // Where this run writes until commit().
  const std::filesystem::path& staging() const noexcept { return staging_; }

  // Moves the staged results into place. Returns a warning (one line) when the old results
  // could not be removed completely, empty otherwise. Throws quadmc::invalid_argument when the
  // folder changed during the run so that it may no longer be replaced; the new results then stay
  // in staging(), which the message names.
  std::string commit();

  // Removes what this run created and did not hand over (the staging folder unless commit()
  // kept it, the parent folders it created while empty) and releases the lock. Idempotent.
  void finish() noexcept;

 private:
  [[noreturn]] void refuse(const std::string& what) const;
  [[noreturn]] void keep_and_refuse(const std::string& what);
  void check_names(const std::vector<std::string>& files) const;
  void create_parents();
  void lock();
  void make_staging();

  std::string parameter_, given_;
  std::filesystem::path folder_, link_, staging_, lock_file_;
  results_file_predicate is_results_file_;
  std::vector<std::filesystem::path> created_parents_;  // outermost first
  int lock_fd_ = -1;
  bool created_lock_file_ = false;
  bool staging_owned_ = false;  // staging_ exists and is this run's to remove
};

}  // namespace quadmc
