// A process-wide pool of worker threads that parallel_reduce lends its chunks to, so a call pays a
// wake-up (a lock and a futex wake, about a microsecond) instead of starting and joining threads
// (tens of microseconds per thread). docs/design.md#hot-path-contract: the pool only decides who
// runs a chunk, never which chunks exist or the order their results are folded in, so results are
// bitwise the same with or without it.
//
// Contract of run_with_helpers(helpers, work): work() runs on the calling thread and on up to
// `helpers` pool threads at once; it must be noexcept and return once no work is left for anyone
// (parallel_reduce's work takes chunks from a shared counter until it runs out). The caller never
// waits for a helper to *start*: it runs work() itself, then withdraws the offer and waits only
// for the helpers that did join to return. So a call never deadlocks, even when every pool thread
// is busy — nested calls from inside a chunk (a helper is itself a caller) and concurrent calls
// from several threads (the gallery's workers) just get fewer helpers, and the caller does the
// rest. The pool grows to the largest number of idle helpers ever asked for at once and never
// shrinks; its threads sleep on a condition variable between calls (no spinning: the machine may
// be shared) and live until the process exits.
#pragma once

namespace quadmc::detail {

// One offer of work to the pool; lives on the caller's stack for the duration of the call. Its
// fields other than run and context belong to the pool (guarded by the pool's mutex).
struct pool_job {
  void (*run)(void* context) noexcept = nullptr;
  void* context = nullptr;
  unsigned wanted = 0;       // helpers that may still join
  unsigned active = 0;       // helpers running run(context) now
  pool_job* next = nullptr;  // the pool's queue of open offers
};

// Offers `job` to up to `helpers` pool threads (starting threads if fewer are idle).
void pool_offer(pool_job& job, unsigned helpers);

// Withdraws the offer (no helper joins after this) and waits until every helper that joined has
// returned from run(context); afterwards the job may be destroyed.
void pool_retire(pool_job& job) noexcept;

// Runs work() on this thread and on up to `helpers` pool threads; returns when all have returned.
template <class Work>
void run_with_helpers(unsigned helpers, Work& work) {
  static_assert(noexcept(work()), "work() runs on pool threads and must not throw");
  pool_job job;
  job.run = [](void* context) noexcept { (*static_cast<Work*>(context))(); };
  job.context = &work;
  pool_offer(job, helpers);
  work();
  pool_retire(job);
}

}  // namespace quadmc::detail
