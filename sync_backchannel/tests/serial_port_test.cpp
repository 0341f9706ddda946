// SerialPort and PtyPair on real pseudo-terminals, and the exact error lines for bad devices.
#include "sync_backchannel/serial_port.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sync_backchannel/pty_pair.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

std::string read_exactly(SerialPort& port, std::size_t n, std::chrono::milliseconds timeout) {
  std::string out;
  const auto deadline = Clock::now() + timeout;
  std::uint8_t buffer[64];
  while (out.size() < n && Clock::now() < deadline) {
    const std::size_t got =
        port.read(std::span(buffer, std::min(sizeof buffer, n - out.size())), 50ms);
    out.append(reinterpret_cast<const char*>(buffer), got);
  }
  return out;
}

std::string error_of(const std::string& path, int baud) {
  try {
    SerialPort::open(path, baud);
  } catch (const SerialError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SerialPort, NonexistentDeviceIsAClearError) {
  EXPECT_EQ(error_of("/dev/l2-no-such-tty", 115200),
            "cannot open serial device /dev/l2-no-such-tty: No such file or directory");
}

TEST(SerialPort, RegularFileIsNotATerminal) {
  char path[] = "/tmp/l2-not-a-tty-XXXXXX";
  const int fd = ::mkstemp(path);
  ASSERT_GE(fd, 0);
  ::close(fd);
  EXPECT_EQ(error_of(path, 115200),
            std::string(path) + " is not a terminal: Inappropriate ioctl for device");
  ::unlink(path);
}

TEST(SerialPort, UnsupportedBaudRateIsAClearError) {
  PtyPair pty = PtyPair::open();
  EXPECT_THAT(error_of(pty.slave_path(), 12345),
              ::testing::StartsWith("unsupported baud rate 12345 for " + pty.slave_path() +
                                    " (supported: 50, 75, 110,"));
  EXPECT_THAT(error_of(pty.slave_path(), 12345), ::testing::EndsWith(", 4000000)"));
  EXPECT_FALSE(is_supported_baud(0));
  EXPECT_TRUE(is_supported_baud(9600));
}

// Permission denied. Root bypasses file modes, so as root the open runs in a child that first
// becomes the unprivileged user "nobody" (65534); where that is impossible the test skips.
TEST(SerialPort, DeviceWithoutPermissionIsAClearError) {
  PtyPair pty = PtyPair::open();
  ASSERT_EQ(::chmod(pty.slave_path().c_str(), 0), 0);
  int pipe_fds[2];
  ASSERT_EQ(::pipe(pipe_fds), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(pipe_fds[0]);
    if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) ::_exit(2);
    const std::string text = error_of(pty.slave_path(), 115200);
    const ssize_t ignored = ::write(pipe_fds[1], text.data(), text.size());
    (void)ignored;
    ::_exit(0);
  }
  ::close(pipe_fds[1]);
  std::string text;
  char buffer[256];
  for (ssize_t n; (n = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0;) text.append(buffer, n);
  ::close(pipe_fds[0]);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 2) GTEST_SKIP() << "running as root and cannot drop to uid 65534";
  EXPECT_EQ(text, "cannot open serial device " + pty.slave_path() + ": Permission denied");
}

TEST(PtyPair, SlaveIsAPseudoTerminalPath) {
  PtyPair pty = PtyPair::open();
  EXPECT_THAT(pty.slave_path(), ::testing::StartsWith("/dev/pts/"));
  EXPECT_TRUE(pty.master().is_open());
  EXPECT_EQ(pty.master().name(), "pty master of " + pty.slave_path());
}

TEST(PtyPair, BytesCrossBothWaysUnchanged) {
  PtyPair pty = PtyPair::open();
  SerialPort host = SerialPort::open(pty.slave_path(), 115200);
  // Every byte value, including CR, LF, XON/XOFF and ^C, must pass untouched in raw mode.
  std::string all;
  for (int b = 0; b < 256; ++b) all += static_cast<char>(b);
  pty.master().write_all(all, 500ms);
  EXPECT_EQ(read_exactly(host, all.size(), 2s), all);
  host.write_all(all, 500ms);
  EXPECT_EQ(read_exactly(pty.master(), all.size(), 2s), all);
  // Nothing echoed back to the writer.
  std::uint8_t extra[8];
  EXPECT_EQ(pty.master().read(extra, 20ms), 0u);
  EXPECT_EQ(host.read(extra, 20ms), 0u);
}

TEST(PtyPair, BytesWrittenBeforeTheHostOpensAreDiscardedOnOpen) {
  // A host that (re)connects must not act on READY lines from before it was listening.
  PtyPair pty = PtyPair::open();
  pty.master().write_all("stale", 100ms);
  SerialPort host = SerialPort::open(pty.slave_path(), 115200);
  pty.master().write_all("fresh", 100ms);
  EXPECT_EQ(read_exactly(host, 5, 1s), "fresh");
}

TEST(SerialPort, ReadTimesOutWithinItsBound) {
  PtyPair pty = PtyPair::open();
  SerialPort host = SerialPort::open(pty.slave_path(), 9600);
  std::uint8_t buffer[16];
  const auto start = Clock::now();
  EXPECT_EQ(host.read(buffer, 150ms), 0u);
  const auto took = Clock::now() - start;
  EXPECT_GE(took, 150ms);
  // Within its bound: a read that ignored it would block until the test's timeout. Ten times
  // the bound, for a loaded machine that wakes the reader late.
  EXPECT_LT(took, 10 * 150ms);
}

TEST(SerialPort, ReadAfterTheOtherEndClosedIsAHangUp) {
  std::string slave_path;
  std::optional<SerialPort> host;
  {
    PtyPair pty = PtyPair::open();
    slave_path = pty.slave_path();
    host.emplace(SerialPort::open(slave_path, 115200));
  }
  std::uint8_t buffer[16];
  try {
    host->read(buffer, 500ms);
    FAIL() << "no error";
  } catch (const SerialError& e) {
    EXPECT_EQ(std::string(e.what()), slave_path + " hung up");
  }
}

TEST(SerialPort, MovedFromPortIsClosedAndOwnsNothing) {
  PtyPair pty = PtyPair::open();
  SerialPort a = SerialPort::open(pty.slave_path(), 115200);
  const int fd = a.fd();
  SerialPort b = std::move(a);
  EXPECT_FALSE(a.is_open());
  EXPECT_EQ(b.fd(), fd);
  b.close();
  EXPECT_FALSE(b.is_open());
  EXPECT_EQ(::fcntl(fd, F_GETFD), -1);  // really closed
}

}  // namespace
}  // namespace l2
