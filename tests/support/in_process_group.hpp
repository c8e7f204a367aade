// K processes as K threads of a test, for code that runs under a chunk_exchange
// (core/chunk_exchange.hpp): each member is one process's exchange. Used by the tests of
// split_naive_sum (tests/core) and of every method's shares_chunks (tests/methods).
#pragma once

#include "quadmc/core/chunk_exchange.hpp"

#include <gtest/gtest.h>

#include <barrier>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace quadmc::test_support {

// K processes as K threads: each posts its share, all wait, each copies every share in rank
// order, all wait again (so no share is overwritten before every process has read it).
class in_process_group {
 public:
  explicit in_process_group(unsigned size) : size_(size), barrier_(size), posts_(size) {}

  class member final : public chunk_exchange {
   public:
    member(in_process_group& group, unsigned rank) : group_(&group), rank_(rank) {}
    unsigned size() const noexcept override { return group_->size_; }
    unsigned rank() const noexcept override { return rank_; }
    failure exchange(const void* mine, void* all, const std::size_t* bytes_per_rank,
                     const failure& local) override {
      ++windows_shared;
      return group_->exchange(rank_, mine, all, bytes_per_rank, local);
    }
    void computed_whole(std::size_t chunks) noexcept override { chunks_whole += chunks; }

    std::uint64_t windows_shared = 0;
    std::uint64_t chunks_whole = 0;

   private:
    in_process_group* group_;
    unsigned rank_;
  };

 private:
  struct post {
    const void* mine = nullptr;
    std::size_t bytes = 0;
    chunk_exchange::failure local;
  };

  chunk_exchange::failure exchange(unsigned rank, const void* mine, void* all,
                                   const std::size_t* bytes_per_rank,
                                   const chunk_exchange::failure& local) {
    posts_[rank] = post{mine, bytes_per_rank[rank], local};
    barrier_.arrive_and_wait();
    chunk_exchange::failure agreed;
    for (const post& p : posts_) {
      if (p.local.chunk < agreed.chunk) agreed = p.local;
    }
    if (agreed.chunk == chunk_exchange::no_chunk) {
      auto* out = static_cast<char*>(all);
      for (unsigned r = 0; r < size_; ++r) {
        EXPECT_EQ(posts_[r].bytes, bytes_per_rank[r]);
        if (posts_[r].bytes > 0) std::memcpy(out, posts_[r].mine, posts_[r].bytes);
        out += bytes_per_rank[r];
      }
    }
    barrier_.arrive_and_wait();
    return agreed;
  }

  unsigned size_;
  std::barrier<> barrier_;
  std::vector<post> posts_;
};

}  // namespace quadmc::test_support
