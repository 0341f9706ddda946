#include "l2wall/stop_signal.hpp"

#include <fmt/format.h>
#include <signal.h>

#include <cstring>

#include "l2wall/run_fault.hpp"

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

void check_stop_signal(int shown, const std::string& on_displays) {
  if (!g_stop_signal) return;
  const int signal = g_stop_signal;
  throw RunFault(fmt::format("stopped by signal {} ({}) at frame {}; {}", signal, strsignal(signal),
                             shown, on_displays));
}

}  // namespace l2
