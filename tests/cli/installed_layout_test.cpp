// End-to-end test of an installed quadmc: `cmake --install` of this build folder into a scratch
// prefix, then the installed command run with plots on. The installed binary must find the
// installed plot script (share/quadmc/plot.py beside bin/, bench/quadmc/plot_script.hpp), never
// the source tree's, and the install must hold what the Debian package is built from (its own
// check, tests/package/check_package.sh, runs in CI on the .deb).
//
// Use it for the install rules and the run-time layout. Not for the package's metadata
// (dependencies, file names): ./run.sh package checks those.
#include "quadmc/report/markdown_report.hpp"
#include "quadmc/report/provenance.hpp"
#include "quadmc_process.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

// Installs this build folder (QUADMC_BINARY_DIR) into `prefix`.
command_result install_into(const scratch_folder& dir, const fs::path& prefix) {
  process_options options;
  options.working_directory = dir.path();
  options.stdout_file = dir / "install.stdout";
  options.stderr_file = dir / "install.stderr";
  return child_process(
             {QUADMC_CMAKE_COMMAND, "--install", QUADMC_BINARY_DIR, "--prefix", prefix.string()},
             options)
      .wait();
}

// Runs the installed `quadmc args…` in `dir`.
command_result run_installed(const scratch_folder& dir, const fs::path& prefix,
                             const std::vector<std::string>& args) {
  std::vector<std::string> argv{(prefix / "bin" / "quadmc").string()};
  argv.insert(argv.end(), args.begin(), args.end());
  process_options options;
  options.working_directory = dir.path();
  options.stdout_file = dir / "installed.stdout";
  options.stderr_file = dir / "installed.stderr";
  return child_process(argv, options).wait();
}

TEST(InstalledLayoutTest, InstalledCommandUsesItsInstalledPlotScript) {
  scratch_folder dir;
  const fs::path prefix = dir / "prefix";
  const command_result installed = install_into(dir, prefix);
  ASSERT_EQ(installed.exit_status, 0) << describe(installed);

  // What the package is made of: the command and what it needs at run time, the library, its
  // headers and its CMake package files.
  const fs::path libdir = prefix / QUADMC_INSTALL_LIBDIR;
  for (const fs::path& file :
       {prefix / "bin" / "quadmc", prefix / "share" / "quadmc" / "plot.py",
        prefix / "share" / "quadmc" / "gallery.py", prefix / "share" / "quadmc" / "render.py",
        prefix / "share" / "quadmc" / "scenes" / "render.toml",
        prefix / "share" / "quadmc" / "scenes" / "default.toml",
        prefix / "share" / "doc" / "quadmc" / "copyright",
        prefix / "share" / "doc" / "quadmc" / "CHANGELOG.md",
        prefix / "share" / "doc" / "quadmc" / "CITATION.cff",
        prefix / "include" / "quadmc" / "report" / "provenance.hpp", libdir / "libquadmc_core.a",
        libdir / "libquadmc_report.a", libdir / "cmake" / "quadmc" / "quadmcConfig.cmake",
        libdir / "cmake" / "quadmc" / "quadmcConfigVersion.cmake",
        libdir / "cmake" / "quadmc" / "quadmcTargets.cmake"}) {
    EXPECT_TRUE(fs::is_regular_file(file)) << file << " not installed";
  }

  const command_result version = run_installed(dir, prefix, {"--version"});
  ASSERT_EQ(version.exit_status, 0) << describe(version);
  const fs::path script = fs::canonical(prefix / "share" / "quadmc" / "plot.py");
  EXPECT_NE(version.out.find("\nplot script: " + script.string() + "\n"), std::string::npos)
      << describe(version);

  // A run with plots on, by the installed command only.
  write_text(dir / "s.toml", tiny_scene("installed", "from an installed prefix", true));
  const command_result r =
      run_installed(dir, prefix, {"run", (dir / "s.toml").string(), "--out", "out"});
  ASSERT_EQ(r.exit_status, 0) << describe(r);
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / quadmc::convergence_plot_file("exp", 1)))
      << describe(r);
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / quadmc::work_precision_plot_file("exp", 1)))
      << describe(r);
  EXPECT_EQ(quadmc::read_meta_csv(dir / "out" / "meta.csv").version, QUADMC_PROJECT_VERSION);

  // Without its plot script the installed command refuses before computing, naming the installed
  // path: it does not fall back to the source tree it was built from.
  fs::remove(prefix / "share" / "quadmc" / "plot.py");
  const command_result missing =
      run_installed(dir, prefix, {"run", (dir / "s.toml").string(), "--out", "again"});
  EXPECT_EQ(missing.exit_status, 1) << describe(missing);
  EXPECT_NE(missing.err.find(script.string()), std::string::npos) << describe(missing);
  EXPECT_EQ(line_count(missing.err), 1u) << describe(missing);
  EXPECT_FALSE(fs::exists(dir / "again"));
}

}  // namespace
}  // namespace quadmc_cli_test
