// A quadmc built without MPI, started by mpirun (which sets OMPI_COMM_WORLD_SIZE in each process
// it starts), must not run K copies of the whole scene that overwrite each other's results: it
// says that mpirun use needs the MPI build, and writes nothing. Compiled only into builds
// without MPI (tests/cli/CMakeLists.txt); the MPI build runs tests/mpi/ instead.
#include "quadmc_command.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <string>
#include <vector>

namespace quadmc_cli_test {
namespace {

TEST(WithoutMpi, StartedByMpirunItSaysItNeedsTheMpiBuild) {
  scratch_folder dir;
  write_text(dir / "scene.toml",
             "name = \"x\"\n[[integrand]]\nfamily = \"exp\"\n[[method]]\n"
             "name = \"simpson\"\n[budget]\nN = [8]\n");
  ASSERT_EQ(setenv("OMPI_COMM_WORLD_SIZE", "2", 1), 0);
  const command_result r = run_quadmc(dir, {"run", (dir / "scene.toml").string()});
  unsetenv("OMPI_COMM_WORLD_SIZE");
  EXPECT_EQ(r.exit_status, 1) << describe(r);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << describe(r);
  EXPECT_NE(r.err.find("mpirun use needs the MPI build"), std::string::npos) << describe(r);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.toml"}) << describe(r);
}

}  // namespace
}  // namespace quadmc_cli_test
