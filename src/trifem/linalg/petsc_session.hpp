// SPDX-License-Identifier: MIT
// PETSc (and through it MPI) is initialised on first use by a PETSc backend, once per process,
// and finalised at exit. A run that never selects a PETSc backend never starts MPI.
#pragma once

#include <petscksp.h>

#include <stdexcept>
#include <string>

namespace trifem::linalg::petsc {

/// A PETSc call that returned an error code, with PETSc's message.
class PetscError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Initialises PETSc once (without its signal handlers, so Ctrl-C keeps trifem's meaning, and
/// with an error handler that returns codes instead of printing tracebacks).
void ensure_initialized();

/// Throws PetscError for a non-zero PETSc error code: "<what>: <PETSc's message>".
void check(int code, const char* what);

/// Inserts `options` ("-key value ...") into PETSc's global options database; PetscError if it
/// cannot be parsed.
void insert_options(const std::string& options);

/// Removes the keys of `options` ("-key value ...") from the database again.
void clear_options(const std::string& options);

/// One solver's `solver.petsc_options` in the global database for the solver's lifetime:
/// inserted on construction (InputError if PETSc cannot read them), removed on destruction.
class ScopedOptions {
public:
  explicit ScopedOptions(std::string options);
  ~ScopedOptions() { clear_options(options_); }
  /// Whether the options name `key` ("-ksp_rtol").
  bool has(const std::string& key) const;
  ScopedOptions(const ScopedOptions&) = delete;
  ScopedOptions& operator=(const ScopedOptions&) = delete;

private:
  std::string options_;
};

/// Sets the relative tolerance of `ksp`'s solves, its other tolerances unchanged.
void set_relative_tolerance(KSP ksp, double tolerance);

/// Sets the iteration limit of `ksp`'s solves, its tolerances unchanged.
void set_max_iterations(KSP ksp, int iterations);

/// InputError naming every option of the database that no PETSc object has read (after a
/// probe solve with `options` by the backend `backend`); the unused ones are removed.
void refuse_unused_options(const std::string& options, const char* backend);

/// The options of the database that no PETSc object has read so far, as "-key value" items
/// separated by ", " ("" if every option was used); they are removed from the database.
std::string take_unused_options();

} // namespace trifem::linalg::petsc
