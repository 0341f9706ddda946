#include "sync_backchannel/serial_port.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include <fmt/format.h>

namespace l2 {
namespace {

struct BaudCode {
  int baud;
  speed_t code;
};

constexpr BaudCode kBauds[] = {
    {50, B50},           {75, B75},           {110, B110},         {134, B134},
    {150, B150},         {200, B200},         {300, B300},         {600, B600},
    {1200, B1200},       {1800, B1800},       {2400, B2400},       {4800, B4800},
    {9600, B9600},       {19200, B19200},     {38400, B38400},     {57600, B57600},
    {115200, B115200},   {230400, B230400},   {460800, B460800},   {500000, B500000},
    {576000, B576000},   {921600, B921600},   {1000000, B1000000}, {1152000, B1152000},
    {1500000, B1500000}, {2000000, B2000000}, {2500000, B2500000}, {3000000, B3000000},
    {3500000, B3500000}, {4000000, B4000000},
};

speed_t baud_code(int baud) {
  for (const BaudCode& b : kBauds) {
    if (b.baud == baud) return b.code;
  }
  return B0;
}

std::string errno_text(int error) {
  return std::strerror(error);
}

// Raw 8N1, no flow control. CLOCAL: ignore modem lines, so a cable without DCD still works.
// VMIN/VTIME 0: reads never block in the driver; poll() does the waiting.
void make_raw(termios& tio, speed_t speed) {
  cfmakeraw(&tio);
  tio.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | CSTOPB | CRTSCTS);
  tio.c_cflag |= CS8 | CLOCAL | CREAD;
  tio.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  cfsetispeed(&tio, speed);
  cfsetospeed(&tio, speed);
}

}  // namespace

const std::vector<int>& supported_bauds() {
  static const std::vector<int> bauds = [] {
    std::vector<int> v;
    for (const BaudCode& b : kBauds) v.push_back(b.baud);
    return v;
  }();
  return bauds;
}

bool is_supported_baud(int baud) {
  return baud_code(baud) != B0;
}

SerialPort SerialPort::open(const std::string& path, int baud) {
  // Checked before opening: a bad request should not touch the device at all.
  if (!is_supported_baud(baud)) {
    throw SerialError(fmt::format("unsupported baud rate {} for {} (supported: {})", baud, path,
                                  fmt::join(supported_bauds(), ", ")));
  }
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    throw SerialError(fmt::format("cannot open serial device {}: {}", path, errno_text(errno)));
  }
  SerialPort port(fd, path);
  termios tio{};
  if (::tcgetattr(fd, &tio) != 0) {
    throw SerialError(fmt::format("{} is not a terminal: {}", path, errno_text(errno)));
  }
  make_raw(tio, baud_code(baud));
  if (::tcsetattr(fd, TCSANOW, &tio) != 0) port.fail("cannot configure", errno);
  ::tcflush(fd, TCIOFLUSH);
  return port;
}

SerialPort SerialPort::adopt(int fd, std::string name) {
  SerialPort port(fd, std::move(name));
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags < 0 || ::fcntl(fd, F_SETFL, flags | O_NONBLOCK) != 0) {
    port.fail("cannot make non-blocking", errno);
  }
  return port;
}

void SerialPort::fail(std::string_view what, int error) const {
  throw SerialError(fmt::format("{} {}: {}", what, name_, errno_text(error)));
}

short SerialPort::wait_for(short events, std::chrono::steady_clock::time_point deadline) {
  if (!fd_) throw SerialError(fmt::format("{} is closed", name_));
  for (;;) {
    const auto left =
        std::chrono::ceil<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    pollfd p{fd_.get(), events, 0};
    const int n = ::poll(&p, 1, static_cast<int>(std::max<long long>(left.count(), 0)));
    if (n > 0) return p.revents;
    if (n == 0) return 0;
    if (errno != EINTR) fail("cannot poll", errno);
  }
}

std::size_t SerialPort::read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const short revents = wait_for(POLLIN, deadline);
    if (revents == 0) return 0;
    const ssize_t n = ::read(fd_.get(), buffer.data(), buffer.size());
    if (n > 0) return static_cast<std::size_t>(n);
    // n == 0: the other end closed (EOF on a pty slave). EIO: a pty master whose slave is
    // closed. Either way nobody is on the line any more.
    if (n == 0 || errno == EIO) throw SerialError(fmt::format("{} hung up", name_));
    if (errno != EINTR && errno != EAGAIN) fail("cannot read from", errno);
    if (std::chrono::steady_clock::now() >= deadline) return 0;
  }
}

void SerialPort::write_all(std::span<const std::uint8_t> bytes, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_.get(), bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno != EAGAIN) fail("cannot write to", errno);
    if (wait_for(POLLOUT, deadline) == 0) {
      throw SerialError(fmt::format("timed out writing to {} after {} ms ({} of {} bytes sent)",
                                    name_, timeout.count(), done, bytes.size()));
    }
  }
}

std::size_t SerialPort::write_some(std::span<const std::uint8_t> bytes) {
  if (!fd_) throw SerialError(fmt::format("{} is closed", name_));
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_.get(), bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
    } else if (n == 0 || errno == EAGAIN) {
      break;
    } else if (errno != EINTR) {
      fail("cannot write to", errno);
    }
  }
  return done;
}

std::size_t SerialPort::write_some(std::string_view text) {
  return write_some(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

void SerialPort::write_all(std::string_view text, std::chrono::milliseconds timeout) {
  write_all(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), timeout);
}

}  // namespace l2
