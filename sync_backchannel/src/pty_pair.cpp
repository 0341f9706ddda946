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

PtyPair PtyPair::open() {
  Fd master(::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC));
  if (!master) fail("posix_openpt", errno);
  if (::grantpt(master.get()) != 0) fail("grantpt", errno);
  if (::unlockpt(master.get()) != 0) fail("unlockpt", errno);
  char name[128];
  if (::ptsname_r(master.get(), name, sizeof name) != 0) fail("ptsname", errno);
  const std::string slave_path = name;

  Fd keeper(::open(name, O_RDWR | O_NOCTTY | O_CLOEXEC));
  if (!keeper) fail(fmt::format("opening {}", slave_path), errno);
  // On Linux the terminal settings of the pair live with the slave; set them through it.
  termios tio{};
  if (::tcgetattr(keeper.get(), &tio) != 0) fail("tcgetattr", errno);
  cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL;
  if (::tcsetattr(keeper.get(), TCSANOW, &tio) != 0) fail("tcsetattr", errno);

  SerialPort port = SerialPort::adopt(master.release(), "pty master of " + slave_path);
  return PtyPair(std::move(port), slave_path, std::move(keeper));
}

}  // namespace l2
