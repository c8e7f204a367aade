// Ctrl-C (SIGINT) and SIGTERM in the `quadmc` command: instead of dying half-way, which would
// leave a staging folder, a lock file and a running plot process behind, the command kills the
// plot process, removes what this run created, prints one line and exits with 128 + signal
// (130 for SIGINT, 143 for SIGTERM: the shells' convention for "killed by a signal").
//
// Use install() first thing in main, before any thread starts: the signals are blocked in the
// calling thread, and every thread started later inherits the mask, so only the waiting thread
// install() starts ever receives them. Not for SIGKILL or a crash, which no process can catch;
// their leftovers (a hidden staging folder and lock file beside the results) are described in
// results_staging.hpp.
//
// Why a thread: the cleanup uses std::filesystem and fmt, which an asynchronous signal handler
// must not call (only async-signal-safe functions are allowed there, POSIX.1-2017 XSH 2.4.3).
// The waiting thread receives the signal with sigwait(3) and runs the cleanup as ordinary code.
// So that it never runs while the main thread is half-way through a step (writing into the
// staging folder, moving it into place, drawing the progress bar), the main thread holds hold()'s
// mutex during such steps; the waiting thread takes the same mutex and never releases it (it
// ends the process), so once a signal has arrived the main thread stops at its next step.
#pragma once

#include <sys/types.h>

#include <functional>
#include <mutex>
#include <string>

namespace quadmc::interruption {

// Blocks SIGINT and SIGTERM, ignores SIGPIPE (a closed stdout is then a write error the command
// reports, not a silent death half-way through writing results), and starts the waiting thread.
void install();

// The mutex of the steps a signal must not interrupt half-way. Hold it while calling
// set_cleanup or set_child_process as well.
std::unique_lock<std::mutex> hold();

// What to undo on a signal; returns the rest of the message line, e.g. "removed the unfinished
// results; results/x is as it was". An empty function: nothing to undo.
void set_cleanup(std::function<std::string()> cleanup);

// Whether a signal's line is printed. An MPI rank other than 0 is quiet: rank 0 speaks for the
// run, and mpirun ends the other ranks with SIGTERM whenever one rank exits non-zero, which is
// no news to the user (mpi_run.hpp).
void set_quiet(bool quiet);

// The running child process (the plot script), started in a process group of its own: on a
// signal the whole group is killed (SIGKILL: its output is discarded anyway) and reaped before
// the command exits, so no plot process outlives it. 0: none.
void set_child_process(pid_t pid);

}  // namespace quadmc::interruption
