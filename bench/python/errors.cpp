// The library's errors as Python exceptions, translated in one place: a bad value (an unknown
// set, a key a family lacks, N that a net cannot hold) is ValueError with the library's one-line
// text, which names the parameter, the value and what was expected; so is a non-finite integrand
// value, which names the point.
#include "bindings.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/rng.hpp"

#include <fmt/format.h>

#include <exception>
#include <optional>
#include <vector>

namespace py = pybind11;

namespace quadmc_python {

void add_errors(py::module_&) {
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const quadmc::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const quadmc::non_finite_value& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
}

std::string quoted(const py::handle& value) {
  return py::isinstance<py::str>(value) ? py::str(value) : py::repr(value);
}

bool is_number(const py::handle& value) {
  return (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) &&
         !py::isinstance<py::bool_>(value);
}

std::optional<std::vector<double>> numbers_of(const py::handle& iterable) {
  std::vector<double> numbers;
  for (const py::handle item : iterable) {
    if (!is_number(item)) return std::nullopt;
    numbers.push_back(item.cast<double>());
  }
  return numbers;
}

std::uint64_t to_count(const py::handle& value, std::string_view parameter, std::uint64_t minimum) {
  const std::string text = quoted(value);
  if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value)) {
    throw quadmc::invalid_argument(parameter, text, "an integer");
  }
  const auto number = py::reinterpret_borrow<py::int_>(value);
  if (number < py::int_(minimum) || number > py::int_(UINT64_MAX)) {
    throw quadmc::invalid_argument(parameter, text,
                                   fmt::format("an integer in [{}, 2^64 - 1]", minimum));
  }
  return number.cast<std::uint64_t>();
}

quadmc::rng_kind to_rng(const py::handle& value) {
  if (!py::isinstance<py::str>(value)) {
    throw quadmc::invalid_argument("rng", quoted(value),
                                   fmt::format("one of {}", quadmc::rng_kind_names()));
  }
  return quadmc::parse_rng_kind(value.cast<std::string>(), "rng");
}

}  // namespace quadmc_python
