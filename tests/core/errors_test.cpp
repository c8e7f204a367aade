// Tests for core/errors.hpp: the error types every layer throws on bad input.
//
// What must hold (STYLE.md, "Bad input"): a message names the parameter, quotes the value exactly
// as given (17 significant digits for a double, so the quoted value round-trips) and says what was
// expected; an integrand's NaN/inf is reported with the point that produced it.
#include "quadmc/core/errors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace {

// Catches what `fn` throws as E and returns its message; fails the test if nothing is thrown.
template <class E, class Fn>
std::string message_of(Fn&& fn) {
  try {
    fn();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an exception";
  return {};
}

TEST(InvalidArgument, DerivesFromStdInvalidArgument) {
  static_assert(std::is_base_of_v<std::invalid_argument, quadmc::invalid_argument>);
  static_assert(std::is_base_of_v<std::domain_error, quadmc::non_finite_value>);
  // Callers that only know the standard library must catch it as std::invalid_argument.
  const std::string what = message_of<std::invalid_argument>(
      [] { throw quadmc::invalid_argument("n", "0", "at least 1"); });
  EXPECT_EQ(what, "invalid n = 0: expected at least 1");
}

TEST(InvalidArgument, KeepsTheParameterName) {
  try {
    quadmc::require(false, "dimension", 0, "at least 1");
    FAIL() << "require(false, ...) did not throw";
  } catch (const quadmc::invalid_argument& e) {
    EXPECT_EQ(e.parameter(), "dimension");
  }
  // The free-form constructor (scene files) has no parameter to name.
  EXPECT_EQ(quadmc::invalid_argument("scene line 3: unknown key").parameter(), "");
}

TEST(Require, DoesNothingWhenTheConditionHolds) {
  EXPECT_NO_THROW(quadmc::require(true, "n", -1, "anything"));
  EXPECT_NO_THROW(quadmc::require_finite(1e308, "a"));
}

TEST(Require, NamesParameterValueAndExpectation) {
  const std::string what = message_of<quadmc::invalid_argument>(
      [] { quadmc::require(false, "samples", std::uint64_t{3}, "a power of two"); });
  EXPECT_EQ(what, "invalid samples = 3: expected a power of two");
  EXPECT_NE(what.find("samples"), std::string::npos) << what;
  EXPECT_NE(what.find("3"), std::string::npos) << what;
  EXPECT_NE(what.find("a power of two"), std::string::npos) << what;
}

TEST(Require, QuotesDoublesWithSeventeenSignificantDigits) {
  // 0.1 is stored as 0.1000000000000000055511151231257827…; 17 significant digits are what it
  // takes to name that double and no neighbour (IEEE 754-2019 §5.12.2).
  const std::string what =
      message_of<quadmc::invalid_argument>([] { quadmc::require(false, "a", 0.1, "a < b"); });
  EXPECT_EQ(what, "invalid a = 0.10000000000000001: expected a < b");

  // The quoted text parses back to the very same double, also for a value that is not short.
  for (const double v : {1.0 / 3.0, -2.5e-300, std::nextafter(1.0, 2.0), 6.02214076e23}) {
    const std::string q = quadmc::quote(v);
    EXPECT_EQ(std::stod(q), v) << "quote(" << v << ") = " << q;
  }
  // Other floating types get their own max_digits10 (9 for float), again round-tripping.
  EXPECT_EQ(quadmc::quote(0.1f), "0.100000001");
  EXPECT_EQ(std::stof(quadmc::quote(0.1f)), 0.1f);
  // Integers and strings are quoted as they are.
  EXPECT_EQ(quadmc::quote(-42), "-42");
  EXPECT_EQ(quadmc::quote(std::string("gauss")), "gauss");
}

TEST(Require, FiniteRejectsNanAndInfinityAndQuotesThem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(message_of<quadmc::invalid_argument>([&] { quadmc::require_finite(nan, "b"); }),
            "invalid b = nan: expected a finite number");
  EXPECT_EQ(message_of<quadmc::invalid_argument>([&] { quadmc::require_finite(-inf, "b"); }),
            "invalid b = -inf: expected a finite number");
}

TEST(NonFiniteValue, NamesTheSourceTheValueAndThePoint) {
  const std::vector<double> point = {0.5, 0.25, 0.1};
  const std::string what = message_of<quadmc::non_finite_value>([&] {
    throw quadmc::non_finite_value("genz_corner_peak", point,
                                   std::numeric_limits<double>::infinity());
  });
  // fmt prints each coordinate in its shortest round-trip form, so the point is exact.
  EXPECT_EQ(what, "genz_corner_peak returned inf at x = (0.5, 0.25, 0.1)");
}

}  // namespace
