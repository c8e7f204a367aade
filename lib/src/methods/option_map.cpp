// option_map: method options in memory (option_map.hpp), checked as a scene's table is.
#include "quadmc/methods/option_map.hpp"

#include "quadmc/core/errors.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

namespace quadmc {
namespace {

std::string describe(const option_value& v) {
  return std::visit(
      [](const auto& x) -> std::string {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, double>) {
          return fmt::format("{}", x);
        } else if constexpr (std::is_same_v<T, std::string>) {
          return fmt::format("\"{}\"", x);
        } else if constexpr (std::is_same_v<T, bool>) {
          return x ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          return "an array";
        } else {
          return "a table";
        }
      },
      v.value);
}

bool is_count(double x, std::uint64_t lo, std::uint64_t hi) {
  return std::isfinite(x) && x == std::floor(x) && x >= static_cast<double>(lo) &&
         x <= static_cast<double>(hi);
}

}  // namespace

const option_value* option_map::find(std::string_view key) {
  const auto it = table_.find(key);
  if (it == table_.end()) return nullptr;
  read_.insert(std::string(key));
  return &it->second;
}

void option_map::expected(std::string_view key, std::string_view what) const {
  fail(key, fmt::format("expected {}, got {}", what, describe(table_.find(key)->second)));
}

std::optional<std::uint64_t> option_map::count(std::string_view key, std::uint64_t lo,
                                               std::uint64_t hi, std::string_view what) {
  const option_value* v = find(key);
  if (v == nullptr) return std::nullopt;
  const double* x = std::get_if<double>(&v->value);
  if (x == nullptr || !is_count(*x, lo, hi)) expected(key, what);
  return static_cast<std::uint64_t>(*x);
}

std::optional<double> option_map::number(std::string_view key, std::string_view what) {
  const option_value* v = find(key);
  if (v == nullptr) return std::nullopt;
  const double* x = std::get_if<double>(&v->value);
  if (x == nullptr || !std::isfinite(*x)) expected(key, what);
  return *x;
}

std::optional<std::string> option_map::string(std::string_view key, std::string_view what) {
  const option_value* v = find(key);
  if (v == nullptr) return std::nullopt;
  const std::string* s = std::get_if<std::string>(&v->value);
  if (s == nullptr) expected(key, what);
  return *s;
}

std::optional<bool> option_map::boolean(std::string_view key) {
  const option_value* v = find(key);
  if (v == nullptr) return std::nullopt;
  const bool* b = std::get_if<bool>(&v->value);
  if (b == nullptr) expected(key, "true or false");
  return *b;
}

std::optional<std::vector<std::uint64_t>> option_map::counts(std::string_view key, std::uint64_t lo,
                                                             std::uint64_t hi,
                                                             std::size_t max_values,
                                                             std::string_view what) {
  const option_value* v = find(key);
  if (v == nullptr) return std::nullopt;
  if (const double* x = std::get_if<double>(&v->value)) {
    if (!is_count(*x, lo, hi)) expected(key, what);
    return std::vector<std::uint64_t>{static_cast<std::uint64_t>(*x)};
  }
  const auto* a = std::get_if<std::vector<double>>(&v->value);
  if (a == nullptr || a->empty())
    expected(key, fmt::format("{} or a non-empty array of them", what));
  if (a->size() > max_values) fail(key, fmt::format("more than {} values", max_values));
  std::vector<std::uint64_t> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    if (!is_count((*a)[i], lo, hi)) {
      fail_element(key, i, fmt::format("expected {}, got {}", what, (*a)[i]));
    }
    out.push_back(static_cast<std::uint64_t>((*a)[i]));
  }
  return out;
}

std::optional<std::vector<double>> option_map::numbers(std::string_view key, std::size_t max_values,
                                                       std::string_view what) {
  const option_value* v = find(key);
  if (v == nullptr) return std::nullopt;
  if (const double* x = std::get_if<double>(&v->value)) {
    if (!std::isfinite(*x)) expected(key, what);
    return std::vector<double>{*x};
  }
  const auto* a = std::get_if<std::vector<double>>(&v->value);
  if (a == nullptr || a->empty())
    expected(key, fmt::format("{} or a non-empty array of them", what));
  if (a->size() > max_values) fail(key, fmt::format("more than {} values", max_values));
  for (std::size_t i = 0; i < a->size(); ++i) {
    if (!std::isfinite((*a)[i]))
      fail_element(key, i, fmt::format("expected {}, got {}", what, (*a)[i]));
  }
  return *a;
}

bool option_map::is_table(std::string_view key) const {
  const auto it = table_.find(key);
  return it != table_.end() &&
         std::holds_alternative<std::shared_ptr<const option_table>>(it->second.value);
}

std::unique_ptr<option_reader> option_map::table(std::string_view key, std::string_view what) {
  const option_value* v = find(key);
  if (v == nullptr) fail_missing(key, fmt::format("missing {}", what));
  const auto* t = std::get_if<std::shared_ptr<const option_table>>(&v->value);
  if (t == nullptr) expected(key, what);
  return std::make_unique<option_map>(**t, fmt::format("{}.{}", path_, key));
}

std::exception_ptr option_map::error(where at, std::string_view key, std::size_t index,
                                     std::string_view message) const {
  const auto it = table_.find(key);
  const bool array =
      it != table_.end() && std::holds_alternative<std::vector<double>>(it->second.value);
  const std::string path = at == where::element && array
                               ? fmt::format("{}.{}[{}]", path_, key, index + 1)
                               : fmt::format("{}.{}", path_, key);
  return std::make_exception_ptr(
      invalid_argument::about(path, fmt::format("{}: {}", path, message)));
}

void option_map::reject_unread(std::string_view what, std::span<const std::string_view> accepted) {
  for (const auto& [key, value] : table_) {
    if (read_.contains(key)) continue;
    if (std::find(accepted.begin(), accepted.end(), key) != accepted.end()) continue;
    fail(key, fmt::format("unknown key in {}; expected one of: {}", what,
                          accepted.empty() ? std::string("none")
                                           : fmt::format("{}", fmt::join(accepted, ", "))));
  }
}

}  // namespace quadmc
