// A group of processes that compute one parallel_reduce together: a cell split across the ranks
// of an MPI run (bench/quadmc/mpi_run.hpp). Each process computes a contiguous share of every
// window of chunks, then all of them exchange their chunk results, so that every process holds
// every chunk's result and folds them in chunk order: the same bits as one process computing
// all chunks (docs/design.md#hot-path-contract). One exchange per window of chunks, never per
// chunk or per sample.
//
// The core layer only states the interface; an implementation (MPI) lives with the command, so
// the library never needs MPI. Every process of the group must make the same sequence of
// parallel_reduce calls while the exchange is active — true of any method, whose calls depend
// only on the plan, the seed and the values computed, which all processes share.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>

namespace quadmc {

class chunk_exchange {
 public:
  // A chunk that threw: its index (within the call) and the exception's message; none when
  // chunk == no_chunk.
  static constexpr std::size_t no_chunk = std::numeric_limits<std::size_t>::max();
  struct failure {
    std::size_t chunk = no_chunk;
    std::string message;
  };

  virtual ~chunk_exchange() = default;
  virtual unsigned size() const noexcept = 0;
  virtual unsigned rank() const noexcept = 0;
  // Collective: this process contributes `mine` (its share's results, bytes_per_rank[rank()]
  // bytes); `all` receives every process's share in rank order (Σ bytes_per_rank bytes). Also
  // agrees on a failure: returns the one with the lowest chunk over all processes (no_chunk if
  // none failed), so that every process throws the error a one-process run would throw.
  virtual failure exchange(const void* mine, void* all, const std::size_t* bytes_per_rank,
                           const failure& local) = 0;
  // Not collective: told by parallel_reduce, once per window, that `chunks` chunks of a
  // reduction whose chunk result is not shareable ran whole on this process while the exchange
  // was active. By default nothing; a test counts them to check a method's shares_chunks
  // (methods/method.hpp) against what its kernels really do.
  virtual void computed_whole(std::size_t /*chunks*/) noexcept {}
};

// Whether parallel_reduce may share a reduction's chunk results between processes. Only when
// the chunk result is all that a chunk computes (its function writes nothing that the caller reads
// afterwards) and is trivially copyable: a kernel opts in for its result type, beside the type.
// Every other reduction — one whose chunks store per-region estimates in a table of the caller's,
// as the adaptive cubature's do (rules/adaptive_cubature.hpp), or whose result holds vectors —
// runs all its chunks on every process: slower, and still exact.
template <class T>
inline constexpr bool shareable_chunk_result = false;

// A chunk result that stays on its process whatever T is (never shareable): for a reduction
// whose chunks also write elsewhere, such as a point set that tallies its weights on the side.
template <class T>
struct process_local {
  T value;
};

// The exchange parallel_reduce calls made on this thread take part in; nullptr (the default)
// means compute every chunk here. parallel_reduce clears it while its own chunks run, so a
// nested call inside a chunk stays local.
inline chunk_exchange*& active_chunk_exchange() noexcept {
  thread_local chunk_exchange* exchange = nullptr;
  return exchange;
}

// Makes `exchange` active on this thread for the scope's lifetime.
class chunk_exchange_scope {
 public:
  explicit chunk_exchange_scope(chunk_exchange* exchange) noexcept
      : previous_(active_chunk_exchange()) {
    active_chunk_exchange() = exchange;
  }
  ~chunk_exchange_scope() { active_chunk_exchange() = previous_; }
  chunk_exchange_scope(const chunk_exchange_scope&) = delete;
  chunk_exchange_scope& operator=(const chunk_exchange_scope&) = delete;

 private:
  chunk_exchange* previous_;
};

}  // namespace quadmc
