// SPDX-License-Identifier: MIT
// Thread policy of the explicit module's OpenMP loops.
#pragma once

#include "trifem/core/types.hpp"

namespace trifem::explicit_dynamics {

/// Loops over fewer cells or nodes than this run serially: below it a loop costs well under a
/// millisecond and the fork/join (and, on a loaded machine, the spin-waiting of idle threads)
/// costs more than it saves.
inline constexpr Index kMinParallelLoop = 4096;

} // namespace trifem::explicit_dynamics
