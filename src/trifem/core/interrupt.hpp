// SPDX-License-Identifier: MIT
// A stop request from outside (Ctrl-C): analyses poll it between steps and Newton iterations
// and end cleanly, keeping their results and writing their summary.
#pragma once

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

} // namespace trifem::interrupt
