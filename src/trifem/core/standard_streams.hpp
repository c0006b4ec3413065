// SPDX-License-Identifier: MIT
// The standard streams a process may be started with: closed (cron, daemons) or a pipe whose
// reader goes away (`trifem run ... | head`, a dead tee or logger).
#pragma once

namespace trifem {

/// Called first in main. Reopens closed standard descriptors 0, 1 and 2 on /dev/null, so that
/// no result file is opened as descriptor 1 or 2 and receives the console log; and ignores
/// SIGPIPE, so that a vanished reader of the console makes writes to it fail instead of
/// killing the process: the run goes on (its log is kept in run.log) and ends with its summary.
void guard_standard_streams();

} // namespace trifem
