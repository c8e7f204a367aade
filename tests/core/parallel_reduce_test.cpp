// Tests for core/parallel_reduce.hpp: the result (and the error) must not depend on the number
// of threads, because chunk results are folded strictly in chunk order
// (docs/design.md#hot-path-contract). Equality here is bitwise, not within a tolerance: that is the
// promise.
#include "quadmc/core/parallel_reduce.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "quadmc/core/rng.hpp"
#include "quadmc/core/welford.hpp"

namespace {

constexpr unsigned thread_counts[] = {1, 2, 3, 8, 0};  // 0 = hardware concurrency

// Chunk c's value: ±(1 + v)·2^e with e uniform in [−30, 30], so partial sums lose different
// low bits in different fold orders. Sixteen values per chunk, pairwise-free plain sum, to give
// the threads something to do.
double chunk_value(std::size_t c) {
  const quadmc::random_stream rng(77, quadmc::stream_id({c}));
  double s = 0;
  for (std::uint64_t i = 0; i < 16; ++i) {
    const double sign = rng.uniform(3 * i) < 0.5 ? -1.0 : 1.0;
    const int exponent = static_cast<int>(rng.uniform(3 * i + 1) * 61) - 30;
    s += sign * std::ldexp(1 + rng.uniform(3 * i + 2), exponent);
  }
  return s;
}

std::uint64_t bits_of(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

double reduce_sum(std::size_t chunks, unsigned threads) {
  return quadmc::parallel_reduce(
      chunks, threads, 0.0, [](std::size_t c) { return chunk_value(c); },
      [](double& acc, double x) { acc += x; });
}

TEST(ParallelReduce, SumIsBitwiseIdenticalForAnyThreadCount) {
  constexpr std::size_t chunks = 1000;
  double serial = 0;
  for (std::size_t c = 0; c < chunks; ++c) serial += chunk_value(c);
  // The test can fail: folding the same chunk values in reverse changes the bits, so a
  // parallel_reduce that folded in completion order would be caught.
  double reversed = 0;
  for (std::size_t c = chunks; c-- > 0;) reversed += chunk_value(c);
  ASSERT_NE(bits_of(serial), bits_of(reversed)) << serial << " vs reversed " << reversed;

  for (const unsigned threads : thread_counts) {
    EXPECT_EQ(bits_of(reduce_sum(chunks, threads)), bits_of(serial)) << "threads " << threads;
  }
}

TEST(ParallelReduce, FoldsInChunkOrderWithANonCommutativeCombine) {
  // String concatenation shows the order itself, not just a sum that happens to agree.
  constexpr std::size_t chunks = 300;
  std::string expected;
  for (std::size_t c = 0; c < chunks; ++c) expected += std::to_string(c) + ' ';
  for (const unsigned threads : thread_counts) {
    const std::string folded = quadmc::parallel_reduce(
        chunks, threads, std::string{}, [](std::size_t c) { return std::to_string(c) + ' '; },
        [](std::string& acc, const std::string& s) { acc += s; });
    EXPECT_EQ(folded, expected) << "threads " << threads;
  }
}

TEST(ParallelReduce, MoreChunksThanTheWindowRunEachChunkOnceInOrder) {
  // The internal window is 4096 slots; 2·4096 + 3 chunks cross two window boundaries and leave a
  // short last window.
  constexpr std::size_t chunks = 2 * 4096 + 3;
  double serial = 0;
  for (std::size_t c = 0; c < chunks; ++c) serial += chunk_value(c);
  for (const unsigned threads : {1u, 3u, 8u}) {
    const auto calls = std::make_unique<std::atomic<int>[]>(chunks);
    const double sum = quadmc::parallel_reduce(
        chunks, threads, 0.0,
        [&](std::size_t c) {
          calls[c].fetch_add(1);
          return chunk_value(c);
        },
        [](double& acc, double x) { acc += x; });
    EXPECT_EQ(bits_of(sum), bits_of(serial)) << "threads " << threads;
    for (std::size_t c = 0; c < chunks; ++c) {
      ASSERT_EQ(calls[c].load(), 1) << "chunk " << c << ", threads " << threads;
    }
  }
}

TEST(ParallelReduce, MergesWelfordAccumulatorsReproducibly) {
  // The estimators' use: one welford per chunk, merged in chunk order.
  constexpr std::size_t chunks = 257;
  const auto chunk = [](std::size_t c) {
    quadmc::welford w;
    const quadmc::random_stream rng(5, quadmc::stream_id({c}));
    for (std::uint64_t i = 0; i < 100 + c % 7; ++i) w.add(std::exp(4 * rng.uniform(i)));
    return w;
  };
  const auto merge = [](quadmc::welford& acc, const quadmc::welford& w) { acc.merge(w); };
  const quadmc::welford one = quadmc::parallel_reduce(chunks, 1, quadmc::welford{}, chunk, merge);
  for (const unsigned threads : thread_counts) {
    const quadmc::welford w =
        quadmc::parallel_reduce(chunks, threads, quadmc::welford{}, chunk, merge);
    EXPECT_EQ(w.count(), one.count()) << "threads " << threads;
    EXPECT_EQ(bits_of(w.mean()), bits_of(one.mean())) << "threads " << threads;
    EXPECT_EQ(bits_of(w.m2()), bits_of(one.m2())) << "threads " << threads;
  }
}

TEST(ParallelReduce, BoolResultsAreNotPackedIntoSharedBits) {
  // T = bool once meant std::vector<bool> slots, whose writes from different threads race on
  // the same word (visible under ThreadSanitizer). Here: "every chunk passed", chunk 4321 fails.
  constexpr std::size_t chunks = 5000;
  for (const unsigned threads : thread_counts) {
    const bool all = quadmc::parallel_reduce(
        chunks, threads, true, [](std::size_t c) { return c != 4321; },
        [](bool& acc, bool ok) { acc = acc && ok; });
    EXPECT_FALSE(all) << "threads " << threads;
  }
}

TEST(ParallelReduce, NoChunksReturnsInitWithoutCallingTheChunkFunction) {
  for (const unsigned threads : thread_counts) {
    int calls = 0;
    const double r = quadmc::parallel_reduce(
        0, threads, 42.0,
        [&](std::size_t) {
          ++calls;
          return 1.0;
        },
        [](double& acc, double x) { acc += x; });
    EXPECT_EQ(r, 42.0) << "threads " << threads;
    EXPECT_EQ(calls, 0) << "threads " << threads;
  }
}

TEST(ParallelReduce, ExceptionFromAChunkPropagatesAndIsThatOfTheLowestFailingChunk) {
  // Chunks 50, 120 and 199 throw, and in the second window 5000. Whatever the threads, the caller
  // sees chunk 50's error, as a serial run would report it.
  const auto failing = [](std::size_t c) {
    if (c == 50 || c == 120 || c == 199 || c == 5000) {
      throw std::runtime_error("chunk " + std::to_string(c));
    }
    return chunk_value(c);
  };
  for (const unsigned threads : thread_counts) {
    try {
      quadmc::parallel_reduce(6000, threads, 0.0, failing, [](double& acc, double x) { acc += x; });
      ADD_FAILURE() << "no exception, threads " << threads;
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "chunk 50") << "threads " << threads;
    }
  }
  // Only the second window fails: the first window's work is done, then the error comes out.
  for (const unsigned threads : thread_counts) {
    EXPECT_THROW(quadmc::parallel_reduce(
                     6000, threads, 0.0,
                     [](std::size_t c) {
                       if (c == 5000) throw std::out_of_range("chunk 5000");
                       return 1.0;
                     },
                     [](double& acc, double x) { acc += x; }),
                 std::out_of_range)
        << "threads " << threads;
  }
}

TEST(ParallelReduce, NestedCallsFinishWithTheSerialBits) {
  // A chunk that itself calls parallel_reduce: the inner call runs on a pool thread or on the
  // caller while the pool's threads may all be busy with the outer call. The pool never makes a
  // caller wait for a helper to start, so this must finish (a deadlock would hang the test) with
  // the serial bits.
  constexpr std::size_t outer = 24;
  constexpr std::size_t inner = 40;
  double serial = 0;
  for (std::size_t c = 0; c < outer; ++c) {
    double partial = 0;
    for (std::size_t i = 0; i < inner; ++i) partial += chunk_value(c * inner + i);
    serial += partial;
  }
  for (const unsigned threads : thread_counts) {
    const double nested = quadmc::parallel_reduce(
        outer, threads, 0.0,
        [threads](std::size_t c) {
          return quadmc::parallel_reduce(
              inner, threads, 0.0, [c](std::size_t i) { return chunk_value(c * inner + i); },
              [](double& acc, double x) { acc += x; });
        },
        [](double& acc, double x) { acc += x; });
    EXPECT_EQ(bits_of(nested), bits_of(serial)) << "threads " << threads;
  }
}

TEST(ParallelReduce, ConcurrentCallersShareThePoolAndKeepTheirBits) {
  // Four threads call parallel_reduce at once, many times (as the gallery's workers do): the
  // pool's threads are lent to whichever caller asks, and each caller's result must still be
  // the serial one.
  constexpr std::size_t chunks = 300;
  double serial = 0;
  for (std::size_t c = 0; c < chunks; ++c) serial += chunk_value(c);
  std::vector<int> mismatches(4, 0);
  {
    std::vector<std::jthread> callers;
    for (std::size_t t = 0; t < mismatches.size(); ++t) {
      callers.emplace_back([&, t] {
        for (int round = 0; round < 25; ++round) {
          const unsigned threads = 1 + static_cast<unsigned>((t + round) % 3);
          if (bits_of(reduce_sum(chunks, threads)) != bits_of(serial)) ++mismatches[t];
        }
      });
    }
  }
  for (std::size_t t = 0; t < mismatches.size(); ++t) {
    EXPECT_EQ(mismatches[t], 0) << "caller " << t;
  }
}

TEST(ResolveThreads, ZeroMeansHardwareConcurrency) {
  const unsigned hw = std::thread::hardware_concurrency();
  EXPECT_EQ(quadmc::resolve_threads(0), hw == 0 ? 1u : hw);
  EXPECT_GE(quadmc::resolve_threads(0), 1u);
  EXPECT_EQ(quadmc::resolve_threads(1), 1u);
  EXPECT_EQ(quadmc::resolve_threads(3), 3u);
  // More threads than chunks is fine: the extra ones are not started.
  EXPECT_EQ(bits_of(reduce_sum(2, 64)), bits_of(chunk_value(0) + chunk_value(1)));
}

TEST(ParallelReducePeakThreads, CountsTheThreadsReallyUsed) {
  // min(threads, chunks) threads run a call (the caller among them), and the counter keeps the
  // largest such count since it was set to 0: what a run reports as "threads used".
  unsigned& peak = quadmc::parallel_reduce_peak_threads();
  peak = 0;
  (void)reduce_sum(1, 64);
  EXPECT_EQ(peak, 1u) << "one chunk runs inline, whatever is allowed";
  (void)reduce_sum(3, 8);
  EXPECT_EQ(peak, 3u);
  (void)reduce_sum(2, 8);
  EXPECT_EQ(peak, 3u) << "a peak, not the last call";
  (void)reduce_sum(100, 5);
  EXPECT_EQ(peak, 5u);
  // Another thread has its own counter: concurrent runs do not mix.
  unsigned other = 99;
  std::thread([&] { other = quadmc::parallel_reduce_peak_threads(); }).join();
  EXPECT_EQ(other, 0u);
  peak = 0;
}

}  // namespace
