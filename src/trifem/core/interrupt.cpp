// SPDX-License-Identifier: MIT
#include "trifem/core/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace trifem::interrupt {
namespace {

std::atomic<bool> stop_requested{false};
volatile std::sig_atomic_t stop_signal = 0;

extern "C" void on_signal(int sig) {
  stop_signal = sig;
  stop_requested.store(true);
  std::signal(sig, SIG_DFL); // a second Ctrl-C ends the process at once
}

} // namespace

void install_handler() {
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

} // namespace trifem::interrupt
