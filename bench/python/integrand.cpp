// quadmc.integrand(family, s=None, seed=0, **params): a family of the catalogue
// (functions/catalogue.hpp) built as a scene's [[integrand]] table builds it, and called on an
// (n, s) float64 array through the library's batch evaluate, 256 points per call (the batch of
// core/batching.hpp), with the GIL released. Points are in the integrand's own domain
// (.domain), as the batch contract says (docs/design.md#hot-path-contract).
//
// params as the scene keys: a number is a scalar key, a sequence of numbers a vector key (Genz
// a and u), a str a string key (Genz coefficient_decay); omitted Genz parameters are drawn from
// `seed`. The catalogue checks the keys and names an unknown one, one of the wrong kind or a
// string outside its choices.
#include "bindings.hpp"

#include "quadmc/core/batching.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/smoothness.hpp"
#include "quadmc/functions/catalogue.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace quadmc_python {

namespace {

using input_array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// One keyword as a scalar, a vector or a string key of integrand_params.
void add_param(quadmc::integrand_params& params, const std::string& key, const py::handle& value) {
  if (is_number(value)) {
    params.scalars[key] = value.cast<double>();
    return;
  }
  if (py::isinstance<py::str>(value)) {
    params.strings[key] = value.cast<std::string>();
    return;
  }
  if (!py::isinstance<py::str>(value) && py::isinstance<py::iterable>(value)) {
    if (std::optional<std::vector<double>> values = numbers_of(value); values && !values->empty()) {
      params.vectors[key] = std::move(*values);
      return;
    }
  }
  throw quadmc::invalid_argument(key, quoted(value),
                                 "a number, a non-empty sequence of numbers or a str");
}

quadmc::any_integrand make(const std::string& family, const py::object& s, const py::object& seed,
                           const py::kwargs& keywords) {
  quadmc::integrand_params params;
  if (!s.is_none()) params.dimension = to_count(s, "s", 1);
  params.seed = to_count(seed, "seed", 0);
  for (const auto& [key, value] : keywords) add_param(params, py::str(key), value);
  return quadmc::make_integrand(family, params);
}

py::array_t<double> evaluate(const quadmc::any_integrand& f, const input_array& x) {
  const std::size_t s = f.dimension();
  if (x.ndim() != 2 || static_cast<std::size_t>(x.shape(1)) != s) {
    std::vector<py::ssize_t> extents(x.shape(), x.shape() + x.ndim());
    throw quadmc::invalid_argument(
        "x", fmt::format("an array of shape ({})", fmt::join(extents, ", ")),
        fmt::format("a 2D array of shape (n, {}) for {}", s, f.info().name));
  }
  const auto n = static_cast<std::size_t>(x.shape(0));
  py::array_t<double> y(static_cast<py::ssize_t>(n));
  const std::span<const double> in(x.data(), n * s);
  const std::span<double> out(y.mutable_data(), n);
  {
    py::gil_scoped_release unlocked;
    for (std::size_t i = 0; i < n; i += quadmc::batch_points) {
      const std::size_t count = std::min(quadmc::batch_points, n - i);
      f.evaluate(in.subspan(i * s, count * s), out.subspan(i, count));
    }
  }
  return y;
}

py::list domain_of(const quadmc::any_integrand& f) {
  const quadmc::box& box = f.info().domain;
  py::list out;
  for (std::size_t j = 0; j < box.dimension(); ++j) {
    out.append(py::make_tuple(box.lower[j], box.upper[j]));
  }
  return out;
}

std::string repr_of(const quadmc::any_integrand& f) {
  return fmt::format("<quadmc.Integrand {} s={} exact={}>", f.info().name, f.dimension(),
                     quadmc::quote(f.info().exact));
}

}  // namespace

void add_integrand(py::module_& m) {
  py::class_<quadmc::any_integrand>(
      m, "Integrand", "An integrand of the catalogue: quadmc.integrand(...) makes one.")
      .def_property_readonly("name", [](const quadmc::any_integrand& f) { return f.info().name; })
      .def_property_readonly("formula",
                             [](const quadmc::any_integrand& f) { return f.info().formula; })
      .def_property_readonly("dimension", &quadmc::any_integrand::dimension)
      .def_property_readonly(
          "exact", [](const quadmc::any_integrand& f) { return f.info().exact; },
          "The exact integral over the domain (NaN where none is known).")
      .def_property_readonly(
          "smoothness",
          [](const quadmc::any_integrand& f) { return quadmc::to_string(f.info().regularity); })
      .def_property_readonly("domain", &domain_of, "[(lower, upper)] per coordinate.")
      .def("__call__", &evaluate, py::arg("x"),
           "f at each row of an (n, s) float64 array of points in the domain, as an (n,) array.")
      .def("__repr__", &repr_of);
  m.def("integrand", &make, py::arg("family"), py::arg("s") = py::none(), py::arg("seed") = 0,
        R"(The catalogue family `family` in s dimensions (None: its default) as an Integrand.

Keywords are its keys as quadmc.integrands() lists them: a number for a scalar key, a sequence
for a vector key (genz a=[...], u=[...]), a str for a string key (genz
coefficient_decay="quadratic"); omitted Genz parameters are drawn from seed. Raises
ValueError with the library's text for an unknown family or key.)");
}

}  // namespace quadmc_python
