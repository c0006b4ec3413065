// SPDX-License-Identifier: MIT
#include "trifem/parallel/communicator.hpp"

#include <mpi.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string_view>
#include <thread>

namespace trifem::parallel {
namespace {

/// The launcher's process count, or 1.
int launched_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(name))
      return std::max(1, std::atoi(value));
  return 1;
}

/// A communicator of its own for the failure agreement, so that its barrier never matches a
/// collective of the analysis that other processes may be in.
MPI_Comm failure_comm = MPI_COMM_NULL;

void finalize_mpi() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized)
    return;
  if (failure_comm != MPI_COMM_NULL)
    MPI_Comm_free(&failure_comm);
  MPI_Finalize();
}

bool mpi_running() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  return initialized && !finalized;
}

/// `value` of every process combined by the logical `op` (MPI_LAND, MPI_LOR), on every process.
bool reduced_flag(bool value, MPI_Op op) {
  int mine = value ? 1 : 0, combined = 0;
  MPI_Allreduce(&mine, &combined, 1, MPI_INT, op, MPI_COMM_WORLD);
  return combined != 0;
}

} // namespace

bool launched_in_parallel() {
  return launched_size() > 1;
}

void initialize(int& argc, char**& argv) {
  if (!launched_in_parallel() || mpi_running())
    return;
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_dup(MPI_COMM_WORLD, &failure_comm);
  // registered before PETSc's own finalisation, so it runs after it
  std::atexit(finalize_mpi);
}

bool active() {
  return size() > 1;
}

int rank() {
  if (!mpi_running())
    return 0;
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int size() {
  if (!mpi_running())
    return 1;
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

void sum(Vector& values) {
  if (!active())
    return;
  const int count = static_cast<int>(values.size());
  if (is_root()) // in place: no copy of the (whole-model) vector per call
    MPI_Reduce(MPI_IN_PLACE, values.data(), count, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
  else
    MPI_Reduce(values.data(), nullptr, count, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
  MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

Real sum(Real value) {
  Vector v(1);
  v[0] = value;
  sum(v);
  return v[0];
}

std::vector<Real> gather(Real value) {
  std::vector<Real> values(size(), value);
  if (active())
    MPI_Allgather(&value, 1, MPI_DOUBLE, values.data(), 1, MPI_DOUBLE, MPI_COMM_WORLD);
  return values;
}

int first_rank_differing(std::uint64_t value) {
  if (!active())
    return -1;
  std::vector<std::uint64_t> values(static_cast<std::size_t>(size()));
  MPI_Allgather(&value, 1, MPI_UINT64_T, values.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD);
  for (int r = 1; r < size(); ++r)
    if (values[static_cast<std::size_t>(r)] != values[0])
      return r;
  return -1;
}

bool all(bool value) {
  return active() ? reduced_flag(value, MPI_LAND) : value;
}

bool any(bool value) {
  return active() ? reduced_flag(value, MPI_LOR) : value;
}

std::string first_message(const std::string& message) {
  if (!active())
    return message;
  int mine = message.empty() ? size() : rank(), first = size();
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (first == size())
    return {};
  std::string text = rank() == first ? message : std::string();
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, first, MPI_COMM_WORLD);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), length, MPI_CHAR, first, MPI_COMM_WORLD);
  return text;
}

void broadcast(std::vector<int>& values) {
  if (!active())
    return;
  MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_INT, 0, MPI_COMM_WORLD);
}

bool agree_on_failure(const std::string& message, int exit_code, double wait_seconds) {
  if (!active())
    return true;
  MPI_Request request = MPI_REQUEST_NULL;
  MPI_Ibarrier(failure_comm, &request);
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_seconds);
  int done = 0;
  while (!done && std::chrono::steady_clock::now() < deadline) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (!done)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (done)
    return is_root();
  const std::string_view prefix = "error: "; // the line as printed on one process
  const std::string_view text =
      message.starts_with(prefix) ? std::string_view(message).substr(prefix.size()) : message;
  std::cerr << "error (process " << rank() << " of " << size() << "): " << text
            << " (the other processes are stopped)\n"
            << std::flush;
  MPI_Abort(MPI_COMM_WORLD, exit_code);
  return false;
}

} // namespace trifem::parallel
