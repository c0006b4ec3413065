// SPDX-License-Identifier: MIT
// Error types and the TRIFEM_CHECK / TRIFEM_ASSERT macros.
#pragma once

#include <fmt/format.h>
#include <stdexcept>
#include <string>

namespace trifem {

/// Bad user input (case file, mesh file, parameters). The message names the file, key or line.
class InputError : public std::runtime_error {
public:
  explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

/// A result file cannot be created or written (permissions, disk full). Before a run starts it
/// is a setup error like bad input; during a run it ends the run as a failure, keeping what
/// was written.
class OutputError : public InputError {
public:
  explicit OutputError(const std::string& what) : InputError(what) {}
};

/// Violated internal invariant: a bug in trifem, not in the input.
class LogicError : public std::logic_error {
public:
  explicit LogicError(const std::string& what) : std::logic_error(what) {}
};

namespace detail {
/// Throws LogicError("internal error: <message> (<file>:<line>)").
[[noreturn]] void throw_logic_error(const std::string& message, const char* file, int line);
} // namespace detail

} // namespace trifem

/// Always-on check of user input: throws InputError with the formatted message.
#define TRIFEM_CHECK(cond, ...)                                                                    \
  do {                                                                                             \
    if (!(cond)) [[unlikely]]                                                                      \
      throw ::trifem::InputError(::fmt::format(__VA_ARGS__));                                      \
  } while (false)

/// Always-on check of a result file operation: throws OutputError with the formatted message.
#define TRIFEM_CHECK_OUTPUT(cond, ...)                                                             \
  do {                                                                                             \
    if (!(cond)) [[unlikely]]                                                                      \
      throw ::trifem::OutputError(::fmt::format(__VA_ARGS__));                                     \
  } while (false)

/// Always-on internal invariant check: throws LogicError with file and line.
#define TRIFEM_VERIFY(cond, ...)                                                                   \
  do {                                                                                             \
    if (!(cond)) [[unlikely]]                                                                      \
      ::trifem::detail::throw_logic_error(::fmt::format(__VA_ARGS__), __FILE__, __LINE__);         \
  } while (false)

#ifdef NDEBUG
#define TRIFEM_ASSERT(cond, ...)                                                                   \
  do {                                                                                             \
  } while (false)
#else
/// Debug-only internal invariant check.
#define TRIFEM_ASSERT(cond, ...) TRIFEM_VERIFY(cond, __VA_ARGS__)
#endif
