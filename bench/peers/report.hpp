// Writing a study of quadmc_peers: peers.csv (one row per measurement, every number of the
// report), meta.csv (the quadmc version, commit, compiler and SIMD levels that made them, as
// `quadmc run` writes it: report/provenance.hpp) and README.md (the targets table, throughput,
// quasi-Monte Carlo points per second with the peers' agreement checks, time to accuracy, peak
// memory, reproducibility, the profile notes, the plots).
//
// Use it from quadmc_peers.cpp after the measurement. Not for drawing: plot_peers.py draws the
// work-precision plots from peers.csv. The writers throw std::runtime_error naming the file when
// it cannot be written completely.
#pragma once

#include "study.hpp"

#include <filesystem>
#include <vector>

namespace quadmc::peers {

void write_csv(const std::filesystem::path& path, const std::vector<row>& rows);
void write_meta_csv(const std::filesystem::path& path, const study& st);
void write_markdown_report(const std::filesystem::path& path, const configuration& c,
                           const study& st);

}  // namespace quadmc::peers
