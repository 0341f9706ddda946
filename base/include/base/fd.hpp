// An owned file descriptor: closed exactly once, on every path (sockets, shared-memory
// segments, pty and serial lines, pipes to child processes). Header-only, so the lowest part
// that holds a descriptor needs no library for it.
//
// Example:
//
//   int fds[2];
//   if (::pipe2(fds, O_CLOEXEC) != 0) throw std::system_error(errno, std::generic_category());
//   l2::Fd read_end(fds[0]), write_end(fds[1]);
//   ::write(write_end.get(), "x", 1);
//   write_end.reset();  // closed now; read_end is closed when it goes out of scope
//   l2::Fd moved = std::move(read_end);  // read_end holds nothing (-1) from here on
#pragma once

#include <unistd.h>

#include <utility>

namespace l2 {

class Fd {
 public:
  Fd() = default;
  explicit Fd(int fd) noexcept : fd_(fd) {}
  Fd(Fd&& other) noexcept : fd_(other.release()) {}
  Fd& operator=(Fd&& other) noexcept {
    if (this != &other) reset(other.release());
    return *this;
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() { reset(); }

  int get() const noexcept { return fd_; }
  explicit operator bool() const noexcept { return fd_ >= 0; }
  // Gives the descriptor up without closing it (-1 stays behind).
  int release() noexcept { return std::exchange(fd_, -1); }
  // Closes what is held and takes `fd` (-1: holds nothing).
  void reset(int fd = -1) noexcept {
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
  }

 private:
  int fd_ = -1;
};

}  // namespace l2
