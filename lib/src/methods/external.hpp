// The point files of external.cpp's methods, shared with the methods that take the same files
// as their uniforms (importance and the irradiance methods, with point_set = "external_points":
// families.hpp's read_point_set): the `path` and `points` keys, the cell sizes they give and the
// file of one (cell, repetition), read the same way wherever they are used. The format and its
// checks are sampling/point_file.hpp's. Private to the methods layer; implemented in
// external.cpp.
#pragma once

#include "quadmc/methods/method.hpp"
#include "quadmc/sampling/point_file.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc::methods {

// The keys of a method over files, as its [[method]] table gives them.
struct point_file_options {
  std::string path;  // the template, as given
  std::filesystem::path folder;
  std::vector<std::uint64_t> points;  // explicit N per cell; empty: budget.N
};

// Reads `path` (required, a template with "{N}" and "{r}") and `points` (an increasing list).
point_file_options read_point_file_options(option_reader& r);

// N is the file's row count, never mapped to another; above max_point_file_values a skip.
sizing point_file_sizing(std::uint64_t N);
// The sizes of `points`, one per cell; empty when the cells follow budget.N.
std::vector<sizing> point_file_sizes(const point_file_options& o);

// The file of size N and realization r, read and checked: `s` coordinates per point (0: any).
point_file_data read_cell_file(const point_file_options& o, point_file_columns columns,
                               std::uint64_t N, std::uint64_t r, std::size_t s);

// The file of size N and realization r as the uniforms of a method that maps `uniforms` of them
// per sample: a file of another column count is refused, naming the method (`who`) and the s it
// needs (`why`: what its uniforms are for).
point_file_data read_uniform_file(const point_file_options& o, std::uint64_t N, std::uint64_t r,
                                  std::size_t uniforms, std::string_view who, std::string_view why);

// Points from a file carry no known rate; their replicates give the error bars.
theoretical_rate point_file_theory();

// The docs of the two keys; `path` is required wherever the files are used.
inline constexpr option_doc point_file_path_doc{
    "path",
    "the file per (N, realization): a template with {N} and {r} (r = 0 … repetitions − 1), "
    "relative to the scene file's folder or absolute; CSV or .npy (required)"};
inline constexpr option_doc point_file_points_doc{
    "points", "explicit N per cell (an integer or an increasing list), replacing budget.N"};

}  // namespace quadmc::methods
