// The persistent worker pool behind parallel_reduce (core/worker_pool.hpp says the contract).
//
// One mutex guards the queue of open offers and each job's counters; it is taken once per call
// to offer, once to retire, and once per helper joining and leaving — never per chunk (chunks are
// handed out by parallel_reduce's own atomic counter). The pool object is created on first use
// and deliberately never destroyed: its threads sleep in cv_.wait until the process exits, so no
// static destructor can join a thread that a late parallel_reduce (from another static
// destructor or a detached thread) might still need.
#include "quadmc/core/worker_pool.hpp"

#include <condition_variable>
#include <mutex>
#include <thread>

namespace quadmc::detail {
namespace {

class worker_pool {
 public:
  void offer(pool_job& job, unsigned helpers) {
    if (helpers == 0) return;
    {
      const std::lock_guard lock(mutex_);
      // Threads are started only when too few are idle; the first calls pay for them, later ones
      // find them sleeping. A started thread counts as idle until it takes a job.
      while (idle_ < helpers) {
        std::thread(&worker_pool::loop, this).detach();
        ++idle_;
      }
      job.wanted = helpers;
      job.active = 0;
      job.next = nullptr;
      if (tail_ == nullptr) {
        head_ = &job;
      } else {
        tail_->next = &job;
      }
      tail_ = &job;
    }
    if (helpers == 1) {
      work_.notify_one();
    } else {
      work_.notify_all();
    }
  }

  void retire(pool_job& job) noexcept {
    std::unique_lock lock(mutex_);
    if (job.wanted > 0) unlink(job);
    job.wanted = 0;
    done_.wait(lock, [&] { return job.active == 0; });
  }

 private:
  void unlink(pool_job& job) noexcept {
    pool_job* previous = nullptr;
    for (pool_job* j = head_; j != nullptr; previous = j, j = j->next) {
      if (j != &job) continue;
      (previous == nullptr ? head_ : previous->next) = job.next;
      if (tail_ == &job) tail_ = previous;
      return;
    }
  }

  [[noreturn]] void loop() noexcept {
    std::unique_lock lock(mutex_);
    for (;;) {
      work_.wait(lock, [&] { return head_ != nullptr; });
      pool_job& job = *head_;
      --idle_;
      ++job.active;
      if (--job.wanted == 0) unlink(job);
      lock.unlock();
      job.run(job.context);
      lock.lock();
      ++idle_;
      // The caller may be waiting in retire (under this mutex, so it cannot miss this).
      if (--job.active == 0 && job.wanted == 0) done_.notify_all();
    }
  }

  std::mutex mutex_;
  std::condition_variable work_;  // an offer was queued
  std::condition_variable done_;  // a helper left a withdrawn job
  pool_job* head_ = nullptr;
  pool_job* tail_ = nullptr;
  unsigned idle_ = 0;
};

worker_pool& pool() {
  static worker_pool* const p = new worker_pool;  // never destroyed (see the file comment)
  return *p;
}

}  // namespace

void pool_offer(pool_job& job, unsigned helpers) {
  pool().offer(job, helpers);
}

void pool_retire(pool_job& job) noexcept {
  pool().retire(job);
}

}  // namespace quadmc::detail
