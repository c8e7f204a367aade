// Runs a helper program (the plot script) and waits for it.
#pragma once

#include <string>
#include <vector>

namespace quadmc_cli {

// Runs argv[0] with arguments argv[1…] (no shell, so no quoting issues) and waits. Throws
// std::runtime_error naming the command if it cannot start or exits non-zero.
void run_subprocess(const std::vector<std::string>& argv);

}  // namespace quadmc_cli
