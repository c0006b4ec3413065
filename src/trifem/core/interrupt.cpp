// SPDX-License-Identifier: MIT
#include "trifem/core/interrupt.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <mutex>
#include <thread>

namespace trifem::interrupt {
namespace {

std::atomic<bool> stop_requested{false};
volatile std::sig_atomic_t stop_signal = 0;

/// Self-pipe: the handler writes the signal number, the watcher thread reads it and runs the
/// notice outside the signal context (where files may be written).
int notice_pipe[2] = {-1, -1};
std::mutex notice_mutex;
std::function<void(int)> notice;

extern "C" void on_signal(int sig) {
  stop_signal = sig;
  stop_requested.store(true);
  std::signal(sig, SIG_DFL); // a second Ctrl-C ends the process at once
  if (notice_pipe[1] >= 0) {
    const unsigned char byte = static_cast<unsigned char>(sig);
    const int saved = errno;
    [[maybe_unused]] const auto written = ::write(notice_pipe[1], &byte, 1);
    errno = saved;
  }
}

void watch() {
  for (;;) {
    unsigned char sig = 0;
    const auto got = ::read(notice_pipe[0], &sig, 1);
    if (got < 0 && errno == EINTR)
      continue;
    if (got <= 0)
      return;
    const std::lock_guard lock(notice_mutex);
    if (notice)
      notice(sig);
  }
}

void start_watcher() {
  if (::pipe(notice_pipe) != 0) {
    notice_pipe[0] = notice_pipe[1] = -1; // no notice, the stop request still works
    return;
  }
  ::fcntl(notice_pipe[0], F_SETFD, FD_CLOEXEC);
  ::fcntl(notice_pipe[1], F_SETFD, FD_CLOEXEC);
  ::fcntl(notice_pipe[1], F_SETFL, O_NONBLOCK); // the handler never blocks
  std::thread(watch).detach();
}

} // namespace

void install_handler() {
  static std::once_flag watcher;
  std::call_once(watcher, start_watcher);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

bool requested() {
  return stop_requested.load(std::memory_order_relaxed);
}

void request(bool stop) {
  stop_requested.store(stop);
  if (!stop)
    stop_signal = 0;
}

int signal_number() {
  return stop_signal;
}

void set_notice(std::function<void(int)> action) {
  const std::lock_guard lock(notice_mutex);
  notice = std::move(action);
}

} // namespace trifem::interrupt
