// Tests of split_naive_sum.hpp: a left-to-right sum split across processes (threads of this test,
// each with its own exchange of an in-process group) is bitwise the sum one process adds in
// order, on terms that exercise every branch of the check: a start of 0, binade crossings, ties
// (whose rounding depends on the parity of the running sum), mixed and negative signs, and a
// failing chunk; and the check itself proves a block's end only when it is the serial chain's.
#include "quadmc/core/split_naive_sum.hpp"

#include "support/in_process_group.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace quadmc {
namespace {

using test_support::in_process_group;

double serial_sum(double start, const std::vector<double>& terms) {
  for (const double t : terms) start += t;
  return start;
}

naive_block_run run_of(double estimate, const std::vector<double>& terms) {
  return provisional_block_run(estimate, terms);
}

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

// Ties: 1 + u/2 (u = 2^-52) rounds to the even neighbour, so the chain from 1 stays at 1 and the
// chain from 1 + u goes to 1 + 2u. The check must take the provisional start of the true start's
// parity, whatever the estimate's parity.
TEST(ShiftedBlockEnd, TiesFollowTheParityOfTheTrueStart) {
  const double u = std::ldexp(1.0, -52);
  const std::vector<double> terms(10, u / 2);
  for (const double estimate : {1.0, 1.0 + u, 1.0 + 6 * u, 1.0 + 7 * u}) {
    const naive_block_run run = run_of(estimate, terms);
    for (const double start : {1.0, 1.0 + u, 1.0 + 2 * u, 1.0 + 3 * u, 1.0 + 1001 * u}) {
      const std::optional<double> end = shifted_block_end(run, start);
      ASSERT_TRUE(end.has_value()) << "estimate " << estimate << ", start " << start;
      EXPECT_EQ(bits(*end), bits(serial_sum(start, terms)))
          << "estimate " << estimate << ", start " << start;
    }
  }
  EXPECT_EQ(serial_sum(1.0 + u, terms), 1.0 + 2 * u);  // the tie the test is about
}

TEST(ShiftedBlockEnd, NegativeChainsAreTheMirrorImage) {
  const std::vector<double> terms{-1e-3, -2.5e-4, -0.0, -3e-7, -1.25e-2};
  const naive_block_run run = run_of(-0.6, terms);
  for (const double start : {-0.6, -0.5000001, -0.7, -0.61}) {
    const std::optional<double> end = shifted_block_end(run, start);
    ASSERT_TRUE(end.has_value()) << start;
    EXPECT_EQ(bits(*end), bits(serial_sum(start, terms))) << start;
  }
}

// What the check cannot prove it refuses, and split_naive_sum adds that block again.
TEST(ShiftedBlockEnd, RefusesWhatItCannotProve) {
  const std::vector<double> positive{1e-3, 2e-3, 3e-3};
  EXPECT_FALSE(shifted_block_end(run_of(0.6, positive), 0.0));       // no binade
  EXPECT_FALSE(shifted_block_end(run_of(0.6, positive), 1e-310));    // subnormal
  EXPECT_FALSE(shifted_block_end(run_of(0.6, positive), -0.6));      // terms of the other sign
  EXPECT_FALSE(shifted_block_end(run_of(0.6, {1e-3, -1e-3}), 0.6));  // mixed signs
  EXPECT_FALSE(shifted_block_end(run_of(0.999, positive), 0.999));   // crosses 1
  EXPECT_FALSE(shifted_block_end(run_of(0.6, positive), 0.9985));    // shifted across 1
  EXPECT_FALSE(shifted_block_end(run_of(0.3, positive), 0.6));       // another binade
  EXPECT_FALSE(shifted_block_end(run_of(0.0, positive), 0.6));       // no provisional run
}

// Random blocks (a fixed seed: a property test, not a statistical one): whenever the check
// proves an end it is the serial chain's, and it proves every block whose chains all stay in
// the start's binade.
TEST(ShiftedBlockEnd, ProvesExactlyTheSerialEnd) {
  std::mt19937_64 engine(20261202);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int proven = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int e = static_cast<int>(engine() % 41) - 20;
    const double lower = std::ldexp(1.0, e);
    const double start = lower * (1.0 + unit(engine));
    const double estimate = start * (1.0 + (unit(engine) - 0.5) * 1e-9);
    const double sign = trial % 2 == 0 ? 1.0 : -1.0;
    std::vector<double> terms(1 + engine() % 300);
    for (double& t : terms) {
      // Every fourth term a multiple of a half ulp (ties), the others of random magnitude.
      const int k = static_cast<int>(engine() % 40) + 8;
      t = engine() % 4 == 0 ? std::ldexp(static_cast<double>(engine() % 7), e - 53)
                            : std::ldexp(unit(engine), e - k);
    }
    for (double& t : terms) t *= sign;
    const naive_block_run run = run_of(sign * estimate, terms);
    const double serial = serial_sum(sign * start, terms);
    const std::optional<double> end = shifted_block_end(run, sign * start);
    if (end) {
      ++proven;
      EXPECT_EQ(bits(*end), bits(serial)) << "trial " << trial;
    } else {
      const double upper = 2 * lower;
      const bool inside = std::ilogb(estimate) == e && std::fabs(serial) < upper &&
                          std::fabs(run.end[0]) < upper && std::fabs(run.end[1]) < upper;
      EXPECT_FALSE(inside) << "trial " << trial << ": not proven, yet every chain stays inside";
    }
  }
  EXPECT_GT(proven, 3000);  // most random blocks stay in their binade: the check is not vacuous
}

// The terms of the sums below, as a function of the index: what a rule's chunk would compute.
using term_fn = std::function<double(std::uint64_t)>;

struct split_outcome {
  std::vector<double> sum;
  std::vector<std::string> error;
  std::uint64_t exchanges = 0;  // rank 0's
};

split_outcome split_across(unsigned processes, unsigned threads, const chunking& layout,
                           const term_fn& term) {
  in_process_group group(processes);
  split_outcome out;
  out.sum.assign(processes, std::numeric_limits<double>::quiet_NaN());
  out.error.assign(processes, "");
  std::vector<std::thread> running;
  for (unsigned r = 0; r < processes; ++r) {
    running.emplace_back([&, r] {
      in_process_group::member exchange(group, r);
      auto chunk_terms = [&](std::size_t c, std::span<double> terms) {
        for (std::uint64_t i = layout.begin(c); i < layout.end(c); ++i) {
          terms[i - layout.begin(c)] = term(i);
        }
      };
      try {
        out.sum[r] = split_naive_sum(exchange, layout, threads, chunk_terms);
      } catch (const std::exception& e) {
        out.error[r] = e.what();
      }
      if (r == 0) out.exchanges = exchange.windows_shared;
    });
  }
  for (std::thread& t : running) t.join();
  return out;
}

double serial_of(const chunking& layout, const term_fn& term) {
  double sum = 0.0;
  for (std::uint64_t i = 0; i < layout.total; ++i) sum += term(i);
  return sum;
}

struct named_terms {
  const char* name;
  term_fn term;
  // At most this many blocks fall back to the owner's second pass: the first (a start of 0)
  // and, where the sums only grow, two per binade crossed (the block that crosses, and the
  // next if its estimate fell on the other side); fewer than 40 binades here. No bound for
  // mixed signs.
  std::uint64_t fallbacks;
};

TEST(SplitNaiveSum, IsBitwiseTheSerialSumForAnyProcessAndThreadCount) {
  const double u = std::ldexp(1.0, -52);
  const std::vector<named_terms> cases{
      {"smooth positive", [](std::uint64_t i) { return 1e-3 / (1.0 + 1e-4 * double(i)); }, 81},
      {"negative", [](std::uint64_t i) { return -std::exp(-1e-5 * double(i)) * 0.37; }, 81},
      {"ties", [u](std::uint64_t i) { return i == 0 ? 1.0 : (i % 3 + 1) * u / 2; }, 2},
      {"growing", [](std::uint64_t i) { return double(i); }, 81},
      {"mixed signs", [](std::uint64_t i) { return std::sin(0.37 * double(i)) * 1e-3; }, ~0ull},
  };
  const chunking layout{200001, 250};  // 801 chunks, the last one short: many windows
  for (const named_terms& c : cases) {
    const double serial = serial_of(layout, c.term);
    for (const unsigned processes : {2u, 3u, 5u}) {
      for (const unsigned threads : {1u, 2u}) {
        const split_outcome out = split_across(processes, threads, layout, c.term);
        const std::size_t window = naive_chunks_per_rank * processes;
        const std::uint64_t windows = (layout.chunks() + window - 1) / window;
        for (unsigned r = 0; r < processes; ++r) {
          ASSERT_EQ(out.error[r], "") << c.name;
          EXPECT_EQ(bits(out.sum[r]), bits(serial))
              << c.name << ", " << processes << " processes, " << threads << " threads, rank " << r
              << ": " << out.sum[r] << " vs " << serial;
        }
        // Two exchanges per window and one per block the check did not prove.
        if (c.fallbacks != ~0ull) {
          EXPECT_LE(out.exchanges, 2 * windows + c.fallbacks)
              << c.name << ", " << processes << " processes";
        }
      }
    }
  }
}

// The lowest failing chunk's error is thrown on every process, whichever process computed it.
TEST(SplitNaiveSum, ThrowsTheLowestFailingChunksErrorEverywhere) {
  const chunking layout{10000, 100};
  const term_fn failing = [](std::uint64_t i) {
    if (i == 1234 || i == 5678) throw std::runtime_error("bad term " + std::to_string(i));
    return 1.0;
  };
  for (const unsigned processes : {2u, 3u}) {
    const split_outcome out = split_across(processes, 1, layout, failing);
    for (unsigned r = 0; r < processes; ++r) EXPECT_EQ(out.error[r], "bad term 1234") << r;
  }
}

}  // namespace
}  // namespace quadmc
