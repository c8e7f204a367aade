// `mpirun -np K quadmc run SCENE.toml`: the scene runner on K processes, bitwise equal to one.
//
// Every rank parses the scene and makes the plan itself (both are deterministic). Cells then go
// to ranks by planned cost as the library's scheduler assigns them (scene/schedule.hpp: LPT, the
// makespan at most the total cost / K plus the largest cell); a cell costing more than a
// quarter of a rank's fair share is *split* when its method shares chunks: all ranks run it
// together, each computing its share of every parallel_reduce window and exchanging chunk
// results, so every rank folds all chunks in chunk order (core/chunk_exchange.hpp), or, for a
// naive sum, adding its block's terms and placing the result exactly (core/split_naive_sum.hpp).
// A costly cell whose method does not share chunks (genz_malik, vegas, smolyak, romberg)
// would cost every rank its whole time if split, so it goes to one rank like the others. The cost
// of a cell is repetitions × (fixed + evaluations × seconds per evaluation) of its (integrand,
// method) series: rank 0 times one repetition of the series' smallest cell and of its largest
// cell of at most 2^16 evaluations and sends the figures to every rank, so all ranks make the
// same assignment. Repetition r of a cell is a pure function of
// (plan, cell, r, seed) (docs/design.md#hot-path-contract), so where it ran changes nothing: rank 0
// gathers every cell's repetitions and files them in plan order (scene/run.hpp, run_assembly), and
// every CSV column but the timing is what one process writes.
//
// After the cells: only rank 0 goes on (run_scene's analysis and paired timing, the results
// folder); the others wait for it in finish(), which sleeps between polls, so that rank 0 times
// the time-to-error pairs on cores nothing else is using (scene/cell_scheduler.hpp).
//
// Faults: a rank whose cell fails (bad input found late, a non-finite value) stops running
// cells, and the failure reaches rank 0 with the gather; rank 0 then raises the error of the
// failing cell with the lowest plan index, writes nothing, and every rank exits 1. A killed rank
// makes mpirun end the others (rank 0's interruption handler removes its staging folder).
//
// Built only with Open MPI (QUADMC_MPI, bench/CMakeLists.txt); without it, a command started by
// mpirun says that it needs the MPI build.
#pragma once

#include "quadmc/scene/cell_scheduler.hpp"
#include "quadmc/scene/plan.hpp"
#include "quadmc/scene/run.hpp"
#include "quadmc/scene/schedule.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc_cli::mpi {

// This process's place in the run: rank 0 of 1 when not started by mpirun.
struct world {
  unsigned size = 1;
  unsigned rank = 0;
};

// Which cells all ranks run together, and where a cell ran (scene/schedule.hpp). `--split-cells
// all` splits the cells whose method does not share chunks too: each rank then computes such a
// cell whole, exact and not faster, so that tests see a split cell equal the unsplit one whatever
// its kernel.
using quadmc::cell_placement;
using quadmc::split_policy;

// MPI_Init when built with MPI and started by mpirun. Without the MPI build, a process started
// by mpirun throws (one line: mpirun needs the MPI build). Call once, first thing in main.
world start(int& argc, char**& argv);
// A barrier of every rank, polled with a millisecond's sleep, then MPI_Finalize (when started);
// safe to call when start() did nothing.
void finish() noexcept;
// Whether this binary was built with MPI.
bool built_with_mpi() noexcept;

// Rank 0's verdict on whether the run may go on (its results folder checks passed), sent to
// every rank; returns it. Ranks other than 0 pass `true`.
bool agree_to_proceed(const world& w, bool rank0_ok);

// The scheduler of a run on every rank of `w` (scene/cell_scheduler.hpp): run_plan(plan, options,
// scheduler) is then collective. On rank 0 it files every cell (the whole run); the other ranks
// file nothing and their run_plan returns an empty run_output. A failed cell anywhere throws
// run_error on every rank (its message on rank 0). options.on_progress is called on rank 0 for
// the cells it runs itself and the split cells. Only for a run of more than one rank: a run of
// one process uses quadmc::local_scheduler and never reaches this file.
class mpi_scheduler final : public quadmc::cell_scheduler {
 public:
  mpi_scheduler(world w, split_policy policy);
  void run_cells(quadmc::run_session& session, quadmc::run_assembly& assembly) override;
  // Where each plan cell ran (one entry per cell, on every rank), once run_cells has returned.
  const std::vector<cell_placement>& placement() const noexcept { return placement_; }

 private:
  world world_;
  split_policy policy_;
  std::vector<cell_placement> placement_;
};

}  // namespace quadmc_cli::mpi
