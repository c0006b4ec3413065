// SPDX-License-Identifier: MIT
// A stop request from outside (Ctrl-C): analyses poll it between steps and Newton iterations
// and end cleanly, keeping their results and writing their summary.
#pragma once

#include <functional>

namespace trifem::interrupt {

/// Installs a SIGINT/SIGTERM handler that requests a stop; a second signal ends the process
/// at once (the default action).
void install_handler();

/// True once a stop was requested.
bool requested();

/// Requests a stop (what the signal handler does), or clears the request.
void request(bool stop = true);

/// The signal that requested the stop (0 if none or requested programmatically).
int signal_number();

/// Sets what is done at once when a signal requests a stop (with the signal's number), before
/// the analysis reaches its next poll: run on a watcher thread, not in the signal handler, so
/// it may write files. A process may be killed soon after the signal (mpirun follows its SIGTERM
/// with SIGKILL), so this is where a run marks its summary as interrupted. Setting another
/// action (or none) waits until a running one has returned.
void set_notice(std::function<void(int)> action);

} // namespace trifem::interrupt
