// Point sets and rules read from files: the N points of a user's sampler (or a rule's nodes and
// weights) as a row-major array, checked once when read, and a point set over that array.
//
// Use it where the points come from outside the library (the external_points and external_rule
// methods, methods/external.cpp): a CSV as `quadmc points` writes it, or a NumPy .npy array.
// Not for points the library generates (sampling/*_points.hpp make them from (seed, stream)
// without a file), and not for files larger than max_point_file_values values: the whole array
// is held in memory for one (cell, repetition).
//
// Formats (README "Methods", external_points):
//  - CSV: one point per line, s coordinates (then the weight, for a rule) separated by commas,
//    as `quadmc points` writes them (shortest round-trip decimal, so the doubles read back
//    bitwise). An optional first line of column names (x1,…,xs[,w]) is skipped when its first
//    field is not a number. No quoting, no blank lines inside the data; "\r\n" is accepted.
//  - .npy (chosen by the extension): format versions 1.0, 2.0 and 3.0, a header dict with exactly
//    'descr' ('<f8' or '<f4'; float32 is widened exactly), 'fortran_order' (False only) and
//    'shape' (N, c), c = s or s + 1 for a rule; the data must fill the rest of the file exactly.
// Every coordinate must be finite and in [0, 1) (the point_set contract, sampling/point_set.hpp),
// or in [0, 1] for a rule's nodes (rules/weighted_point_set.hpp: Simpson's include 0 and 1); a
// weight must be finite, of either sign. Each refusal is one quadmc::invalid_argument line that
// names the file and, for a value, its 1-based row and column.
#pragma once

#include "quadmc/sampling/point_set.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

// The most values (N·c) one file may hold: 2^27 doubles are 1 GiB in memory.
inline constexpr std::uint64_t max_point_file_values = std::uint64_t{1} << 27;
// The most bytes one file may have before it is read: 32 bytes of text per value bound the CSV,
// 8 bytes per value (plus its header) the .npy.
inline constexpr std::uint64_t max_point_file_bytes = max_point_file_values * 32;

// Whether the file's last column is a weight.
enum class point_file_columns { points, points_and_weights };

struct point_file_data {
  std::size_t s = 0;      // coordinates per point
  std::uint64_t n = 0;    // points (rows)
  std::vector<double> x;  // row-major, x[i*s + j]
  std::vector<double> w;  // weights (points_and_weights), else empty
};

// Reads and checks `file`: `expected_n` points (0: any) of `expected_s` coordinates (0: any),
// plus a weight column when `columns` says so. Throws invalid_argument naming the file (and the
// row and column of a bad value) for a missing, unreadable, non-regular or oversized file, a
// malformed CSV or .npy, a wrong shape or dtype, a coordinate outside [0, 1) or not finite, a
// weight not finite.
point_file_data read_point_file(const std::filesystem::path& file, point_file_columns columns,
                                std::uint64_t expected_n = 0, std::size_t expected_s = 0);

// The file of size N and realization r: `path_template` with every "{N}" and "{r}" replaced by
// the numbers, resolved against `folder` when relative.
std::filesystem::path point_file_path(std::string_view path_template, std::uint64_t N,
                                      std::uint64_t r, const std::filesystem::path& folder = {});

// The points of a file as a point_set (point_set.hpp): generate copies rows of the array, so an
// estimator sums them in the same chunks and order as any other set. One run cannot estimate its
// own error (not_estimable), as for a randomized quasi-Monte Carlo set; replicates can.
class file_points {
 public:
  explicit file_points(const point_file_data& data) : data_(&data) {
    require_point_set_size(data.s, data.n);
  }
  std::uint64_t size() const noexcept { return data_->n; }
  std::size_t dimension() const noexcept { return data_->s; }
  variance_structure variance() const noexcept { return {variance_kind::not_estimable, 1}; }
  void generate(std::uint64_t first, std::span<double> out) const {
    require_batch(data_->s, data_->n, first, out);
    const double* from = data_->x.data() + first * data_->s;
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = from[k];
  }

 private:
  const point_file_data* data_;
};

}  // namespace quadmc
