#include "sync_backchannel/pty_pair.hpp"

#include <fcntl.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

#include <fmt/format.h>

namespace l2 {
namespace {

[[noreturn]] void fail(std::string_view step, int error) {
  throw SerialError(
      fmt::format("cannot create pseudo-terminal: {} failed: {}", step, std::strerror(error)));
}

}  // namespace

// Closes a descriptor on every error path of open().
class FdGuard {
 public:
  explicit FdGuard(int fd) : fd_(fd) {}
  FdGuard(const FdGuard&) = delete;
  FdGuard& operator=(const FdGuard&) = delete;
  ~FdGuard() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }

 private:
  int fd_;
};

PtyPair PtyPair::open() {
  FdGuard master(::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC));
  if (master.get() < 0) fail("posix_openpt", errno);
  if (::grantpt(master.get()) != 0) fail("grantpt", errno);
  if (::unlockpt(master.get()) != 0) fail("unlockpt", errno);
  char name[128];
  if (::ptsname_r(master.get(), name, sizeof name) != 0) fail("ptsname", errno);
  const std::string slave_path = name;

  FdGuard keeper(::open(name, O_RDWR | O_NOCTTY | O_CLOEXEC));
  if (keeper.get() < 0) fail(fmt::format("opening {}", slave_path), errno);
  // On Linux the terminal settings of the pair live with the slave; set them through it.
  termios tio{};
  if (::tcgetattr(keeper.get(), &tio) != 0) fail("tcgetattr", errno);
  cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL;
  if (::tcsetattr(keeper.get(), TCSANOW, &tio) != 0) fail("tcsetattr", errno);

  SerialPort port = SerialPort::adopt(master.release(), "pty master of " + slave_path);
  return PtyPair(std::move(port), slave_path, keeper.release());
}

PtyPair::PtyPair(PtyPair&& other) noexcept
    : master_(std::move(other.master_)),
      slave_path_(std::move(other.slave_path_)),
      keeper_(std::exchange(other.keeper_, -1)) {}

PtyPair& PtyPair::operator=(PtyPair&& other) noexcept {
  if (this != &other) {
    if (keeper_ >= 0) ::close(keeper_);
    master_ = std::move(other.master_);
    slave_path_ = std::move(other.slave_path_);
    keeper_ = std::exchange(other.keeper_, -1);
  }
  return *this;
}

PtyPair::~PtyPair() {
  if (keeper_ >= 0) ::close(keeper_);
}

}  // namespace l2
