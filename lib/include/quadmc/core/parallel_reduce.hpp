// Deterministic parallel reduction over fixed-size chunks.
//
// The work is cut into `chunks` pieces whose boundaries depend only on the problem (never on the
// thread count). Threads take chunks in any order and write each result into its own slot; the
// slots are then folded strictly left to right, chunk 0 first. Floating-point addition is not
// associative, so this fixed fold order is what makes a run on 8 threads bitwise equal to a run
// on 1 (docs/design.md#hot-path-contract: chunk results are folded in chunk order).
//
// Memory stays bounded for any N: chunks are processed in windows of at most `window` slots, each
// window folded before the next starts. The fold order is the same as with one big window.
// The calling thread runs chunks itself, helped by threads of a persistent pool
// (core/worker_pool.hpp) that are woken, not started, per window: a call costs about a
// microsecond more than the work, so small cells may ask for threads too. A single chunk or a
// single thread runs inline, without the pool. Calls may nest (a chunk may call parallel_reduce)
// and may run concurrently from several threads: a caller never waits for a helper to start, so
// busy pool threads mean fewer helpers, never a deadlock, and never other results.
#pragma once

#include "quadmc/core/chunk_exchange.hpp"
#include "quadmc/core/worker_pool.hpp"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace quadmc {

// Number of threads to use when a caller asks for 0 ("all cores").
inline unsigned resolve_threads(unsigned requested) noexcept {
  if (requested != 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : hw;
}

// The most threads (the caller included) that any parallel_reduce called from this thread has
// run on since the counter was last set to 0: min(threads, chunks of a window) per call. A call
// with fewer chunks than threads runs on fewer, so this, not the count asked for, is the number
// of threads a run really used (the runner reports it). (A pool thread busy with another
// caller's work leaves a call with fewer helpers; that is not counted, as it changes only the
// speed.) One counter per calling thread, so runs on different threads do not mix;
// updated once per window of chunks, never per chunk.
inline unsigned& parallel_reduce_peak_threads() noexcept {
  thread_local unsigned peak = 0;
  return peak;
}

namespace detail {

// Computes chunks begin … begin + count − 1 into out[0 … count − 1] on up to `threads` threads
// (the caller's included). Returns the lowest failing chunk's offset (count if none) and its
// exception: after a failure no new chunk is handed out, but every chunk numbered below it was
// handed out earlier and still runs to its end, so the lowest failure is always seen and the
// error, like the result, does not depend on the thread count.
template <class Slot, class ChunkFn>
std::size_t compute_chunks(Slot* out, std::size_t begin, std::size_t count, unsigned threads,
                           ChunkFn& chunk_fn, std::exception_ptr& failure) {
  const unsigned workers = static_cast<unsigned>(std::min<std::size_t>(threads, count));
  unsigned& peak = parallel_reduce_peak_threads();
  peak = std::max({peak, workers, 1u});
  std::atomic<std::size_t> next{0};
  std::size_t failed_chunk = count;
  std::mutex failure_mutex;  // taken only when a chunk throws
  auto work = [&]() noexcept {
    for (std::size_t c = next.fetch_add(1); c < count; c = next.fetch_add(1)) {
      try {
        out[c].value = chunk_fn(begin + c);
      } catch (...) {
        const std::lock_guard lock(failure_mutex);
        if (c < failed_chunk) {
          failed_chunk = c;
          failure = std::current_exception();
        }
        next.store(count);  // stop handing out chunks
      }
    }
  };
  if (workers <= 1) {
    work();
  } else {
    // Returns once every thread that took a chunk has finished it (the pool's retire
    // synchronizes through its mutex, so the slots written by helpers are visible here).
    detail::run_with_helpers(workers - 1, work);
  }
  return failed_chunk;
}

inline std::string exception_message(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "an exception that is not a std::exception";
  }
}

// One window of a parallel_reduce shared by the processes of `exchange`: rank r computes chunks
// [count·r/K, count·(r+1)/K) of it (contiguous, so the exchange hands every result back already
// in chunk order) and receives the others' into out[0 … count − 1].
template <class Slot, class ChunkFn>
void distributed_window(chunk_exchange& exchange, Slot* out, std::size_t begin, std::size_t count,
                        unsigned threads, ChunkFn& chunk_fn) {
  static_assert(std::is_trivially_copyable_v<Slot>, "chunk results travel as bytes");
  const unsigned ranks = exchange.size();
  std::vector<std::size_t> bytes(ranks);
  std::vector<std::size_t> first(ranks + 1);
  for (unsigned r = 0; r <= ranks; ++r) first[r] = count * r / ranks;
  for (unsigned r = 0; r < ranks; ++r) bytes[r] = (first[r + 1] - first[r]) * sizeof(Slot);
  const unsigned me = exchange.rank();
  const std::size_t mine = first[me + 1] - first[me];
  std::vector<Slot> own(mine);
  std::exception_ptr failure;
  std::size_t failed = mine;
  {
    // A parallel_reduce inside a chunk stays on this process.
    const chunk_exchange_scope local(nullptr);
    failed = compute_chunks(own.data(), begin + first[me], mine, threads, chunk_fn, failure);
  }
  chunk_exchange::failure local_failure;
  if (failed < mine) {
    local_failure.chunk = begin + first[me] + failed;
    local_failure.message = exception_message(failure);
  }
  const chunk_exchange::failure agreed =
      exchange.exchange(own.data(), out, bytes.data(), local_failure);
  if (agreed.chunk != chunk_exchange::no_chunk) {
    if (agreed.chunk == local_failure.chunk) std::rethrow_exception(failure);
    throw std::runtime_error(agreed.message);
  }
}

}  // namespace detail

// result = combine(…combine(combine(init, chunk_fn(0)), chunk_fn(1))…, chunk_fn(chunks − 1)).
// chunk_fn(std::size_t) -> T must be safe to call concurrently for distinct chunks; combine(T&,
// const T&) folds a chunk result into the accumulator. An exception thrown by a chunk is rethrown
// here after all threads have joined: that of the lowest-numbered failing chunk, as a serial run
// would throw.
//
// With a chunk_exchange active on this thread (core/chunk_exchange.hpp) and a T whose kernel
// declared it shareable_chunk_result, this process computes only its share of each window and
// receives the other processes' chunk results; the fold is the same, so is the result. A failure on
// another process is thrown here as a std::runtime_error with that chunk's message. Any other T
// runs every chunk here and tells the active exchange so (chunk_exchange::computed_whole).
template <class T, class ChunkFn, class Combine>
T parallel_reduce(std::size_t chunks, unsigned threads, T init, ChunkFn&& chunk_fn,
                  Combine&& combine) {
  threads = resolve_threads(threads);
  constexpr std::size_t window = 4096;
  // One slot per chunk of the window, each written by one thread. Wrapped in a struct so that
  // T = bool does not get std::vector<bool>, whose packed bits would make those writes a race.
  struct slot {
    T value;
  };
  std::vector<slot> slots(std::min(chunks, window));
  chunk_exchange* exchange = nullptr;
  chunk_exchange* const active = active_chunk_exchange();
  if (active != nullptr && active->size() > 1) exchange = active;
  if constexpr (shareable_chunk_result<T>) {
    static_assert(std::is_trivially_copyable_v<T>, "shared chunk results travel as bytes");
  }
  for (std::size_t begin = 0; begin < chunks; begin += window) {
    const std::size_t count = std::min(window, chunks - begin);
    bool shared = false;
    if constexpr (shareable_chunk_result<T>) {
      if (exchange != nullptr) {
        detail::distributed_window(*exchange, slots.data(), begin, count, threads, chunk_fn);
        shared = true;
      }
    }
    if (!shared) {
      if (exchange != nullptr) exchange->computed_whole(count);
      std::exception_ptr failure;
      if (detail::compute_chunks(slots.data(), begin, count, threads, chunk_fn, failure) < count) {
        std::rethrow_exception(failure);
      }
    }
    for (std::size_t c = 0; c < count; ++c) combine(init, slots[c].value);
  }
  return init;
}

}  // namespace quadmc
