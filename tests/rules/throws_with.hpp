// Test-only: asserts that a call throws exception type E whose message contains a given text,
// so every bad-input test checks both the type and what the message tells the user.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <string_view>

namespace quadmc::testing {

template <class E, class Fn>
::testing::AssertionResult throws_with(Fn&& fn, std::string_view expected_text) {
  try {
    fn();
  } catch (const E& e) {
    const std::string message = e.what();
    if (message.find(expected_text) != std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "message \"" << message << "\" lacks \"" << expected_text << "\"";
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "threw another type: " << e.what();
  }
  return ::testing::AssertionFailure() << "did not throw (expected \"" << expected_text << "\")";
}

}  // namespace quadmc::testing
