// What make_method says about a method name and its options, for the methods tests: the message
// of the invalid_argument it throws, or "no error". One copy for every test of the layer.
#pragma once

#include "quadmc/core/errors.hpp"
#include "quadmc/methods/registry.hpp"

#include <string>
#include <string_view>

namespace quadmc {

inline std::string error_of(std::string_view method, const option_table& options) {
  try {
    make_method(method, options);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace quadmc
