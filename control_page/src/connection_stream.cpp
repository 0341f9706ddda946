#include "connection_stream.hpp"

#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "base/socket.hpp"

namespace l2 {

namespace {

// A read takes what the kernel has, up to this; cpp-httplib reads a request's head a byte at a
// time.
constexpr std::size_t kReadChunk = 4096;

}  // namespace

ConnectionStream::ConnectionStream(socket_t sock, Clock::duration read_wait,
                                   Clock::duration write_wait)
    : sock_(sock), read_wait_(read_wait), write_wait_(write_wait) {}

bool ConnectionStream::next_request(Clock::duration idle, Clock::duration read_limit,
                                    Clock::duration write_limit) {
  writing_ = false;
  write_limit_ = write_limit;
  deadline_ = Clock::now() + idle;
  if (taken_ == buffer_.size() && !wait(POLLIN, idle)) return false;
  deadline_ = Clock::now() + read_limit;
  return true;
}

// Waits for `events` up to `most`, and never past the deadline.
bool ConnectionStream::wait(short events, Clock::duration most) const {
  const auto left = std::min(most, deadline_ - Clock::now());
  if (left <= Clock::duration::zero()) return false;
  pollfd p{sock_, events, 0};
  const auto ms = std::chrono::ceil<std::chrono::milliseconds>(left).count();
  int n;
  do {
    n = ::poll(&p, 1, static_cast<int>(ms));
  } while (n < 0 && errno == EINTR);
  return n > 0;
}

bool ConnectionStream::is_readable() const {
  return taken_ < buffer_.size() || wait(POLLIN, read_wait_);
}

bool ConnectionStream::is_writable() const {
  return wait(POLLOUT, write_wait_);
}

ssize_t ConnectionStream::read(char* ptr, size_t size) {
  if (taken_ == buffer_.size()) {
    if (!wait(POLLIN, read_wait_)) return -1;
    buffer_.resize(kReadChunk);
    const ssize_t n = ::recv(sock_, buffer_.data(), kReadChunk, MSG_DONTWAIT);
    buffer_.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
    taken_ = 0;
    if (n <= 0) return n;
  }
  const std::size_t n = std::min(size, buffer_.size() - taken_);
  std::memcpy(ptr, buffer_.data() + taken_, n);
  taken_ += n;
  return static_cast<ssize_t>(n);
}

ssize_t ConnectionStream::write(const char* ptr, size_t size) {
  if (!writing_) {
    writing_ = true;
    deadline_ = Clock::now() + write_limit_;
  }
  if (!wait(POLLOUT, write_wait_)) return -1;
  // Never blocking: a send that waited for the whole answer to go would outlive the deadline.
  const ssize_t n = ::send(sock_, ptr, size, MSG_NOSIGNAL | MSG_DONTWAIT);
  return n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK) ? 0 : n;
}

void ConnectionStream::get_remote_ip_and_port(std::string& ip, int& port) const {
  const SocketAddress a = peer_address(sock_);
  ip = a.host;
  port = a.port;
}

void ConnectionStream::get_local_ip_and_port(std::string& ip, int& port) const {
  const SocketAddress a = local_address(sock_);
  ip = a.host;
  port = a.port;
}

}  // namespace l2
