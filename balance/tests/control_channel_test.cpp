#include "balance/control_channel.hpp"

#include <gtest/gtest.h>

#include <thread>

#include <sys/socket.h>

namespace l2 {
namespace {

using std::chrono::milliseconds;

TEST(ControlChannel, LinesArriveWholeAndInOrder) {
  auto [coordinator, host] = control_socket_pair();
  host.send_line("TIMES 0 1 1 0.25");
  host.send_line("TIMES 1 1 1 0.5");
  EXPECT_EQ(coordinator.receive_line(milliseconds(1000)), "TIMES 0 1 1 0.25");
  EXPECT_EQ(coordinator.receive_line(milliseconds(1000)), "TIMES 1 1 1 0.5");
  coordinator.send_line("LAYOUT 2 1 0 0 10 10 0");
  EXPECT_EQ(host.receive_line(milliseconds(1000)), "LAYOUT 2 1 0 0 10 10 0");
}

TEST(ControlChannel, NothingWithinTheTimeoutIsNoLine) {
  auto [coordinator, host] = control_socket_pair();
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_EQ(coordinator.receive_line(milliseconds(50)), std::nullopt);
  EXPECT_GE(std::chrono::steady_clock::now() - t0, milliseconds(50));
}

TEST(ControlChannel, APeerThatClosedIsAnError) {
  auto [coordinator, host] = control_socket_pair();
  host.send_line("TIMES 0 0 0");
  { SocketControlChannel gone = std::move(host); }
  EXPECT_EQ(coordinator.receive_line(milliseconds(1000)), "TIMES 0 0 0");
  try {
    coordinator.receive_line(milliseconds(1000));
    FAIL() << "no error";
  } catch (const ControlError& e) {
    EXPECT_STREQ(e.what(), "control channel: the peer closed it");
  }
  EXPECT_THROW(coordinator.send_line("LAYOUT 1 1 0 0 1 1 0"), ControlError);
}

TEST(ControlChannel, AnEndlessLineIsRefusedNotKept) {
  auto [coordinator, host] = control_socket_pair();
  std::thread writer([fd = host.fd()] {
    const std::string chunk(65536, 'x');
    std::size_t sent = 0;
    while (sent <= kMaxControlLine + chunk.size()) {
      // MSG_NOSIGNAL: the reader closing while a write is under way must end the loop, not
      // the test process by SIGPIPE.
      const ssize_t n = ::send(fd, chunk.data(), chunk.size(), MSG_NOSIGNAL);
      if (n <= 0) return;  // the reader gave up and closed
      sent += static_cast<std::size_t>(n);
    }
  });
  EXPECT_THROW(coordinator.receive_line(milliseconds(5000)), ControlError);
  { SocketControlChannel gone = std::move(coordinator); }
  writer.join();
}

}  // namespace
}  // namespace l2
