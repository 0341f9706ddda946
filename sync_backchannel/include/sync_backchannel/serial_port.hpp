// A serial line over POSIX termios: real ttys (/dev/ttyS*, /dev/ttyUSB*) and pseudo-terminals
// alike. Raw 8N1, no flow control, non-blocking fd driven by poll() so every read and write is
// bounded in time. Errors are SerialError with one line naming the device and the errno text.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "base/fd.hpp"

namespace l2 {

class SerialError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr int kDefaultBaud = 115200;

// Baud rates termios can set (B50 .. B4000000).
const std::vector<int>& supported_bauds();
bool is_supported_baud(int baud);

class SerialPort {
 public:
  // Opens `path` read/write, makes it raw 8N1 at `baud` without flow control, and discards
  // whatever was queued before we opened it (stale bytes from an earlier session).
  // Throws SerialError: "cannot open serial device <path>: <errno text>",
  // "<path> is not a terminal: <errno text>", "unsupported baud rate <n> for <path> (...)".
  static SerialPort open(const std::string& path, int baud = kDefaultBaud);

  // Takes ownership of an already configured descriptor (for example a pty master); `name` is
  // what error messages call it. Makes the fd non-blocking.
  static SerialPort adopt(int fd, std::string name);

  SerialPort(SerialPort&& other) noexcept = default;
  SerialPort& operator=(SerialPort&& other) noexcept = default;
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;
  ~SerialPort() = default;

  // Waits up to `timeout` for at least one byte, then returns what is available (up to
  // buffer.size()). Returns 0 when the timeout passed with nothing to read. Throws SerialError
  // when the other end hung up or the read failed.
  std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout);

  // Writes every byte, waiting at most `timeout` in total for the line to accept them.
  // Throws SerialError on timeout (naming how many bytes went out) or failure.
  void write_all(std::span<const std::uint8_t> bytes, std::chrono::milliseconds timeout);
  void write_all(std::string_view text, std::chrono::milliseconds timeout);

  // Writes what the line accepts right now, without waiting; returns how many bytes that was
  // (fewer than asked when the line is full). Throws SerialError when the write fails.
  std::size_t write_some(std::span<const std::uint8_t> bytes);
  std::size_t write_some(std::string_view text);

  void close() noexcept { fd_.reset(); }
  bool is_open() const { return static_cast<bool>(fd_); }
  const std::string& name() const { return name_; }
  int fd() const { return fd_.get(); }

 private:
  SerialPort(int fd, std::string name) : fd_(fd), name_(std::move(name)) {}
  // poll() for `events` until `deadline`; EINTR restarts with the remaining time.
  short wait_for(short events, std::chrono::steady_clock::time_point deadline);
  [[noreturn]] void fail(std::string_view what, int error) const;

  Fd fd_;
  std::string name_;
};

}  // namespace l2
