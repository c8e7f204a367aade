// The one table of methods: every method a scene may name, by family, in listing order.
//
// Use find_method to look a scene's `name` up (then descriptor->create reads its options), and
// method_registry to list them (`quadmc list`, the README's table). Adding a method is one class
// and one descriptor in its family's file under lib/src/methods/; adding a family is one file
// there and one line in registry.cpp. Nothing outside this layer names a method.
#pragma once

#include "quadmc/methods/method.hpp"
#include "quadmc/methods/option_map.hpp"

#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace quadmc {

std::span<const method_descriptor* const> method_registry();
const method_descriptor* find_method(std::string_view name) noexcept;  // nullptr when unknown
std::string method_names();  // comma-separated, for "expected one of …" messages

// The method `name` configured by `options` (the same checks as a scene's [[method]] table;
// unknown keys are refused). Throws invalid_argument for an unknown name or a bad option.
std::unique_ptr<const method> make_method(std::string_view name, const option_table& options = {});

}  // namespace quadmc
