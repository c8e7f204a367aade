// quadmc.discrepancy(points, kind): the L2 discrepancy of an (n, s) array of points in [0, 1]
// by the library's exact O(n²·s) formulas (sampling/discrepancy.hpp, docs/theory.md#discrepancy):
// "l2_star" (Warnock), "centered" or "wrap_around" (Hickernell). The array is read in place when
// it is C-contiguous float64, else converted once; the pairs are summed with the GIL released.
// Shape and values are checked here, naming `points` and the coordinate, before the library's
// own checks, whose messages cannot know the Python names.
#include "bindings.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/sampling/discrepancy.hpp"

#include <pybind11/numpy.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <span>
#include <string>
#include <utility>

namespace py = pybind11;

namespace quadmc_python {

namespace {

using input_array = py::array_t<double, py::array::c_style | py::array::forcecast>;
using discrepancy_function = double (*)(std::span<const double>, std::size_t);

constexpr std::array<std::pair<std::string_view, discrepancy_function>, 3> kinds{{
    {"l2_star", &quadmc::l2_star_discrepancy},
    {"centered", &quadmc::centered_discrepancy},
    {"wrap_around", &quadmc::wraparound_discrepancy},
}};

discrepancy_function function_of(const std::string& kind) {
  for (const auto& [name, function] : kinds) {
    if (name == kind) return function;
  }
  throw quadmc::invalid_argument("kind", kind, "one of l2_star, centered, wrap_around");
}

std::string shape_of(const input_array& points) {
  std::vector<py::ssize_t> extents(points.shape(), points.shape() + points.ndim());
  return fmt::format("an array of shape ({})", fmt::join(extents, ", "));
}

void check_points(const input_array& points) {
  if (points.ndim() != 2 || points.shape(0) < 1 || points.shape(1) < 1) {
    throw quadmc::invalid_argument("points", shape_of(points),
                                   "a 2D array of shape (n, s) with n ≥ 1 and s ≥ 1");
  }
  const auto n = static_cast<std::uint64_t>(points.shape(0));
  if (n > quadmc::max_discrepancy_points) {
    throw quadmc::invalid_argument("points", shape_of(points),
                                   "n ≤ 2^14 rows for an O(n²) discrepancy");
  }
  const auto x = points.unchecked<2>();
  for (py::ssize_t i = 0; i < x.shape(0); ++i) {
    for (py::ssize_t j = 0; j < x.shape(1); ++j) {
      // Written so that NaN fails too.
      if (!(x(i, j) >= 0.0 && x(i, j) <= 1.0)) {
        throw quadmc::invalid_argument(fmt::format("points[{}, {}]", i, j), quadmc::quote(x(i, j)),
                                       "a coordinate in [0, 1]");
      }
    }
  }
}

double discrepancy(const input_array& points, const std::string& kind) {
  const discrepancy_function function = function_of(kind);
  check_points(points);
  const std::span<const double> x(points.data(), static_cast<std::size_t>(points.size()));
  const auto s = static_cast<std::size_t>(points.shape(1));
  py::gil_scoped_release unlocked;
  return function(x, s);
}

}  // namespace

void add_discrepancy(py::module_& m) {
  m.def("discrepancy", &discrepancy, py::arg("points"), py::arg("kind"),
        R"(The L2 discrepancy of an (n, s) array of points in [0, 1]^s, n ≤ 2^14.

kind: "l2_star" (boxes anchored at the origin, Warnock's formula), "centered" or "wrap_around"
(Hickernell's). Returns D, not D². Raises ValueError naming the parameter for a bad kind, shape
or coordinate.)");
}

}  // namespace quadmc_python
