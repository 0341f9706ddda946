#include "mpi_link/liveness.hpp"

#include <fmt/format.h>
#include <sys/socket.h>

#include <array>
#include <cerrno>

namespace l2 {

Heard heard(std::string_view bytes, bool closed) {
  if (bytes.find(kLivenessEnded) != std::string_view::npos) return Heard::ended;
  if (bytes.find(kLivenessAborting) != std::string_view::npos) return Heard::aborting;
  if (bytes.find(kLivenessStopped) != std::string_view::npos) return Heard::stopped;
  if (closed) return Heard::closed;
  return bytes.empty() ? Heard::nothing : Heard::pulse;
}

std::string no_word_for(std::chrono::milliseconds timeout) {
  return fmt::format("no word for {:g} s", static_cast<double>(timeout.count()) / 1000.0);
}

Heard read_liveness(int fd) {
  std::array<char, 256> buffer{};
  std::string bytes;
  for (;;) {
    const ssize_t n = recv(fd, buffer.data(), buffer.size(), MSG_DONTWAIT);
    if (n > 0) {
      bytes.append(buffer.data(), static_cast<std::size_t>(n));
      if (bytes.size() < 4096) continue;  // a peer that floods is not read for ever
      return heard(bytes, false);
    }
    const bool closed = n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR);
    return heard(bytes, closed);
  }
}

void send_liveness(int fd, char byte) {
  send(fd, &byte, 1, MSG_DONTWAIT | MSG_NOSIGNAL);
}

}  // namespace l2
