// The UDP edge on loopback: a frame sent arrives as a cursor frame, a datagram that is not OSC
// is counted, and an address in use is one line.
#include "touch/tuio_receiver.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <chrono>
#include <thread>

#include "base/socket.hpp"
#include "tuio_datagrams.hpp"

namespace l2 {
namespace {

using namespace testing_support;
using namespace std::chrono_literals;

void send_to(std::uint16_t port, const std::vector<std::uint8_t>& datagram) {
  const Fd fd(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0));
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(port);
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::sendto(fd.get(), datagram.data(), datagram.size(), 0,
                     reinterpret_cast<const sockaddr*>(&to), sizeof to),
            static_cast<ssize_t>(datagram.size()));
}

// The frames of what was sent, polled until `n` came (a ceiling far above a loopback send).
std::vector<CursorFrame> frames(TuioReceiver& r, std::size_t n) {
  std::vector<CursorFrame> got;
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (got.size() < n && std::chrono::steady_clock::now() < deadline) {
    for (CursorFrame& f : r.poll()) got.push_back(std::move(f));
    std::this_thread::sleep_for(1ms);
  }
  return got;
}

TEST(TuioReceiver, FramesSentOnLoopbackArriveAndGarbageIsCounted) {
  TuioReceiver r("127.0.0.1", 0);
  ASSERT_NE(r.port(), 0);
  EXPECT_TRUE(r.poll().empty());  // nothing waiting: no wait either
  send_to(r.port(), {'n', 'o', 'p', 'e'});
  send_to(r.port(), tuio_frame(1, {{5, 0.5f, 0.25f}}));
  send_to(r.port(), std::vector<std::uint8_t>(9, 0));
  send_to(r.port(), tuio_frame(2, {}));
  const std::vector<CursorFrame> got = frames(r, 2);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].fseq, 1);
  EXPECT_EQ(got[0].cursors, (std::vector<Cursor>{{5, 0.5, 0.25}}));
  EXPECT_TRUE(got[1].cursors.empty());
  EXPECT_EQ(r.dropped_packets(), 2);
  EXPECT_EQ(r.dropped_messages(), 0);
}

TEST(TuioReceiver, AnAddressInUseIsOneLine) {
  TuioReceiver first("127.0.0.1", 0);
  try {
    TuioReceiver second("127.0.0.1", first.port());
    ADD_FAILURE() << "bound twice";
  } catch (const NetError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot bind udp 127.0.0.1:" + std::to_string(first.port()) +
                                         ": Address already in use");
  }
}

}  // namespace
}  // namespace l2
