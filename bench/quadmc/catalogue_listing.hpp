// Text listings of the `quadmc` command: what a scene may name (`quadmc list`) and the slope
// summary printed after a run.
#pragma once

#include "quadmc/analysis/convergence_table.hpp"

#include <span>
#include <string>

namespace quadmc_cli {

// Integrands (with formula, smoothness, parameter keys), methods, point sets and warps, one line
// each.
std::string catalogue_listing();

// One line per (integrand, method): fitted slope with its 95% interval, theory, verdict.
std::string slope_summary(std::span<const quadmc::convergence_table> tables);

}  // namespace quadmc_cli
