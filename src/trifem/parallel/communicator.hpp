// SPDX-License-Identifier: MIT
// The processes of a run started by mpirun: who this process is, and the few collective
// operations the analysis needs (sums that give the same bits on every process, agreement on a
// yes/no, agreement on a failure). Without mpirun, or with one process, every operation is the
// identity and MPI is not initialised by this module.
#pragma once

#include "trifem/core/error.hpp"
#include "trifem/core/types.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace trifem::parallel {

/// True if this process was started by mpirun (or another MPI launcher) with more than one
/// process (read from the launcher's environment: OMPI_COMM_WORLD_SIZE or PMI_SIZE).
bool launched_in_parallel();

/// Initialises MPI when launched_in_parallel() (threads funnelled: only the main thread calls
/// MPI) and finalises it at exit. Call first in main(); a no-op otherwise.
void initialize(int& argc, char**& argv);

/// True if MPI runs with more than one process: the model is assembled and solved in parts.
bool active();
/// This process's rank (0 without MPI) and the number of processes (1 without MPI).
int rank();
int size();
/// True on the process that writes files and the log (rank 0).
inline bool is_root() {
  return rank() == 0;
}

/// Replaces `values` on every process by the sum over all processes, added in rank order on
/// rank 0 and broadcast, so every process holds the same bits.
void sum(Vector& values);
/// The same for a single number.
Real sum(Real value);
/// The `value` of every process, by rank, on every process.
std::vector<Real> gather(Real value);
/// True if `value` is true on every process.
bool all(bool value);
/// True if `value` is true on some process.
bool any(bool value);
/// The non-empty `message` of the lowest rank that has one, on every process ("" if none).
std::string first_message(const std::string& message);
/// The lowest rank whose `value` differs from rank 0's, on every process (-1 if all agree).
int first_rank_differing(std::uint64_t value);
/// Broadcasts `values` (of equal size everywhere) from rank 0.
void broadcast(std::vector<int>& values);

/// Runs `write` (which writes files of the run) on this process. If it throws OutputError on
/// some process, every process throws OutputError with the message of the lowest such rank, so
/// that all take the same path afterwards (the run goes on, or stops, on every process).
template <class F>
void agree_on_output(F&& write);

/// Called by a process that failed with `message`. If every process fails within
/// `wait_seconds` (an error in the input, read by all), returns true on rank 0 and false
/// elsewhere: rank 0 alone reports it, and all end normally. If some process does not fail
/// (the error is this process's own), prints "error (process k of N): message" (`message`
/// without its leading "error: ") and aborts every process with `exit_code`, so none is left
/// waiting.
bool agree_on_failure(const std::string& message, int exit_code, double wait_seconds = 5.0);

template <class F>
void agree_on_output(F&& write) {
  std::string failure;
  try {
    write();
  } catch (const OutputError& e) {
    if (!active())
      throw;
    failure = e.what();
  }
  if (active())
    failure = first_message(failure);
  if (!failure.empty())
    throw OutputError(failure);
}

} // namespace trifem::parallel
