#include "mpi_link/liveness.hpp"

#include <fmt/format.h>
#include <sys/socket.h>

#include <array>
#include <cerrno>

namespace l2 {

Heard heard(std::string_view bytes, bool closed) {
  if (bytes.find(kLivenessEnded) != std::string_view::npos) return Heard::ended;
  if (bytes.find(kLivenessFailed) != std::string_view::npos) return Heard::failed;
  if (bytes.find(kLivenessAborting) != std::string_view::npos) return Heard::aborting;
  if (bytes.find(kLivenessStopped) != std::string_view::npos) return Heard::stopped;
  if (closed) return Heard::closed;
  return bytes.empty() ? Heard::nothing : Heard::pulse;
}

std::string failed_word(int code) {
  return fmt::format("{}{};", kLivenessFailed, code);
}

int failed_code(std::string_view bytes) {
  const std::size_t at = bytes.find(kLivenessFailed);
  if (at == std::string_view::npos) return -1;
  int code = 0;
  for (std::size_t i = at + 1; i < bytes.size() && i < at + 5; ++i) {
    if (bytes[i] == ';') return i > at + 1 ? code : -1;
    if (bytes[i] < '0' || bytes[i] > '9') return -1;
    code = code * 10 + (bytes[i] - '0');
  }
  return -1;
}

std::string no_word_for(std::chrono::milliseconds timeout) {
  return fmt::format("no word for {:g} s", static_cast<double>(timeout.count()) / 1000.0);
}

Heard read_liveness(int fd, int* exit_code) {
  std::array<char, 256> buffer{};
  std::string bytes;
  bool closed = false;
  for (;;) {
    const ssize_t n = recv(fd, buffer.data(), buffer.size(), MSG_DONTWAIT);
    if (n > 0) {
      bytes.append(buffer.data(), static_cast<std::size_t>(n));
      if (bytes.size() < 4096) continue;  // a peer that floods is not read for ever
      break;
    }
    closed = n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR);
    break;
  }
  const Heard h = heard(bytes, closed);
  if (h == Heard::failed && exit_code) *exit_code = failed_code(bytes);
  return h;
}

void send_liveness(int fd, std::string_view word) {
  send(fd, word.data(), word.size(), MSG_DONTWAIT | MSG_NOSIGNAL);
}

void send_last_word(int fd, std::string_view word) {
  std::array<char, 256> buffer{};
  for (int i = 0; i < 64 && recv(fd, buffer.data(), buffer.size(), MSG_DONTWAIT) > 0; ++i) {
  }
  send_liveness(fd, word);
  shutdown(fd, SHUT_WR);
}

void send_last_word(int fd, char byte) {
  send_last_word(fd, std::string_view(&byte, 1));
}

void send_liveness(int fd, char byte) {
  send_liveness(fd, std::string_view(&byte, 1));
}

}  // namespace l2
