// core/function_ref.hpp: the call reaches the referenced callable with its arguments, returns
// its result, sees the callable's state as it is at the time of the call (a reference, not a
// copy), and is what the kernels compiled in the library call once per batch.
#include "quadmc/core/function_ref.hpp"

#include <gtest/gtest.h>

#include <span>
#include <string>
#include <vector>

namespace {

using quadmc::function_ref;

TEST(FunctionRef, PassesArgumentsAndReturnsTheResult) {
  const auto add = [](int a, int b) { return 10 * a + b; };
  const function_ref<int(int, int)> f(add);
  EXPECT_EQ(f(3, 4), 34);
  EXPECT_EQ(f(4, 3), 43);
}

TEST(FunctionRef, RefersToTheCallableInsteadOfCopyingIt) {
  int calls = 0;
  const auto count = [&calls]() { return ++calls; };
  const function_ref<int()> f(count);
  EXPECT_EQ(f(), 1);
  EXPECT_EQ(f(), 2);
  EXPECT_EQ(calls, 2);
}

TEST(FunctionRef, WritesThroughSpansAsTheKernelsBatchesDo) {
  const auto fill = [](std::size_t first, std::span<double> y) {
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = static_cast<double>(first + i);
  };
  const function_ref<void(std::size_t, std::span<double>)> f(fill);
  std::vector<double> y(3);
  f(5, y);
  EXPECT_EQ(y, (std::vector<double>{5.0, 6.0, 7.0}));
}

TEST(FunctionRef, CallsAFunctionObjectWithAConstCallOperator) {
  struct prefix {
    std::string text;
    std::string operator()(const std::string& s) const { return text + s; }
  };
  const prefix hello{"hello, "};
  const function_ref<std::string(const std::string&)> f(hello);
  EXPECT_EQ(f("world"), "hello, world");
}

}  // namespace
