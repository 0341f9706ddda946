#include "base/socket.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cstring>
#include <memory>
#include <thread>
#include <vector>

#include "base/result.hpp"

namespace l2 {
namespace {

using Clock = std::chrono::steady_clock;

std::string err_text(int e) {
  return std::strerror(e);
}

struct AddrInfoDeleter {
  void operator()(addrinfo* a) const { freeaddrinfo(a); }
};
using AddrInfoPtr = std::unique_ptr<addrinfo, AddrInfoDeleter>;

AddrInfoPtr resolve(const std::string& host, std::uint16_t port, bool passive,
                    int socktype = SOCK_STREAM) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = socktype;
  hints.ai_flags = passive ? AI_PASSIVE : 0;
  addrinfo* res = nullptr;
  const std::string service = std::to_string(port);
  const int rc = getaddrinfo(host.empty() ? nullptr : host.c_str(), service.c_str(), &hints, &res);
  if (rc != 0) {
    throw NetError(fmt::format("cannot resolve host '{}': {}", host, gai_strerror(rc)));
  }
  return AddrInfoPtr(res);
}

int ms_until(Clock::time_point deadline) {
  const auto left =
      std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return static_cast<int>(std::clamp<long long>(left, 0, INT_MAX));
}

// Waits for `events` on fd; false when the deadline passed first.
bool wait_for(int fd, short events, Clock::time_point deadline) {
  for (;;) {
    pollfd p{fd, events, 0};
    const int rc = ::poll(&p, 1, ms_until(deadline));
    if (rc > 0) return true;
    if (rc == 0) return false;
    if (errno != EINTR) throw NetError(fmt::format("poll failed: {}", err_text(errno)));
  }
}

SocketAddress address_of(const sockaddr_storage& ss) {
  char host[INET6_ADDRSTRLEN] = "?";
  if (ss.ss_family == AF_INET) {
    const auto* a = reinterpret_cast<const sockaddr_in*>(&ss);
    inet_ntop(AF_INET, &a->sin_addr, host, sizeof host);
    return {host, ntohs(a->sin_port)};
  }
  if (ss.ss_family == AF_INET6) {
    const auto* a = reinterpret_cast<const sockaddr_in6*>(&ss);
    inet_ntop(AF_INET6, &a->sin6_addr, host, sizeof host);
    return {host, ntohs(a->sin6_port)};
  }
  return {"?", 0};
}

// One non-blocking connect attempt, completed within the deadline. Returns the errno.
Result<Fd> try_connect(const addrinfo* ai, Clock::time_point deadline) {
  const auto failed = [](int error) { return Failure{err_text(error), error}; };
  Fd fd(::socket(ai->ai_family, ai->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, ai->ai_protocol));
  if (!fd) return failed(errno);
  if (::connect(fd.get(), ai->ai_addr, ai->ai_addrlen) != 0) {
    if (errno != EINPROGRESS && errno != EINTR) return failed(errno);
    if (!wait_for(fd.get(), POLLOUT, deadline)) return failed(ETIMEDOUT);
    int so_error = 0;
    socklen_t len = sizeof so_error;
    ::getsockopt(fd.get(), SOL_SOCKET, SO_ERROR, &so_error, &len);
    if (so_error != 0) return failed(so_error);
  }
  return fd;
}

}  // namespace

void set_nonblocking(int fd) {
  const int flags = ::fcntl(fd, F_GETFL, 0);
  ::fcntl(fd, F_SETFL, flags | O_NONBLOCK);
}

// Tiles and acks are latency-bound small writes at frame ends; Nagle would hold them back.
void set_nodelay(int fd) {
  const int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
}

Fd listen_tcp(const std::string& host, std::uint16_t port) {
  const AddrInfoPtr addrs = resolve(host, port, true);
  int last_errno = 0;
  for (const addrinfo* ai = addrs.get(); ai; ai = ai->ai_next) {
    Fd fd(::socket(ai->ai_family, ai->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, ai->ai_protocol));
    if (!fd) {
      last_errno = errno;
      continue;
    }
    const int one = 1;
    ::setsockopt(fd.get(), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(fd.get(), ai->ai_addr, ai->ai_addrlen) == 0 && ::listen(fd.get(), 64) == 0) {
      return fd;
    }
    last_errno = errno;
  }
  throw NetError(fmt::format("cannot listen on {}:{}: {}", host, port, err_text(last_errno)));
}

Fd bind_udp(const std::string& host, std::uint16_t port) {
  const AddrInfoPtr addrs = resolve(host, port, true, SOCK_DGRAM);
  int last_errno = 0;
  for (const addrinfo* ai = addrs.get(); ai; ai = ai->ai_next) {
    Fd fd(::socket(ai->ai_family, ai->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, ai->ai_protocol));
    if (fd && ::bind(fd.get(), ai->ai_addr, ai->ai_addrlen) == 0) return fd;
    last_errno = errno;
  }
  throw NetError(fmt::format("cannot bind udp {}:{}: {}", host, port, err_text(last_errno)));
}

std::uint16_t local_port(int fd) {
  return local_address(fd).port;
}

namespace {

// The port of "HOST:PORT", or -1: digits only (from_chars takes no sign or space), 1..65535.
int endpoint_port(std::string_view text) {
  const auto colon = text.rfind(':');
  if (colon == std::string_view::npos || colon == 0) return -1;
  const std::string_view digits = text.substr(colon + 1);
  int port = -1;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), port);
  if (ec != std::errc{} || end != digits.data() + digits.size() || port < 1 || port > 65535)
    return -1;
  return port;
}

}  // namespace

std::string endpoint_error(std::string_view text) {
  if (endpoint_port(text) > 0) return {};
  return fmt::format("'{}' is not HOST:PORT (port 1..65535)", text);
}

Endpoint parse_endpoint(std::string_view text) {
  const int port = endpoint_port(text);
  if (port < 0) throw std::invalid_argument(endpoint_error(text));
  return {std::string(text.substr(0, text.rfind(':'))), static_cast<std::uint16_t>(port)};
}

SocketAddress peer_address(int fd) {
  sockaddr_storage ss{};
  socklen_t len = sizeof ss;
  if (::getpeername(fd, reinterpret_cast<sockaddr*>(&ss), &len) != 0) return {"?", 0};
  return address_of(ss);
}

SocketAddress local_address(int fd) {
  sockaddr_storage ss{};
  socklen_t len = sizeof ss;
  if (::getsockname(fd, reinterpret_cast<sockaddr*>(&ss), &len) != 0) return {"?", 0};
  return address_of(ss);
}

std::string peer_name(int fd) {
  const SocketAddress a = peer_address(fd);
  if (a.port == 0) return a.host;
  return a.host.find(':') == std::string::npos ? fmt::format("{}:{}", a.host, a.port)
                                               : fmt::format("[{}]:{}", a.host, a.port);
}

Fd connect_tcp(const std::string& host, std::uint16_t port, std::chrono::milliseconds timeout,
               std::string_view what) {
  const auto deadline = Clock::now() + timeout;
  const AddrInfoPtr addrs = resolve(host, port, false);
  for (;;) {
    Failure last{err_text(0), 0};
    for (const addrinfo* ai = addrs.get(); ai; ai = ai->ai_next) {
      Result<Fd> fd = try_connect(ai, deadline);
      if (fd.ok()) {
        set_nodelay(fd->get());
        return std::move(fd).value();
      }
      last = Failure{fd.reason(), fd.error()};
    }
    // Refused: the server is probably still starting. Anything else will not get better.
    if (last.error != ECONNREFUSED || Clock::now() >= deadline) {
      throw NetError(fmt::format("cannot connect to {} {}:{} within {} ms: {}", what, host, port,
                                 timeout.count(), last.reason));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

void send_all(int fd, std::span<const iovec> parts, Clock::time_point deadline,
              const std::string& peer) {
  std::vector<iovec> left(parts.begin(), parts.end());
  std::size_t first = 0;
  while (first < left.size()) {
    msghdr msg{};
    msg.msg_iov = left.data() + first;
    msg.msg_iovlen = std::min<std::size_t>(left.size() - first, IOV_MAX);
    const ssize_t n = ::sendmsg(fd, &msg, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN || errno == EWOULDBLOCK) {
        if (!wait_for(fd, POLLOUT, deadline)) {
          throw NetError(fmt::format("{}: send timed out (peer not reading)", peer));
        }
        continue;
      }
      if (errno == EPIPE || errno == ECONNRESET) {
        throw ConnectionClosed(fmt::format("{} closed the connection", peer));
      }
      throw NetError(fmt::format("{}: send failed: {}", peer, err_text(errno)));
    }
    // Advance past what went out; a part sent halfway keeps its tail.
    auto sent = static_cast<std::size_t>(n);
    while (first < left.size() && sent >= left[first].iov_len) sent -= left[first++].iov_len;
    if (sent > 0) {
      left[first].iov_base = static_cast<std::uint8_t*>(left[first].iov_base) + sent;
      left[first].iov_len -= sent;
    }
  }
}

void recv_all(int fd, std::uint8_t* data, std::size_t n, Clock::time_point deadline,
              const std::string& peer) {
  std::size_t got = 0;
  while (got < n) {
    const ssize_t r = ::recv(fd, data + got, n - got, 0);
    if (r > 0) {
      got += static_cast<std::size_t>(r);
      continue;
    }
    if (r == 0) throw ConnectionClosed(fmt::format("{} closed the connection", peer));
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EWOULDBLOCK) {
      if (!wait_for(fd, POLLIN, deadline)) throw NetError(fmt::format("{}: timed out", peer));
      continue;
    }
    if (errno == ECONNRESET) {
      throw ConnectionClosed(fmt::format("{} closed the connection", peer));
    }
    throw NetError(fmt::format("{}: receive failed: {}", peer, err_text(errno)));
  }
}

}  // namespace l2
