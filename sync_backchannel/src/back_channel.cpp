#include "sync_backchannel/back_channel.hpp"

#include <array>

namespace l2 {

bool BackChannel::send_line(const std::string& line, MessageKind kind) {
  // READY never waits for a host that stopped reading; a SYNC? waits a bounded time.
  if (kind == MessageKind::Ready) return port_.write_some(line) == line.size();
  port_.write_all(line, kWriteTimeout);
  return true;
}

bool BackChannel::receive(MessageKind /*awaited*/, std::chrono::milliseconds timeout) {
  std::array<std::uint8_t, 256> buffer;
  const std::size_t n = port_.read(buffer, timeout);
  feed(std::span<const std::uint8_t>(buffer.data(), n));
  return n > 0;
}

}  // namespace l2
