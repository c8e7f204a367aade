// The defaults of method.hpp's interface.
#include "quadmc/methods/method.hpp"

#include <algorithm>

namespace quadmc {

std::string_view to_string(cell_control control) noexcept {
  switch (control) {
    case cell_control::fixed_size:
      return "fixed";
    case cell_control::budget:
      return "budget";
    case cell_control::tolerance:
      return "tolerance";
  }
  return "?";
}

method_kind method::kind() const {
  return descriptor().kind;
}

quadmc::error_bars method::error_bars() const {
  return error_bars::own;
}

std::optional<std::string> method::incompatibility(const integrand_traits&) const {
  return std::nullopt;
}

std::vector<sizing> method::explicit_sizes(std::size_t) const {
  return {};
}

void method::check_inputs(std::size_t, const cell_size&, std::uint64_t) const {}

void method::measure_points(const method_cell&, const run_context&, repetition_result&) const {}

double method::error_envelope(const integrand_info&, const cell_size&) const {
  return std::numeric_limits<double>::quiet_NaN();
}

std::optional<error_prediction> method::predict_error(const integrand_info&) const {
  return std::nullopt;
}

bool method_descriptor::supports(cell_control control) const noexcept {
  return std::find(controls.begin(), controls.end(), control) != controls.end();
}

}  // namespace quadmc
