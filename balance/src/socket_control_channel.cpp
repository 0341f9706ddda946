#include <fmt/format.h>
#include <poll.h>
#include <sys/socket.h>

#include <cerrno>
#include <cstring>

#include "balance/control_channel.hpp"

namespace l2 {

void SocketControlChannel::send_line(const std::string& line) {
  const std::string bytes = line + "\n";
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    // MSG_NOSIGNAL: a closed peer is an error to report, not SIGPIPE ending the run.
    const ssize_t n = ::send(fd_.get(), bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw ControlError(fmt::format("control channel: send: {}", std::strerror(errno)));
    sent += static_cast<std::size_t>(n);
  }
}

std::optional<std::string> SocketControlChannel::receive_line(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const std::size_t newline = pending_.find('\n');
    if (newline != std::string::npos) {
      std::string line = pending_.substr(0, newline);
      pending_.erase(0, newline + 1);
      return line;
    }
    if (pending_.size() > kMaxControlLine) {
      throw ControlError(
          fmt::format("control channel: a line longer than {} bytes", kMaxControlLine));
    }
    const auto left =
        std::chrono::ceil<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    pollfd p{fd_.get(), POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::max<long long>(left.count(), 0)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0)
      throw ControlError(fmt::format("control channel: poll: {}", std::strerror(errno)));
    if (ready == 0) {
      if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
      continue;  // woken a little early
    }
    char buffer[65536];
    const ssize_t n = ::recv(fd_.get(), buffer, sizeof buffer, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw ControlError(fmt::format("control channel: recv: {}", std::strerror(errno)));
    if (n == 0) throw ControlError("control channel: the peer closed it");
    pending_.append(buffer, static_cast<std::size_t>(n));
  }
}

std::pair<SocketControlChannel, SocketControlChannel> control_socket_pair() {
  int fds[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM, 0, fds) != 0) {
    throw ControlError(fmt::format("control channel: socketpair: {}", std::strerror(errno)));
  }
  return {SocketControlChannel(Fd(fds[0])), SocketControlChannel(Fd(fds[1]))};
}

}  // namespace l2
