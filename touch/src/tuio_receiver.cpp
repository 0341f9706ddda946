#include "touch/tuio_receiver.hpp"

#include <sys/socket.h>

#include <cerrno>

#include "base/socket.hpp"
#include "touch/osc_packet.hpp"

namespace l2 {
namespace {

// The largest UDP payload: a longer datagram cannot arrive whole.
constexpr std::size_t kMaxDatagram = 65536;

}  // namespace

TuioReceiver::TuioReceiver(const std::string& host, std::uint16_t port)
    : fd_(bind_udp(host, port)), buffer_(kMaxDatagram) {}

std::uint16_t TuioReceiver::port() const {
  return local_port(fd_.get());
}

std::vector<CursorFrame> TuioReceiver::poll() {
  std::vector<CursorFrame> frames;
  for (int k = 0; k < kMaxDatagramsPerPoll; ++k) {
    // MSG_TRUNC: the datagram's whole length, so a cut one is seen and dropped.
    const ssize_t n = ::recv(fd_.get(), buffer_.data(), buffer_.size(), MSG_TRUNC);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;  // nothing waiting (EAGAIN), or an error the next call meets again
    if (static_cast<std::size_t>(n) > buffer_.size()) {
      ++dropped_packets_;
      continue;
    }
    const auto messages =
        decode_osc(std::span<const std::uint8_t>(buffer_.data(), static_cast<std::size_t>(n)));
    if (!messages.ok()) {
      ++dropped_packets_;
      continue;
    }
    for (const OscMessage& m : *messages)
      if (auto f = cursors_.take(m)) frames.push_back(std::move(*f));
  }
  return frames;
}

}  // namespace l2
