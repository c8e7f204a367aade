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

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "quadmc/core/worker_pool.hpp"

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

// result = combine(…combine(combine(init, chunk_fn(0)), chunk_fn(1))…, chunk_fn(chunks − 1)).
// chunk_fn(std::size_t) -> T must be safe to call concurrently for distinct chunks; combine(T&,
// const T&) folds a chunk result into the accumulator. An exception thrown by a chunk is rethrown
// here after all threads have joined: that of the lowest-numbered failing chunk, as a serial run
// would throw. (After a failure no new chunk is handed out, but every chunk numbered below it
// was handed out earlier and still runs to its end, so the lowest failure is always seen and the
// error, like the result, does not depend on the thread count.)
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
  for (std::size_t begin = 0; begin < chunks; begin += window) {
    const std::size_t count = std::min(window, chunks - begin);
    const unsigned workers = static_cast<unsigned>(std::min<std::size_t>(threads, count));
    unsigned& peak = parallel_reduce_peak_threads();
    peak = std::max({peak, workers, 1u});
    if (workers <= 1) {
      for (std::size_t c = 0; c < count; ++c) slots[c].value = chunk_fn(begin + c);
    } else {
      std::atomic<std::size_t> next{0};
      std::exception_ptr failure;
      std::size_t failed_chunk = count;
      std::mutex failure_mutex;  // taken only when a chunk throws
      auto work = [&]() noexcept {
        for (std::size_t c = next.fetch_add(1); c < count; c = next.fetch_add(1)) {
          try {
            slots[c].value = chunk_fn(begin + c);
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
      // Returns once every thread that took a chunk has finished it (the pool's retire
      // synchronizes through its mutex, so the slots written by helpers are visible here).
      detail::run_with_helpers(workers - 1, work);
      if (failure) std::rethrow_exception(failure);
    }
    for (std::size_t c = 0; c < count; ++c) combine(init, slots[c].value);
  }
  return init;
}

}  // namespace quadmc
