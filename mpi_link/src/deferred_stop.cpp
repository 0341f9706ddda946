#include "deferred_stop.hpp"

#include <signal.h>

#include <cstdio>
#include <cstdlib>

namespace l2 {
namespace {

volatile sig_atomic_t g_deferred = 0;

extern "C" void on_deferred_stop(int signal) {
  g_deferred = signal;
}

}  // namespace

void defer_stop_signals() {
  struct sigaction action {};
  action.sa_handler = on_deferred_stop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int deferred_stop_signal() {
  return g_deferred;
}

void end_by_deferred_signal() {
  const int signal = g_deferred;
  std::fflush(stderr);
  ::signal(signal, SIG_DFL);
  raise(signal);
  std::_Exit(128 + signal);  // raise does not return for SIGINT or SIGTERM; for the compiler
}

}  // namespace l2
