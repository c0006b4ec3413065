// SPDX-License-Identifier: MIT
#include "trifem/linalg/petsc_session.hpp"

#include "trifem/core/error.hpp"

#include <fmt/format.h>
#include <petscsys.h>

#include <cctype>
#include <cstdlib>
#include <mutex>
#include <sstream>
#include <utility>

namespace trifem::linalg::petsc {
namespace {

/// The message of the error being returned (set by the first handler call of an error chain).
thread_local std::string last_message;

PetscErrorCode record_error(MPI_Comm, int, const char*, const char*, PetscErrorCode code,
                            PetscErrorType type, const char* message, void*) {
  if (type == PETSC_ERROR_INITIAL) {
    const char* text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    last_message = message != nullptr && *message != '\0' ? message : (text ? text : "");
  }
  return code;
}

void finalize() {
  PetscBool finalized = PETSC_FALSE;
  PetscFinalized(&finalized);
  if (!finalized)
    PetscFinalize();
}

} // namespace

void ensure_initialized() {
  static std::once_flag once;
  std::call_once(once, [] {
    PetscBool already = PETSC_FALSE;
    PetscInitialized(&already);
    if (already)
      return;
    // options set before PetscInitialize are honoured by it
    PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr);
    check(PetscInitializeNoArguments(), "PETSc could not be initialised");
    PetscPushErrorHandler(record_error, nullptr);
    std::atexit(finalize);
  });
}

void check(int code, const char* what) {
  if (code == 0)
    return;
  std::string message = last_message;
  last_message.clear();
  if (message.empty()) {
    const char* text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    message = text ? text : fmt::format("PETSc error {}", code);
  }
  throw PetscError(fmt::format("{}: {}", what, message));
}

void insert_options(const std::string& options) {
  ensure_initialized();
  check(PetscOptionsInsertString(nullptr, options.c_str()), "the PETSc options could not be read");
}

void clear_options(const std::string& options) {
  std::istringstream words(options);
  for (std::string word; words >> word;) {
    const bool key =
        word.size() > 1 && word[0] == '-' && std::isalpha(static_cast<unsigned char>(word[1]));
    if (key)
      PetscOptionsClearValue(nullptr, word.c_str());
  }
}

ScopedOptions::ScopedOptions(std::string options) : options_(std::move(options)) {
  ensure_initialized();
  if (options_.empty())
    return;
  try {
    insert_options(options_);
  } catch (const PetscError& e) {
    throw InputError(fmt::format("solver.petsc_options = '{}': {}", options_, e.what()));
  }
}

void set_relative_tolerance(KSP ksp, double tolerance) {
  PetscReal relative = 0.0, absolute = 0.0, divergence = 0.0;
  PetscInt iterations = 0;
  check(KSPGetTolerances(ksp, &relative, &absolute, &divergence, &iterations),
        "PETSc KSP tolerances");
  check(KSPSetTolerances(ksp, tolerance, absolute, divergence, iterations), "PETSc KSP tolerances");
}

void set_max_iterations(KSP ksp, int iterations) {
  PetscReal relative = 0.0, absolute = 0.0, divergence = 0.0;
  PetscInt old = 0;
  check(KSPGetTolerances(ksp, &relative, &absolute, &divergence, &old), "PETSc KSP tolerances");
  check(KSPSetTolerances(ksp, relative, absolute, divergence, iterations), "PETSc KSP tolerances");
}

bool ScopedOptions::has(const std::string& key) const {
  std::istringstream words(options_);
  for (std::string word; words >> word;)
    if (word == key)
      return true;
  return false;
}

void refuse_unused_options(const std::string& options, const char* backend) {
  const std::string unused = take_unused_options();
  if (!unused.empty())
    throw InputError(fmt::format("solver.petsc_options = '{}': PETSc does not know or use {} "
                                 "(with the {} backend)",
                                 options, unused, backend));
}

std::string take_unused_options() {
  PetscInt count = 0;
  char** names = nullptr;
  char** values = nullptr;
  check(PetscOptionsLeftGet(nullptr, &count, &names, &values), "PETSc options");
  std::string list;
  for (PetscInt i = 0; i < count; ++i) {
    const std::string name = names[i];
    if (name == "no_signal_handler")
      continue;
    list += fmt::format("{}-{}{}{}", list.empty() ? "" : ", ", name, values[i] ? " " : "",
                        values[i] ? values[i] : "");
    PetscOptionsClearValue(nullptr, ("-" + name).c_str());
  }
  PetscOptionsLeftRestore(nullptr, &count, &names, &values);
  return list;
}

} // namespace trifem::linalg::petsc
