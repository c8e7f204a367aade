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

split_policy parse_split_policy(std::string_view text) {
  if (text == "auto") return split_policy::automatic;
  if (text == "all") return split_policy::all;
  if (text == "none") return split_policy::none;
  throw std::invalid_argument(
      fmt::format("invalid --split-cells = '{}': expected auto, all or none", text));
}

std::string cells_csv(const quadmc::plan& p, const std::vector<cell_placement>& placement) {
  std::string out =
      "integrand,instance,s,method,N,tolerance,evaluations,repetitions,shares_chunks,placement\n";
  for (std::size_t i = 0; i < p.cells.size(); ++i) {
    const quadmc::plan_cell& cell = p.cells[i];
    const bool to_tolerance = !std::isnan(cell.tolerance);
    const cell_placement where = i < placement.size() ? placement[i] : cell_placement{};
    // Scene names are identifiers (scene/parse.hpp), so no field needs quoting.
    out += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", p.source.integrands[cell.integrand].name,
                       cell.instance, cell.dimension, p.source.methods[cell.method].label,
                       to_tolerance ? std::string() : std::to_string(cell.nominal_N),
                       to_tolerance ? fmt::format("{}", cell.tolerance) : std::string(),
                       cell.evaluations, cell.repetitions, cell_shares_chunks(p, i) ? 1 : 0,
                       where.split ? std::string("split") : fmt::format("rank {}", where.rank));
  }
  return out;
}

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

quadmc::run_output run_plan_distributed(const quadmc::plan& p, const quadmc::run_options& options,
                                        const world&, split_policy,
                                        std::vector<cell_placement>* placement) {
  if (placement != nullptr) placement->assign(p.cells.size(), cell_placement{});
  return quadmc::run_plan(p, options);
}

#else

namespace {

using clock = std::chrono::steady_clock;

double seconds_since(clock::time_point start) {
  return std::chrono::duration<double>(clock::now() - start).count();
}

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
  std::vector<std::pair<std::size_t, std::string> > skipped;
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
  for (const auto& [index, reason] : o.skipped) {
    w.u64(index);
    w.u64(skipped);
    w.text(reason);
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
      o.skipped.emplace_back(index, r.text());
    }
  }
  if (!r.done()) throw std::runtime_error("a rank's gathered results have trailing bytes");
  return o;
}

// Each series' cost (scene/schedule.hpp): rank 0 times the probes the scheduler chooses and
// sends the figures to every rank, so that all ranks cost cells alike and make one assignment.
// A series whose probe fails here gets the nominal cost: the run proper reports its error.
std::vector<quadmc::series_cost> series_costs(const quadmc::plan& p,
                                              const quadmc::cost_probes& probes,
                                              const quadmc::run_context& context, const world& w) {
  const std::size_t series = probes.smallest.size();
  std::vector<double> figures(2 * series);
  if (w.rank == 0) {
    // The fastest of three timings of a cell of at most probe_evaluations: timed once, a cell of
    // microseconds is at the mercy of one preemption (the other ranks spin in MPI_Bcast
    // meanwhile, and an oversubscribed machine hands rank 0's core to them), which can price a
    // series hundreds of times too high. A larger cell (a series that starts above the probe
    // size) is timed once.
    const auto seconds_of = [&](std::size_t i) {
      const int timings = p.cells[i].evaluations <= quadmc::probe_evaluations ? 3 : 1;
      double best = std::numeric_limits<double>::infinity();
      for (int k = 0; k < timings; ++k) {
        const auto t0 = clock::now();
        (void)quadmc::run_cell_repetitions(p, i, 0, 1, context, 0.0);
        best = std::min(best, seconds_since(t0));
      }
      return best;
    };
    for (std::size_t s = 0; s < series; ++s) {
      quadmc::series_cost c;
      try {
        const std::size_t small = probes.smallest[s];
        const std::size_t probe = probes.probe[s];
        const double t0 = seconds_of(small);
        const double t1 = probe == small ? t0 : seconds_of(probe);
        c = quadmc::fit_series_cost(p.cells[small].evaluations, t0, p.cells[probe].evaluations, t1);
      } catch (const std::exception&) {
        c = quadmc::series_cost{};
      }
      figures[2 * s] = c.fixed;
      figures[2 * s + 1] = c.per_evaluation;
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

std::string max_seconds_reason(double max_seconds, double elapsed) {
  return fmt::format("budget.max_seconds = {} s spent ({:.1f} s elapsed)", max_seconds, elapsed);
}

std::string skip_what(const quadmc::plan& p, std::size_t index) {
  const quadmc::plan_cell& cell = p.cells[index];
  return fmt::format("{} × {}, N = {}", p.source.methods[cell.method].label,
                     p.source.integrands[cell.integrand].name, cell.nominal_N);
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
  if (mpi_started) {
    MPI_Barrier(MPI_COMM_WORLD);
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

quadmc::run_output run_plan_distributed(const quadmc::plan& p, const quadmc::run_options& options,
                                        const world& w, split_policy policy,
                                        std::vector<cell_placement>* placement) {
  if (placement != nullptr) placement->assign(p.cells.size(), cell_placement{});
  if (w.size <= 1) return quadmc::run_plan(p, options);
  const auto run_start = clock::now();
  const unsigned threads_allowed =
      quadmc::resolve_threads(options.threads.value_or(p.source.threads));
  const double timing_min_seconds = quadmc::resolved_timing_min_seconds(p, options);
  const quadmc::run_context context{p.source.seed, threads_allowed};
  quadmc::parallel_reduce_peak_threads() = 0;

  const quadmc::cost_probes probes = quadmc::choose_cost_probes(p);
  const std::vector<quadmc::series_cost> cost = series_costs(p, probes, context, w);
  const assignment work = assign_cells(p, probes, cost, w, policy);
  if (placement != nullptr) *placement = work.placement;

  quadmc::run_progress progress;
  progress.cells_total = work.split.size() + (w.rank == 0 ? work.own.size() : 0);
  for (const std::size_t i : work.split) {
    progress.evaluations_total += p.cells[i].evaluations * p.cells[i].repetitions;
  }
  if (w.rank == 0) {
    for (const std::size_t i : work.own) {
      progress.evaluations_total += p.cells[i].evaluations * p.cells[i].repetitions;
    }
  }
  const bool report = w.rank == 0 && static_cast<bool>(options.on_progress);
  // A split cell is timed once, by its own call: repeating it until a minimum time has passed
  // would make each rank decide by its own clock how often to take part in its collectives.
  auto run_one = [&](std::size_t index, double min_seconds) {
    std::uint64_t done = 0;
    const std::uint64_t reps = p.cells[index].repetitions;
    auto on_done = [&](const quadmc::repetition_result& result) {
      progress.evaluations_done += result.evaluations;
      if (report && ++done < reps) options.on_progress(progress);
    };
    auto results = quadmc::run_cell_repetitions(p, index, 0, reps, context, min_seconds, on_done);
    ++progress.cells_done;
    if (report) options.on_progress(progress);
    return results;
  };

  const std::optional<double> max_seconds = p.source.budget.max_seconds;
  rank_outcome mine;
  std::vector<std::optional<quadmc::cell_run> > split_results(p.cells.size());
  {
    mpi_chunk_exchange exchange(w);
    for (const std::size_t index : work.split) {
      // Whether to skip a split cell is rank 0's clock's decision, sent to all ranks: they must
      // all run it or none.
      const double elapsed = seconds_since(run_start);
      int skip = max_seconds && elapsed > *max_seconds ? 1 : 0;
      MPI_Bcast(&skip, 1, MPI_INT, 0, MPI_COMM_WORLD);
      if (skip != 0) {
        mine.skipped.emplace_back(index, max_seconds_reason(max_seconds.value_or(0.0), elapsed));
        continue;
      }
      try {
        const quadmc::chunk_exchange_scope shared(&exchange);
        split_results[index] = run_one(index, 0.0);
      } catch (const std::exception& e) {
        // Every rank fails here alike: the exchange agreed on the failing chunk, and what a
        // rank computes outside chunks is the same on all of them.
        mine.failed_cell = index;
        mine.failure = e.what();
        break;
      }
    }
  }
  if (!mine.failed_cell) {
    for (const std::size_t index : work.own) {
      const double elapsed = seconds_since(run_start);
      if (max_seconds && elapsed > *max_seconds) {
        mine.skipped.emplace_back(index, max_seconds_reason(*max_seconds, elapsed));
        continue;
      }
      try {
        mine.ran.emplace_back(index, run_one(index, timing_min_seconds));
      } catch (const std::exception& e) {
        mine.failed_cell = index;
        mine.failure = e.what();
        break;
      }
    }
  }

  // Gather every rank's outcome on rank 0.
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

  // Rank 0 files the cells in plan order, or finds the failure; all ranks learn the outcome.
  std::string failure;
  quadmc::run_output out;
  if (w.rank == 0) {
    std::vector<std::optional<quadmc::cell_run> > by_cell(p.cells.size());
    std::vector<std::optional<std::string> > skip_reason(p.cells.size());
    std::optional<std::size_t> first_failed;
    for (unsigned r = 0; r < w.size; ++r) {
      rank_outcome o = r == 0 ? mine
                              : deserialise(gathered.data() + displacements[r],
                                            static_cast<std::size_t>(counts[r]));
      if (o.failed_cell && (!first_failed || *o.failed_cell < *first_failed)) {
        first_failed = o.failed_cell;
        failure = fmt::format("{} (on MPI rank {} of {})", o.failure, r, w.size);
      }
      for (auto& [index, run] : o.ran) by_cell[index] = std::move(run);
      for (auto& [index, reason] : o.skipped) skip_reason[index] = std::move(reason);
    }
    for (const std::size_t index : work.split) {
      if (split_results[index]) by_cell[index] = std::move(split_results[index]);
    }
    if (failure.empty()) {
      quadmc::run_assembly assembly(p);
      for (std::size_t index = 0; index < p.cells.size(); ++index) {
        if (skip_reason[index]) {
          assembly.skip(quadmc::plan_skip{skip_what(p, index), *skip_reason[index]});
        } else if (by_cell[index]) {
          assembly.add(index, std::move(*by_cell[index]));
        }
      }
      out = std::move(assembly).finish();
      out.threads_allowed = threads_allowed;
      out.threads = std::max(1u, quadmc::parallel_reduce_peak_threads());
    }
  }
  int failed = failure.empty() ? 0 : 1;
  MPI_Bcast(&failed, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (failed != 0) {
    throw quadmc::run_error(w.rank == 0 ? failure
                                        : std::string("a cell failed (rank 0 says which)"));
  }
  out.seconds = seconds_since(run_start);
  return out;
}

#endif

}  // namespace quadmc_cli::mpi
