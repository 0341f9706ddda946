// The next message a pipeserver sent the run over a control channel (balance/control_channel.hpp),
// taken without waiting: the one receive-and-decode that LiveBalance (TIMES) and LiveWindows
// (WANT) share, so both treat a gone peer and a garbled line alike.
#pragma once

#include <fmt/format.h>

#include <chrono>
#include <optional>
#include <string>

#include "balance/control_channel.hpp"
#include "balance/control_messages.hpp"
#include "l2wall/run_fault.hpp"

namespace l2 {

// nullopt when no line waits, or when the pipeserver is gone (the run names it from its exit,
// which says more than a closed socket). A line that does not decode as `decode` expects ends the
// run naming the pipeserver (RunFault).
template <class Decode>
auto waiting_message(ControlChannel& channel, int pipeserver, Decode decode)
    -> std::optional<decltype(decode(std::string()))> {
  std::optional<std::string> line;
  try {
    line = channel.receive_line(std::chrono::milliseconds(0));
  } catch (const ControlError&) {
    return std::nullopt;
  }
  if (!line) return std::nullopt;
  try {
    return decode(*line);
  } catch (const ControlError& e) {
    throw RunFault(fmt::format("pipeserver {}: {}", pipeserver, e.what()));
  }
}

}  // namespace l2
