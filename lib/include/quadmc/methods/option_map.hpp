// Method options held in memory: the option_reader for a method configured from C++ (tests, a
// program that reads no scene file), with the same checks and messages as a scene's table minus
// the file position.
//
// Use make_method (registry.hpp) with an option_table, e.g.
//   make_method("importance", {{"warp", "power"}, {"point_set", "jittered"}});
// Not for scene files: scene/parse.cpp reads those, with file:line:key errors.
#pragma once

#include "quadmc/methods/option_reader.hpp"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <variant>
#include <vector>

namespace quadmc {

struct option_value;
using option_table = std::map<std::string, option_value, std::less<>>;

// A number (integers are numbers: counts accept integral values), a string, a boolean, an array
// of numbers, or a nested table.
struct option_value {
  std::variant<double, std::string, bool, std::vector<double>, std::shared_ptr<const option_table>>
      value;

  option_value(double x) : value(x) {}                    // NOLINT(google-explicit-constructor)
  option_value(int x) : value(static_cast<double>(x)) {}  // NOLINT(google-explicit-constructor)
  option_value(const char* s) : value(std::string(s)) {}  // NOLINT(google-explicit-constructor)
  option_value(std::string s) : value(std::move(s)) {}    // NOLINT(google-explicit-constructor)
  option_value(bool b) : value(b) {}                      // NOLINT(google-explicit-constructor)
  option_value(std::vector<double> v) : value(std::move(v)) {}  // NOLINT
  option_value(option_table t)                                  // NOLINT
      : value(std::make_shared<const option_table>(std::move(t))) {}
};

class option_map final : public option_reader {
 public:
  explicit option_map(option_table table, std::string path = "options")
      : table_(std::move(table)), path_(std::move(path)) {}

  std::string path() const override { return path_; }
  bool has(std::string_view key) const override { return table_.contains(key); }
  std::optional<std::uint64_t> count(std::string_view key, std::uint64_t lo, std::uint64_t hi,
                                     std::string_view what) override;
  std::optional<double> number(std::string_view key, std::string_view what) override;
  std::optional<std::string> string(std::string_view key, std::string_view what) override;
  std::optional<bool> boolean(std::string_view key) override;
  std::optional<std::vector<std::uint64_t>> counts(std::string_view key, std::uint64_t lo,
                                                   std::uint64_t hi, std::size_t max_values,
                                                   std::string_view what) override;
  std::optional<std::vector<double>> numbers(std::string_view key, std::size_t max_values,
                                             std::string_view what) override;
  bool is_table(std::string_view key) const override;
  std::unique_ptr<option_reader> table(std::string_view key, std::string_view what) override;
  std::exception_ptr error(where at, std::string_view key, std::size_t index,
                           std::string_view message) const override;
  void reject_unread(std::string_view what, std::span<const std::string_view> accepted) override;

 private:
  const option_value* find(std::string_view key);
  [[noreturn]] void expected(std::string_view key, std::string_view what) const;

  option_table table_;
  std::string path_;
  std::set<std::string, std::less<>> read_;
};

}  // namespace quadmc
