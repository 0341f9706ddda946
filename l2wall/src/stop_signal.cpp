#include "l2wall/stop_signal.hpp"

#include <fmt/format.h>

#include <cstring>

#include "l2wall/run_fault.hpp"

namespace l2 {

void check_stop_signal(int shown, const std::string& on_displays) {
  const int signal = stop_signal_received();
  if (!signal) return;
  throw RunFault(fmt::format("stopped by signal {} ({}) at frame {}; {}", signal, strsignal(signal),
                             shown, on_displays));
}

}  // namespace l2
