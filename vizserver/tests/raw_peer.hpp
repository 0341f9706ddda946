// A peer that speaks the tile protocol byte by byte over a real socket, for tests that play a
// stranger or a broken pipeserver.
#pragma once

#include <poll.h>
#include <sys/socket.h>

#include <chrono>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "base/socket.hpp"
#include "viz_link/wire.hpp"

namespace l2::viz::testing {

// Everything a raw connection receives until the server closes it, or nullopt if it is still
// open at the deadline.
inline std::optional<std::string> read_until_closed(int fd, std::chrono::milliseconds within) {
  std::string got;
  const auto deadline = Clock::now() + within;
  while (Clock::now() < deadline) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 20) <= 0) continue;
    char buf[4096];
    const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
    if (n <= 0) return got;
    got.append(buf, static_cast<std::size_t>(n));
  }
  return std::nullopt;
}

// The first message the server sends on `fd`: its kind, and its text if it is an ERROR (the
// rest of its payload otherwise).
inline std::pair<Kind, std::string> first_reply(int fd) {
  const auto deadline = Clock::now() + std::chrono::milliseconds(3000);
  MessageHead head(Protocol::Tiles);
  recv_all(fd, head.space().data(), kHeaderBytes, deadline, "server");
  EXPECT_TRUE(head.received(kHeaderBytes).ok());
  if (!head.has_header()) return {};
  std::string body(head.header().payload_bytes, '\0');
  recv_all(fd, reinterpret_cast<std::uint8_t*>(body.data()), body.size(), deadline, "server");
  return {head.header().kind, head.header().kind == Kind::Error ? body : std::string()};
}

inline void send_bytes(int fd, std::span<const std::uint8_t> bytes) {
  const iovec part{const_cast<std::uint8_t*>(bytes.data()), bytes.size()};
  send_all(fd, std::span(&part, 1), Clock::now() + std::chrono::milliseconds(1000), "server");
}

}  // namespace l2::viz::testing
