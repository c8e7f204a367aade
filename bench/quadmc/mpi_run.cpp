// The MPI runner of `quadmc run` (mpi_run.hpp). Everything MPI is in this file, compiled with
// QUADMC_HAVE_MPI = 1 only in the MPI build; the library never sees MPI.
#include "mpi_run.hpp"

#include "quadmc/core/chunk_exchange.hpp"
#include "quadmc/core/errors.hpp"
#include "quadmc/core/parallel_reduce.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#ifndef QUADMC_HAVE_MPI
#define QUADMC_HAVE_MPI 0
#endif
#if QUADMC_HAVE_MPI
#include <mpi.h>
#endif

namespace quadmc_cli::mpi {

namespace {

// Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE in every process it starts; PMI_SIZE and
// PMIX_RANK are what other launchers (and Open MPI's PMIx) set.
bool launched_by_mpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr ||
         std::getenv("PMIX_RANK") != nullptr;
}

[[maybe_unused]] bool mpi_started = false;

}  // namespace

bool built_with_mpi() noexcept {
  return QUADMC_HAVE_MPI != 0;
}

#if !QUADMC_HAVE_MPI

world start(int&, char**&) {
  if (launched_by_mpirun()) {
    throw std::runtime_error(
        "started by mpirun, but this quadmc was built without MPI: mpirun use needs the MPI "
        "build (install libopenmpi-dev and openmpi-bin, then configure again: QUADMC_MPI is on "
        "when CMake finds Open MPI)");
  }
  return {};
}

void finish() noexcept {}

bool agree_to_proceed(const world&, bool rank0_ok) {
  return rank0_ok;
}

mpi_scheduler::mpi_scheduler(world w, split_policy policy) : world_(w), policy_(policy) {}

void mpi_scheduler::run_cells(quadmc::run_session&, quadmc::run_assembly&) {
  throw std::logic_error("the MPI scheduler needs the MPI build (QUADMC_MPI)");
}

#else

namespace {

// MPI's counts are int: a message over 2 GiB − 1 is refused with the reason, never truncated.
int as_count(std::size_t bytes, std::string_view what) {
  if (bytes > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw std::runtime_error(fmt::format(
        "{} is {} bytes, more than one MPI message holds (2^31 − 1): run fewer repetitions or "
        "cells per rank",
        what, bytes));
  }
  return static_cast<int>(bytes);
}

// Chunk results of a split cell travel as bytes (T is trivially copyable, checked by
// parallel_reduce); the failure, if any, is agreed on first, so no rank waits for a share
// another rank will never send.
class mpi_chunk_exchange final : public quadmc::chunk_exchange {
 public:
  explicit mpi_chunk_exchange(const world& w) : world_(w) {}
  unsigned size() const noexcept override { return world_.size; }
  unsigned rank() const noexcept override { return world_.rank; }

  failure exchange(const void* mine, void* all, const std::size_t* bytes_per_rank,
                   const failure& local) override {
    std::uint64_t own = local.chunk;
    std::uint64_t lowest = 0;
    MPI_Allreduce(&own, &lowest, 1, MPI_UINT64_T, MPI_MIN, MPI_COMM_WORLD);
    if (lowest != no_chunk) {
      // The rank that owns the lowest failing chunk sends its message to all.
      int owner_candidate =
          own == lowest ? static_cast<int>(world_.rank) : std::numeric_limits<int>::max();
      int owner = 0;
      MPI_Allreduce(&owner_candidate, &owner, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
      std::string message = own == lowest ? local.message : std::string();
      std::uint64_t length = message.size();
      MPI_Bcast(&length, 1, MPI_UINT64_T, owner, MPI_COMM_WORLD);
      message.resize(length);
      MPI_Bcast(message.data(), as_count(length, "a chunk's error message"), MPI_CHAR, owner,
                MPI_COMM_WORLD);
      return failure{lowest, message};
    }
    std::vector<int> counts(world_.size);
    std::vector<int> displacements(world_.size);
    std::size_t offset = 0;
    for (unsigned r = 0; r < world_.size; ++r) {
      counts[r] = as_count(bytes_per_rank[r], "a window of chunk results");
      displacements[r] = as_count(offset, "a window of chunk results");
      offset += bytes_per_rank[r];
    }
    MPI_Allgatherv(mine, counts[world_.rank], MPI_BYTE, all, counts.data(), displacements.data(),
                   MPI_BYTE, MPI_COMM_WORLD);
    return {};
  }

 private:
  world world_;
};

// What a rank sends rank 0: its first failure (if any), then per cell it ran or skipped the
// repetitions or the skip reason.
static_assert(std::is_trivially_copyable_v<quadmc::repetition_result>,
              "repetitions travel between ranks as bytes");
static_assert(std::is_trivially_copyable_v<quadmc::cell_timing>,
              "a cell's timing travels between ranks as bytes");

class byte_writer {
 public:
  void u64(std::uint64_t v) { raw(&v, sizeof v); }
  void text(const std::string& s) {
    u64(s.size());
    raw(s.data(), s.size());
  }
  void raw(const void* data, std::size_t n) {
    const auto* p = static_cast<const char*>(data);
    bytes_.insert(bytes_.end(), p, p + n);
  }
  std::vector<char>& bytes() { return bytes_; }

 private:
  std::vector<char> bytes_;
};

class byte_reader {
 public:
  byte_reader(const char* data, std::size_t size) : data_(data), size_(size) {}
  std::uint64_t u64() {
    std::uint64_t v = 0;
    raw(&v, sizeof v);
    return v;
  }
  std::string text() {
    std::string s(u64(), '\0');
    raw(s.data(), s.size());
    return s;
  }
  void raw(void* out, std::size_t n) {
    if (n > size_ - at_) throw std::runtime_error("a rank's gathered results are truncated");
    std::memcpy(out, data_ + at_, n);
    at_ += n;
  }
  bool done() const noexcept { return at_ == size_; }

 private:
  const char* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

enum record_kind : std::uint64_t { ran = 0, skipped = 1 };

struct rank_outcome {
  std::optional<std::size_t> failed_cell;  // the first cell that failed here (plan index)
  std::string failure;
  std::vector<std::pair<std::size_t, quadmc::cell_run> > ran;
  std::vector<std::pair<std::size_t, quadmc::plan_skip> > skipped;
};

std::vector<char> serialise(const rank_outcome& o) {
  byte_writer w;
  w.u64(o.failed_cell ? 1 : 0);
  w.u64(o.failed_cell.value_or(0));
  w.text(o.failure);
  w.u64(o.ran.size() + o.skipped.size());
  for (const auto& [index, run] : o.ran) {
    w.u64(index);
    w.u64(ran);
    w.raw(&run.timing, sizeof run.timing);
    w.u64(run.repetitions.size());
    w.raw(run.repetitions.data(), run.repetitions.size() * sizeof(quadmc::repetition_result));
  }
  for (const auto& [index, skip] : o.skipped) {
    w.u64(index);
    w.u64(skipped);
    w.text(skip.what);
    w.text(skip.reason);
  }
  return std::move(w.bytes());
}

rank_outcome deserialise(const char* data, std::size_t size) {
  byte_reader r(data, size);
  rank_outcome o;
  const bool failed = r.u64() != 0;
  const std::uint64_t failed_cell = r.u64();
  if (failed) o.failed_cell = failed_cell;
  o.failure = r.text();
  const std::uint64_t records = r.u64();
  for (std::uint64_t k = 0; k < records; ++k) {
    const std::size_t index = r.u64();
    if (r.u64() == ran) {
      quadmc::cell_run run;
      r.raw(&run.timing, sizeof run.timing);
      run.repetitions.resize(r.u64());
      r.raw(run.repetitions.data(), run.repetitions.size() * sizeof(quadmc::repetition_result));
      o.ran.emplace_back(index, std::move(run));
    } else {
      quadmc::plan_skip skip;
      skip.what = r.text();
      skip.reason = r.text();
      o.skipped.emplace_back(index, std::move(skip));
    }
  }
  if (!r.done()) throw std::runtime_error("a rank's gathered results have trailing bytes");
  return o;
}

// Each series' cost (scene/schedule.hpp): rank 0 times the probes (time_series_costs) and sends
// the figures to every rank, so that all ranks cost cells alike and make one assignment.
std::vector<quadmc::series_cost> series_costs(const quadmc::plan& p,
                                              const quadmc::cost_probes& probes,
                                              const quadmc::run_context& context, const world& w) {
  const std::size_t series = probes.smallest.size();
  std::vector<double> figures(2 * series);
  if (w.rank == 0) {
    const std::vector<quadmc::series_cost> measured = quadmc::time_series_costs(p, probes, context);
    for (std::size_t s = 0; s < series; ++s) {
      figures[2 * s] = measured[s].fixed;
      figures[2 * s + 1] = measured[s].per_evaluation;
    }
  }
  MPI_Bcast(figures.data(), as_count(figures.size(), "the cost table"), MPI_DOUBLE, 0,
            MPI_COMM_WORLD);
  std::vector<quadmc::series_cost> cost(series);
  for (std::size_t s = 0; s < series; ++s) cost[s] = {figures[2 * s], figures[2 * s + 1]};
  return cost;
}

struct assignment {
  std::vector<std::size_t> split;         // cells all ranks run together, in plan order
  std::vector<std::size_t> own;           // this rank's cells, in plan order
  std::vector<cell_placement> placement;  // every cell's, on every rank
};

assignment assign_cells(const quadmc::plan& p, const quadmc::cost_probes& probes,
                        const std::vector<quadmc::series_cost>& series, const world& w,
                        split_policy policy) {
  std::vector<bool> shares(p.cells.size());
  for (std::size_t i = 0; i < p.cells.size(); ++i) shares[i] = cell_shares_chunks(p, i);
  assignment a;
  a.placement = quadmc::assign_cells(quadmc::cell_costs(p, probes, series), shares, w.size, policy);
  for (std::size_t i = 0; i < p.cells.size(); ++i) {
    if (a.placement[i].split) {
      a.split.push_back(i);
    } else if (a.placement[i].rank == w.rank) {
      a.own.push_back(i);
    }
  }
  return a;
}

// Runs the cells all ranks share (in plan order, every rank taking part in each) into `together`,
// recording the budget skips or the first failure in `mine`. Every rank has the same results of
// them, so they stay here and are not sent to rank 0. Whether to skip a split cell is rank
// 0's clock's decision, sent to all ranks: they must all run it or none. A split cell is timed
// once, by its own call: repeating it until a minimum time has passed would make each rank decide
// by its own clock how often to take part in its collectives.
void run_split_cells(quadmc::run_session& session, const std::vector<std::size_t>& split,
                     const world& w, rank_outcome& mine,
                     std::vector<std::pair<std::size_t, quadmc::cell_run> >& together) {
  mpi_chunk_exchange exchange(w);
  for (const std::size_t index : split) {
    const double elapsed = session.elapsed();
    int skip = session.budget_spent(elapsed) ? 1 : 0;
    MPI_Bcast(&skip, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (skip != 0) {
      mine.skipped.emplace_back(index, session.budget_skip(index, elapsed));
      continue;
    }
    try {
      const quadmc::chunk_exchange_scope shared(&exchange);
      together.emplace_back(index, session.run_cell(index, 0.0));
    } catch (const std::exception& e) {
      // Every rank fails here alike: the exchange agreed on the failing chunk, and what a rank
      // computes outside chunks is the same on all of them.
      mine.failed_cell = index;
      mine.failure = e.what();
      return;
    }
  }
}

// Runs this rank's own cells whole, by its own clock's budget.
void run_own_cells(quadmc::run_session& session, const std::vector<std::size_t>& own,
                   rank_outcome& mine) {
  for (const std::size_t index : own) {
    const double elapsed = session.elapsed();
    if (session.budget_spent(elapsed)) {
      mine.skipped.emplace_back(index, session.budget_skip(index, elapsed));
      continue;
    }
    try {
      mine.ran.emplace_back(index, session.run_cell(index, session.timing_min_seconds()));
    } catch (const std::exception& e) {
      mine.failed_cell = index;
      mine.failure = e.what();
      return;
    }
  }
}

// Every rank's outcome, on rank 0 (in rank order; rank 0's own first); empty on the others.
std::vector<rank_outcome> gather_outcomes(rank_outcome mine, const world& w) {
  const std::vector<char> bytes = serialise(mine);
  const int my_count = as_count(bytes.size(), "a rank's results");
  std::vector<int> counts(w.rank == 0 ? w.size : 0);
  MPI_Gather(&my_count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> displacements(counts.size());
  std::size_t total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    displacements[r] = as_count(total, "the gathered results");
    total += static_cast<std::size_t>(counts[r]);
  }
  std::vector<char> gathered(total);
  MPI_Gatherv(bytes.data(), my_count, MPI_BYTE, gathered.data(), counts.data(),
              displacements.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
  std::vector<rank_outcome> all;
  if (w.rank != 0) return all;
  all.push_back(std::move(mine));
  for (unsigned r = 1; r < w.size; ++r) {
    all.push_back(
        deserialise(gathered.data() + displacements[r], static_cast<std::size_t>(counts[r])));
  }
  return all;
}

// Rank 0: the failure of the failing cell with the lowest plan index (empty when none failed),
// else every cell filed into `assembly` in plan order.
std::string file_in_plan_order(const quadmc::plan& p, std::vector<rank_outcome>& all,
                               quadmc::run_assembly& assembly) {
  std::optional<std::size_t> first_failed;
  std::string failure;
  for (std::size_t r = 0; r < all.size(); ++r) {
    const rank_outcome& o = all[r];
    if (o.failed_cell && (!first_failed || *o.failed_cell < *first_failed)) {
      first_failed = o.failed_cell;
      failure = fmt::format("{} (on MPI rank {} of {})", o.failure, r, all.size());
    }
  }
  if (!failure.empty()) return failure;
  std::vector<std::optional<quadmc::cell_run> > by_cell(p.cells.size());
  std::vector<std::optional<quadmc::plan_skip> > skip(p.cells.size());
  for (rank_outcome& o : all) {
    for (auto& [index, run] : o.ran) by_cell[index] = std::move(run);
    // A split cell skipped is in every rank's outcome, with the same cell and rank 0's verdict.
    for (auto& [index, skipped] : o.skipped) {
      if (!skip[index]) skip[index] = std::move(skipped);
    }
  }
  for (std::size_t index = 0; index < p.cells.size(); ++index) {
    if (skip[index]) {
      assembly.skip(std::move(*skip[index]));
    } else if (by_cell[index]) {
      assembly.add(index, std::move(*by_cell[index]));
    }
  }
  return {};
}

}  // namespace

world start(int& argc, char**& argv) {
  if (!launched_by_mpirun()) return {};
  int provided = 0;
  // Only the main thread calls MPI (worker threads compute chunks and never communicate).
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  mpi_started = true;
  int size = 1;
  int rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return {static_cast<unsigned>(size), static_cast<unsigned>(rank)};
}

void finish() noexcept {
  // Every rank reaches the barrier before any leaves: a rank that returns non-zero first would
  // make mpirun end the others while they finish, with a report of a signal, not of the error.
  // Waited for with a sleep between polls, not MPI_Barrier: Open MPI's blocking calls poll without
  // pause, so the ranks done first would take the cores from rank 0 while it times the
  // time-to-error pairs alone (scene/paired_timing.hpp), writes the folder and runs the plots.
  // A millisecond's sleep costs the run at most that at its end.
  if (mpi_started) {
    MPI_Request all_here = MPI_REQUEST_NULL;
    MPI_Ibarrier(MPI_COMM_WORLD, &all_here);
    int done = 0;
    MPI_Test(&all_here, &done, MPI_STATUS_IGNORE);
    while (done == 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      MPI_Test(&all_here, &done, MPI_STATUS_IGNORE);
    }
    MPI_Finalize();
  }
  mpi_started = false;
}

bool agree_to_proceed(const world& w, bool rank0_ok) {
  if (w.size <= 1) return rank0_ok;
  int ok = rank0_ok ? 1 : 0;
  MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return ok != 0;
}

mpi_scheduler::mpi_scheduler(world w, split_policy policy) : world_(w), policy_(policy) {}

void mpi_scheduler::run_cells(quadmc::run_session& session, quadmc::run_assembly& assembly) {
  const quadmc::plan& p = session.source();
  const world& w = world_;
  const quadmc::cost_probes probes = quadmc::choose_cost_probes(p);
  const std::vector<quadmc::series_cost> cost = series_costs(p, probes, session.context(), w);
  const assignment work = assign_cells(p, probes, cost, w, policy_);
  placement_ = work.placement;

  // Rank 0 speaks for the run: it reports the split cells and its own.
  std::size_t cells = work.split.size();
  std::uint64_t evaluations = 0;
  for (const std::size_t i : work.split) {
    evaluations += p.cells[i].evaluations * p.cells[i].repetitions;
  }
  if (w.rank == 0) {
    cells += work.own.size();
    for (const std::size_t i : work.own) {
      evaluations += p.cells[i].evaluations * p.cells[i].repetitions;
    }
  }
  session.count_progress_of(cells, evaluations, w.rank == 0);

  rank_outcome mine;
  std::vector<std::pair<std::size_t, quadmc::cell_run> > shared;
  run_split_cells(session, work.split, w, mine, shared);
  if (!mine.failed_cell) run_own_cells(session, work.own, mine);
  std::vector<rank_outcome> all = gather_outcomes(std::move(mine), w);
  if (w.rank == 0) {
    for (auto& cell : shared) all.front().ran.push_back(std::move(cell));
  }
  const std::string failure = w.rank == 0 ? file_in_plan_order(p, all, assembly) : std::string();
  int failed = failure.empty() ? 0 : 1;
  MPI_Bcast(&failed, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (failed != 0) {
    throw quadmc::run_error(w.rank == 0 ? failure
                                        : std::string("a cell failed (rank 0 says which)"));
  }
}

#endif

}  // namespace quadmc_cli::mpi
