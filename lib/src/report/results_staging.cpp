// The results folder of a run; the rules are in results_staging.hpp.
#include "quadmc/report/results_staging.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/report/provenance.hpp"
#include "quadmc/report/results_folder.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <stdio.h>  // renameat2 (glibc ≥ 2.28)
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <optional>
#include <string_view>
#include <system_error>
#include <utility>

namespace quadmc {

namespace fs = std::filesystem;

namespace {

// ".<name>.partial-XXXXXX" is the longest name derived from the folder's: 16 bytes more.
constexpr std::size_t staging_extra_bytes = 16;

std::string error_text(int error) {
  return std::strerror(error);
}

// "a folder", "a symbolic link", …: what an entry is, for messages.
std::string_view file_kind(const fs::file_status& status) {
  switch (status.type()) {
    case fs::file_type::directory:
      return "a folder";
    case fs::file_type::symlink:
      return "a symbolic link";
    case fs::file_type::fifo:
      return "a FIFO";
    case fs::file_type::socket:
      return "a socket";
    case fs::file_type::block:
    case fs::file_type::character:
      return "a device";
    default:
      return "not a regular file";
  }
}

// What makes `folder` not a results folder of this command, or nothing: an entry that is not a
// regular file with a name the command writes (a folder named "figures.svg" is somebody's), or,
// in a folder with any entry, no meta.csv that quadmc wrote. Every run that writes a folder writes
// meta.csv (report/provenance.hpp), so hand-made files that happen to have a run's names — a
// README.md, drawings in *.svg — are never taken for old results and deleted.
std::optional<std::string> first_foreign_entry(const fs::path& folder,
                                               results_file_predicate is_results_file) {
  std::error_code ec;
  bool empty = true;
  fs::directory_iterator it(folder, ec);
  for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
    empty = false;
    const std::string name = it->path().filename().string();
    std::error_code status_ec;
    const fs::file_status status = it->symlink_status(status_ec);
    if (!is_results_file(name)) {
      return fmt::format("it holds '{}', which a run does not write", name);
    }
    if (!fs::is_regular_file(status)) {
      return fmt::format("it holds '{}', {} where a run writes a regular file", name,
                         file_kind(status));
    }
  }
  if (ec) return fmt::format("its entries cannot be listed ({})", ec.message());
  if (empty) return std::nullopt;
  const fs::path meta = folder / std::string(quadmc::meta_csv_file);
  std::error_code meta_ec;
  if (!fs::is_regular_file(fs::symlink_status(meta, meta_ec))) {
    return fmt::format(
        "it has no {} (which every run writes beside its results), so its files are not a run's",
        quadmc::meta_csv_file);
  }
  try {
    (void)quadmc::read_meta_csv(meta);
  } catch (const std::exception& e) {
    return fmt::format("its {} is not one a run writes ({})", quadmc::meta_csv_file, e.what());
  }
  return std::nullopt;
}

// Whether `folder` is the current folder or one of its parents: replacing it would pull the
// working directory from under the user (even a results folder: `cd results/default` and
// `quadmc run … --out .`).
bool holds_current_folder(const fs::path& folder) {
  std::error_code ec;
  const fs::path here = fs::canonical(fs::current_path(ec), ec);
  if (ec) return false;
  const fs::path target = fs::weakly_canonical(folder, ec);
  if (ec) return false;
  auto h = here.begin();
  for (auto t = target.begin(); t != target.end(); ++t, ++h) {
    if (h == here.end() || *h != *t) return false;
  }
  return true;
}

// The file system's longest name in the nearest existing folder on the way to `path`.
std::size_t name_max_at(fs::path path) {
  std::error_code ec;
  while (!path.empty() && !fs::exists(path, ec) && path != path.root_path()) {
    path = path.parent_path();
  }
  const long limit = ::pathconf(path.empty() ? "/" : path.c_str(), _PC_NAME_MAX);
  return limit > 0 ? static_cast<std::size_t>(limit) : NAME_MAX;
}

int rename_no_replace(const fs::path& from, const fs::path& to) {
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return 0;
  // A file system without the flag: rename(2), which may only replace an empty folder.
  if (errno == EINVAL || errno == ENOSYS) return ::rename(from.c_str(), to.c_str());
  return -1;
}

}  // namespace

fs::path results_folder_path(const std::string& out, const std::string& scene_name) {
  const fs::path given = out.empty() ? fs::path("results") / scene_name : fs::path(out);
  fs::path folder = fs::absolute(given).lexically_normal();
  if (!folder.has_filename()) folder = folder.parent_path();  // "/a/out/" → "/a/out"
  if (!folder.has_filename() || folder == folder.root_path()) {
    throw quadmc::invalid_argument(out.empty() ? "results folder" : "--out", given.string(),
                                   "a folder below the file system root");
  }
  return folder;
}

results_staging::results_staging(std::string parameter, std::string given, fs::path folder,
                                 const std::vector<std::string>& files,
                                 results_file_predicate is_results_file)
    : parameter_(std::move(parameter)),
      given_(std::move(given)),
      folder_(std::move(folder)),
      is_results_file_(is_results_file) {
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(folder_, ec))) {
    // Followed, not replaced: renaming a folder onto the link would turn the link into a copy
    // and leave the folder it pointed to with the old results.
    link_ = folder_;
    const fs::path target = fs::canonical(link_, ec);
    if (ec == std::errc::too_many_symbolic_link_levels) {
      refuse("a symlink loop (following it never reaches a folder); give the folder itself");
    }
    if (ec) {
      refuse(fmt::format("a symlink to '{}', which does not exist; give the folder itself",
                         fs::read_symlink(link_, ec).string()));
    }
    folder_ = target;
  }
  check_names(files);
  if (holds_current_folder(folder_)) {
    refuse(
        "the current folder or one of its parents, which a run never replaces (give a folder "
        "inside it, e.g. --out results/mine)");
  }
  const fs::file_status status = fs::status(folder_, ec);
  if (fs::exists(status)) {
    if (!fs::is_directory(status)) refuse("a file, not a folder");
    if (const auto foreign = first_foreign_entry(folder_, is_results_file_)) {
      refuse(
          fmt::format("not a results folder: {}, so it is not replaced (choose a new folder "
                      "or an earlier results folder)",
                      *foreign));
    }
    if (::access(folder_.c_str(), W_OK) != 0) {
      refuse(
          fmt::format("the folder is not writable ({}), so its old results could not be "
                      "replaced",
                      error_text(errno)));
    }
  }
  try {
    create_parents();
    lock();
    make_staging();
  } catch (...) {
    finish();
    throw;
  }
}

void results_staging::refuse(const std::string& what) const {
  throw quadmc::invalid_argument(fmt::format("{} '{}': {}", parameter_, given_, what));
}

void results_staging::keep_and_refuse(const std::string& what) {
  staging_owned_ = false;  // the new results are the user's now: never removed
  refuse(fmt::format("{}; the new results are kept in {}", what, staging_.string()));
}

void results_staging::check_names(const std::vector<std::string>& files) const {
  const std::size_t name_max = name_max_at(folder_);
  for (const fs::path& component : folder_.relative_path()) {
    if (component.native().size() > name_max) {
      refuse(fmt::format("the path component '{}' has {} bytes; the file system allows {}",
                         component.string(), component.native().size(), name_max));
    }
  }
  const std::size_t name = folder_.filename().native().size();
  if (name + staging_extra_bytes > name_max) {
    refuse(
        fmt::format("the folder name has {} bytes; at most {} fit (the file system allows {} "
                    "per name, and the staging folder '.<name>.partial-XXXXXX' adds {})",
                    name, name_max - staging_extra_bytes, name_max, staging_extra_bytes));
  }
  for (const std::string& file : files) {
    if (file.size() > name_max) {
      refuse(
          fmt::format("the run would write '{}', a name of {} bytes; the file system allows {} "
                      "(shorten the integrand's name)",
                      file, file.size(), name_max));
    }
  }
  // The deepest path the run creates: a file in the staging folder (README.md at least).
  std::size_t longest_file = std::string_view("convergence.csv").size();
  for (const std::string& file : files) longest_file = std::max(longest_file, file.size());
  const std::size_t longest = folder_.native().size() + staging_extra_bytes + 1 + longest_file;
  if (longest >= PATH_MAX) {
    refuse(
        fmt::format("the path is too long: the run's files would have paths of {} bytes; the "
                    "system allows {}",
                    longest, PATH_MAX - 1));
  }
}

void results_staging::create_parents() {
  std::vector<fs::path> missing;  // innermost first
  std::error_code ec;
  for (fs::path p = folder_.parent_path(); !fs::exists(fs::symlink_status(p, ec));
       p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.root_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (::mkdir(it->c_str(), 0777) == 0) {
      created_parents_.push_back(*it);
    } else if (errno != EEXIST) {
      refuse(fmt::format("cannot create the folder {}: {}", it->string(), error_text(errno)));
    }
  }
}

void results_staging::lock() {
  lock_file_ = folder_.parent_path() / fmt::format(".{}.lock", folder_.filename().string());
  // The holder removes the lock file before it closes it, so a file opened just before that is
  // no longer the lock: after flock, check that the path still names the locked file, else retry.
  for (int attempt = 0; attempt < 100; ++attempt) {
    bool created = true;
    int fd = ::open(lock_file_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0 && errno == EEXIST) {
      created = false;
      fd = ::open(lock_file_.c_str(), O_RDWR | O_CLOEXEC);
      if (fd < 0 && errno == ENOENT) continue;  // removed by its holder meanwhile
    }
    if (fd < 0) {
      refuse(fmt::format("cannot create the lock file {}: {}", lock_file_.string(),
                         error_text(errno)));
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(fd);
      if (error == EWOULDBLOCK) {
        refuse(
            fmt::format("another quadmc run is writing this folder (it holds the lock {}); "
                        "wait for it to finish or choose another folder",
                        lock_file_.string()));
      }
      refuse(fmt::format("cannot lock {}: {}", lock_file_.string(), error_text(error)));
    }
    struct stat held {};
    struct stat named {};
    if (::fstat(fd, &held) == 0 && ::stat(lock_file_.c_str(), &named) == 0 &&
        held.st_dev == named.st_dev && held.st_ino == named.st_ino) {
      lock_fd_ = fd;
      created_lock_file_ = created;
      return;
    }
    ::close(fd);
  }
  refuse(fmt::format("cannot lock {}: it keeps being replaced", lock_file_.string()));
}

void results_staging::make_staging() {
  std::string pattern =
      (folder_.parent_path() / (fmt::format(".{}.partial-XXXXXX", folder_.filename().string())))
          .string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    refuse(fmt::format("cannot create the staging folder {}: {}", pattern, error_text(errno)));
  }
  staging_ = pattern;
  staging_owned_ = true;
  // mkdtemp makes it 0700; the results folder gets what mkdir would give it (0777 less the
  // umask), as before staging existed.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(staging_.c_str(), 0777 & ~mask);
}

std::string results_staging::commit() {
  // Checked again, under the lock: what the folder holds now, not what it held before the run.
  for (int attempt = 0; attempt < 3; ++attempt) {
    std::error_code ec;
    const fs::file_status status = fs::symlink_status(folder_, ec);
    if (!fs::exists(status)) {
      if (rename_no_replace(staging_, folder_) == 0) {
        staging_owned_ = false;
        return {};
      }
      if (errno == EEXIST || errno == ENOTEMPTY) continue;  // created meanwhile: check it
      keep_and_refuse(fmt::format("cannot move the new results into place: {}", error_text(errno)));
    }
    if (!fs::is_directory(status)) {
      keep_and_refuse("it was replaced by a file or a link during the run, so it is not replaced");
    }
    if (const auto foreign = first_foreign_entry(folder_, is_results_file_)) {
      keep_and_refuse(
          fmt::format("it changed during the run: {}, so it is not replaced", *foreign));
    }
    fs::path old_copy;
    if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, folder_.c_str(), RENAME_EXCHANGE) == 0) {
      old_copy = staging_;  // the swap put the old results where the new ones were
    } else if (errno == EINVAL || errno == ENOSYS) {
      // No RENAME_EXCHANGE on this file system: old aside, new in; the folder is missing for
      // the instant between the two renames, never holding a mixture.
      std::string aside =
          (folder_.parent_path() / (fmt::format(".{}.old-XXXXXX", folder_.filename().string())))
              .string();
      if (::mkdtemp(aside.data()) == nullptr) {
        keep_and_refuse(fmt::format("cannot create {}: {}", aside, error_text(errno)));
      }
      if (::rename(folder_.c_str(), aside.c_str()) != 0) {
        const int error = errno;
        ::rmdir(aside.c_str());
        keep_and_refuse(fmt::format("cannot move the old results aside: {}", error_text(error)));
      }
      if (::rename(staging_.c_str(), folder_.c_str()) != 0) {
        const int error = errno;
        ::rename(aside.c_str(), folder_.c_str());
        keep_and_refuse(
            fmt::format("cannot move the new results into place: {}", error_text(error)));
      }
      old_copy = aside;
    } else {
      keep_and_refuse(fmt::format("cannot move the new results into place: {}", error_text(errno)));
    }
    staging_owned_ = false;
    // The old results: only their regular results files are removed, one by one, so a file
    // that slipped in at the last moment survives (the folder then stays and is named).
    std::string problem;
    fs::directory_iterator it(old_copy, ec);
    for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
      const std::string name = it->path().filename().string();
      std::error_code status_ec;
      if (fs::is_regular_file(it->symlink_status(status_ec)) && is_results_file_(name)) {
        if (::unlink(it->path().c_str()) != 0 && problem.empty()) {
          problem = fmt::format("cannot remove '{}': {}", name, error_text(errno));
        }
      } else if (problem.empty()) {
        problem = fmt::format("it holds '{}', which a run does not write", name);
      }
    }
    if (ec && problem.empty()) problem = ec.message();
    if (::rmdir(old_copy.c_str()) == 0) return {};
    if (problem.empty()) problem = error_text(errno);
    return fmt::format(
        "the new results are in {}, but the previous ones could not be removed and "
        "are left in {} ({})",
        folder_.string(), old_copy.string(), problem);
  }
  keep_and_refuse("it kept changing while the new results were moved in");
}

void results_staging::finish() noexcept {
  if (staging_owned_) {
    std::error_code ignored;
    fs::remove_all(staging_, ignored);
    staging_owned_ = false;
  }
  if (lock_fd_ >= 0) {
    // Removed while still locked (a run that opened it meanwhile sees it is gone and retries).
    if (created_lock_file_) ::unlink(lock_file_.c_str());
    ::close(lock_fd_);
    lock_fd_ = -1;
  }
  // Innermost first; rmdir refuses a folder that is not empty, which is what we want.
  for (auto it = created_parents_.rbegin(); it != created_parents_.rend(); ++it) {
    ::rmdir(it->c_str());
  }
  created_parents_.clear();
}

}  // namespace quadmc
