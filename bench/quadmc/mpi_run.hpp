// `mpirun -np K quadmc run SCENE.toml`: the scene runner on K processes, bitwise equal to one.
//
// Every rank parses the scene and makes the plan itself (both are deterministic). Cells then go
// to ranks by planned cost, largest first, each to the least-loaded rank (the LPT rule: the
// makespan is at most the total cost / K plus the largest cell); a cell costing more than a
// quarter of a rank's fair share is *split*: all ranks run it together, each computing its share
// of every parallel_reduce window and exchanging chunk results, so every rank folds all chunks in
// chunk order (core/chunk_exchange.hpp). The cost of a cell is its evaluations × repetitions ×
// the method's measured seconds per evaluation on that integrand (rank 0 times one repetition of
// each series' smallest cell and sends the figures to every rank, so all ranks make the same
// assignment). Repetition r of a cell is a pure function of (plan, cell, r, seed)
// (docs/design.md#hot-path-contract), so where it ran changes nothing: rank 0 gathers every
// cell's repetitions and files them in plan order (scene/run.hpp, run_assembly), and every CSV
// column but the timing is what one process writes.
//
// Faults: a rank whose cell fails (bad input found late, a non-finite value) stops running
// cells, and the failure reaches rank 0 with the gather; rank 0 then raises the error of the
// failing cell with the lowest plan index, writes nothing, and every rank exits 1. A killed rank
// makes mpirun end the others (rank 0's interruption handler removes its staging folder).
//
// Built only with Open MPI (QUADMC_MPI, bench/CMakeLists.txt); without it, a command started by
// mpirun says that it needs the MPI build.
#pragma once

#include "quadmc/scene/plan.hpp"
#include "quadmc/scene/run.hpp"

#include <string_view>

namespace quadmc_cli::mpi {

// This process's place in the run: rank 0 of 1 when not started by mpirun.
struct world {
  unsigned size = 1;
  unsigned rank = 0;
};

// Which cells all ranks run together: `automatic` splits the cells above the threshold above;
// `all` and `none` are for tests and measurements (a split cell must equal the unsplit one).
enum class split_policy { automatic, all, none };
split_policy parse_split_policy(std::string_view text);

// MPI_Init when built with MPI and started by mpirun. Without the MPI build, a process started
// by mpirun throws (one line: mpirun needs the MPI build). Call once, first thing in main.
world start(int& argc, char**& argv);
// MPI_Finalize (when started); safe to call when start() did nothing.
void finish() noexcept;
// Whether this binary was built with MPI.
bool built_with_mpi() noexcept;

// Rank 0's verdict on whether the run may go on (its results folder checks passed), sent to
// every rank; returns it. Ranks other than 0 pass `true`.
bool agree_to_proceed(const world& w, bool rank0_ok);

// Runs the plan on every rank of `w` (collective). Rank 0 returns the whole run (series in plan
// order); other ranks return an empty run_output. A failed cell anywhere throws run_error on
// every rank (its message on rank 0). options.on_progress is called on rank 0 for the cells it
// runs itself and the split cells.
quadmc::run_output run_plan_distributed(const quadmc::plan& p, const quadmc::run_options& options,
                                        const world& w, split_policy policy);

}  // namespace quadmc_cli::mpi
