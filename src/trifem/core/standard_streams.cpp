// SPDX-License-Identifier: MIT
#include "trifem/core/standard_streams.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <csignal>

namespace trifem {

void guard_standard_streams() {
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1)
      continue; // open
    // open() takes the lowest free descriptor, which is `fd` (the lower ones are open by now)
    const int opened = ::open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
    if (opened >= 0 && opened != fd) {
      ::dup2(opened, fd);
      ::close(opened);
    }
  }
  std::signal(SIGPIPE, SIG_IGN);
}

} // namespace trifem
