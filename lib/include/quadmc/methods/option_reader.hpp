// The keys of one [[method]] table as a method's descriptor reads them: typed getters that
// remember which keys were read, and failures that name the file, line and key.
//
// Use it in a descriptor's `create` (method.hpp) to read the method's own options; the scene
// parser owns the table, reads the keys every method shares (name, label, integrands,
// repetitions, control, tolerances) and, after `create`, refuses every key nobody read, listing
// the ones the method accepts (the pattern of pbrt-v4's ParameterDictionary and ReportUnused:
// a typo is an error, never a silent default). Not for integrand parameters (the catalogue,
// functions/catalogue.hpp, reads those).
//
// Every getter that finds a value of the wrong type or out of range fails with
// "expected <what>, got <value>" at the key; a getter for a key that is absent returns nullopt.
// Counts are integers or integral floats (1e6), never negative; numbers are finite.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc {

class option_reader {
 public:
  virtual ~option_reader() = default;

  // The dotted path of this table in messages, e.g. "method[2]" or "method[2].warp".
  virtual std::string path() const = 0;
  virtual bool has(std::string_view key) const = 0;
  // The folder relative file paths of the table are read from (the scene file's); empty: the
  // working directory.
  virtual std::filesystem::path folder() const { return {}; }

  virtual std::optional<std::uint64_t> count(std::string_view key, std::uint64_t lo,
                                             std::uint64_t hi, std::string_view what) = 0;
  virtual std::optional<double> number(std::string_view key, std::string_view what) = 0;
  virtual std::optional<std::string> string(std::string_view key, std::string_view what) = 0;
  virtual std::optional<bool> boolean(std::string_view key) = 0;
  // An integer or an array of integers (at most `max_values`), each in [lo, hi].
  virtual std::optional<std::vector<std::uint64_t>> counts(std::string_view key, std::uint64_t lo,
                                                           std::uint64_t hi, std::size_t max_values,
                                                           std::string_view what) = 0;
  // A number or an array of numbers (at most `max_values`).
  virtual std::optional<std::vector<double>> numbers(std::string_view key, std::size_t max_values,
                                                     std::string_view what) = 0;
  // Whether the key holds a table ({ name = …, rate = … }); its reader, marked read.
  virtual bool is_table(std::string_view key) const = 0;
  virtual std::unique_ptr<option_reader> table(std::string_view key, std::string_view what) = 0;

  // Failures at a key, at element `index` (0-based; 1-based in the message) of an array key, or
  // at the table itself for a required key it lacks.
  [[noreturn]] void fail(std::string_view key, std::string_view message) const {
    std::rethrow_exception(error(where::key, key, 0, message));
  }
  [[noreturn]] void fail_element(std::string_view key, std::size_t index,
                                 std::string_view message) const {
    std::rethrow_exception(error(where::element, key, index, message));
  }
  [[noreturn]] void fail_missing(std::string_view key, std::string_view message) const {
    std::rethrow_exception(error(where::missing, key, 0, message));
  }

  // The error a failure throws (the scene parser's names file, line and key): at the key, at
  // element `index` of it, or at the table for a missing key.
  enum class where { key, element, missing };
  virtual std::exception_ptr error(where at, std::string_view key, std::size_t index,
                                   std::string_view message) const = 0;

  // Fails at the first key of the table nobody read: "unknown key in <what>; expected one of:
  // <accepted>".
  virtual void reject_unread(std::string_view what, std::span<const std::string_view> accepted) = 0;

  // A string that must be one of `choices`; nullopt when absent.
  std::optional<std::string> choice(std::string_view key,
                                    std::span<const std::string_view> choices) {
    std::string list;
    for (std::string_view c : choices) {
      if (!list.empty()) list += ", ";
      list += c;
    }
    const std::string what = "one of: " + list;
    std::optional<std::string> value = string(key, what);
    if (!value) return value;
    for (std::string_view c : choices) {
      if (*value == c) return value;
    }
    std::string message = "expected ";
    message += what;
    message += ", got \"";
    message += *value;
    message += '"';
    fail(key, message);
  }
};

}  // namespace quadmc
