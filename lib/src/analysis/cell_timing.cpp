// Median and min–max spread of a cell's timing batches; the definitions are in cell_timing.hpp.
#include "quadmc/analysis/cell_timing.hpp"

#include "quadmc/core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace quadmc {

cell_timing summarise_timing(std::span<const double> samples, std::uint64_t estimates) {
  require(!samples.empty(), "samples.size()", samples.size(), "at least one timing batch");
  require(estimates >= samples.size(), "estimates", estimates,
          fmt::format("at least one per batch ({} batches)", samples.size()));
  for (std::size_t k = 0; k < samples.size(); ++k) {
    require(std::isfinite(samples[k]) && samples[k] >= 0.0, fmt::format("samples[{}]", k),
            samples[k], "finite and >= 0");
  }
  std::vector<double> sorted(samples.begin(), samples.end());
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  cell_timing out;
  out.estimates = estimates;
  out.seconds_per_estimate = n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  if (n > 1 && out.seconds_per_estimate > 0.0) {
    out.spread = (sorted.back() - sorted.front()) / out.seconds_per_estimate;
  } else if (n > 1) {
    out.spread = 0.0;  // every batch below the clock's resolution
  }
  return out;
}

}  // namespace quadmc
