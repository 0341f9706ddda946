#include "base/stop_signals.hpp"

#include <signal.h>

#include <cstdio>
#include <cstdlib>

namespace l2 {
namespace {

volatile sig_atomic_t g_stop_signal = 0;

extern "C" void on_stop_signal(int signal) {
  g_stop_signal = signal;
}

}  // namespace

void catch_stop_signals() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int stop_signal_received() {
  return g_stop_signal;
}

void end_by_stop_signal() {
  const int signal = g_stop_signal;
  std::fflush(stdout);
  std::fflush(stderr);
  ::signal(signal, SIG_DFL);
  raise(signal);
  std::_Exit(128 + signal);  // raise does not return for SIGINT or SIGTERM; for the compiler
}

}  // namespace l2
