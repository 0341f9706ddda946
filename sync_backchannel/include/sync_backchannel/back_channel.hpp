// The READY protocol on a serial line (spec §6, docs/ready-protocol.md): a tty, or a pty on one
// machine. The protocol is ReadyLine's; this moves its lines over the port.
// One BackChannel per line, used from one thread at a time.
#pragma once

#include <chrono>
#include <string>

#include "sync_backchannel/ready_line.hpp"
#include "sync_backchannel/serial_port.hpp"

namespace l2 {

// Bounds the host's SYNC? write; the emulator end never waits (see send_ready).
inline constexpr std::chrono::milliseconds kWriteTimeout{100};

class BackChannel final : public ReadyLine {
 public:
  explicit BackChannel(SerialPort& port) : port_(port) {}
  const std::string& name() const { return port_.name(); }

 private:
  bool send_line(const std::string& line, MessageKind kind) override;
  bool receive(MessageKind awaited, std::chrono::milliseconds timeout) override;
  const std::string& line_name() const override { return port_.name(); }

  SerialPort& port_;
};

}  // namespace l2
