// The compositing server against peers that do not play by the rules, over real sockets: a
// burst of strangers around a pipeserver's HELLO, a flood of garbage, a half-sent TILE, ERROR
// text made to attack a terminal, a stranger that claims a pipeserver's id, and a HELLO replayed.
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "raw_peer.hpp"
#include "viz_link/tile_sender.hpp"
#include "viz_link/wire.hpp"
#include "vizserver/compositing_server.hpp"
#include "vizserver/display_watcher.hpp"

namespace l2::viz {
namespace {

using namespace std::chrono_literals;
using testing::first_reply;
using ::testing::HasSubstr;
using testing::read_until_closed;
using testing::send_bytes;

ServerOptions one_display(int pipeservers) {
  ServerOptions o;
  o.display_sizes = {{4, 4}};
  o.pipeservers = pipeservers;
  o.accept_timeout = 5000ms;
  o.stall_timeout = 5000ms;
  return o;
}

TEST(VizServerHostile, ABurstOfStrangersDoesNotEvictAPipeserverWhoseHelloArrived) {
  // 40 connections between a pipeserver's connect and the server's first look at it: the
  // seventeenth closed the oldest connection without HELLO, the pipeserver, its HELLO unread.
  CompositingServer server(one_display(1));  // listening, its loop not yet running
  Fd pipeserver = connect_tcp("127.0.0.1", server.port(), 2000ms);
  send_bytes(pipeserver.get(), encode(Hello{0, 1}));
  std::vector<Fd> strangers;
  for (int i = 0; i < 40; ++i) strangers.push_back(connect_tcp("127.0.0.1", server.port(), 2000ms));
  server.start();
  EXPECT_EQ(first_reply(pipeserver.get()).first, Kind::Welcome);
  send_bytes(pipeserver.get(), encode(FrameDone{0, 0, 0}));
  EXPECT_NE(server.wait_frame(0, 3000ms), nullptr);
}

TEST(VizServerHostile, APipeserverClosedBeforeItsWelcomeConnectsAgain) {
  // A compositing server that closes the first connection unread (as one flooded by strangers
  // does) and welcomes the second: the pipeserver gave up at the first close.
  Fd listener = listen_tcp("127.0.0.1", 0);
  const std::uint16_t port = local_port(listener.get());
  std::thread server([&] {
    accept_within(listener, 3000ms).reset();  // closed at once, HELLO unread
    Fd second = accept_within(listener, 3000ms);
    if (!second) return;
    std::uint8_t hello[kHeaderBytes + 24];
    recv_all(second.get(), hello, sizeof hello, Clock::now() + 3000ms, "pipeserver");
    send_bytes(second.get(), encode(Welcome{0, 1, 1}));
    std::this_thread::sleep_for(200ms);
  });
  std::string error;
  try {
    TileSender::connect("127.0.0.1", port, 0, 1);
  } catch (const NetError& e) {
    error = e.what();
  }
  server.join();
  EXPECT_EQ(error, "");
}

TEST(VizServerHostile, RefusedConnectionsAreCountedButOnlyTheFirstFewKept) {
  // Each refused connection added a line for ever: 20,000 of them, 2.6 MB.
  CompositingServer server(one_display(1));
  server.start();
  const std::string junk = "GET / HTTP/1.1\r\n\r\n";
  for (int i = 0; i < 200; ++i) {
    Fd raw = connect_tcp("127.0.0.1", server.port(), 2000ms);
    send_bytes(raw.get(), std::span(reinterpret_cast<const std::uint8_t*>(junk.data()), 12));
    ASSERT_TRUE(read_until_closed(raw.get(), 2000ms));
  }
  EXPECT_EQ(server.error_count(), 200u);
  ASSERT_EQ(server.errors().size(), 16u);
  EXPECT_THAT(server.errors()[15], HasSubstr(": bad magic 0x20544547"));
  auto s = TileSender::connect("127.0.0.1", server.port(), 0, 1);  // the run goes on
  s.finish_frame(0, 0);
  s.wait_swapped(0, 3000ms);
}

TEST(VizServerHostile, AHalfSentTileEndsTheRunAtTheStallTimeout) {
  // One pipeserver, so no frame waits for it: the stall timeout never looked at it, and a TILE
  // that stops after its first 1,000 bytes held the server for ever.
  auto o = one_display(1);
  o.stall_timeout = 300ms;
  CompositingServer server(o);
  server.start();
  Fd raw = connect_tcp("127.0.0.1", server.port(), 2000ms);
  const std::uint16_t my_port = local_port(raw.get());
  send_bytes(raw.get(), encode(Hello{0, 1}));
  ASSERT_EQ(first_reply(raw.get()).first, Kind::Welcome);
  send_bytes(raw.get(), encode(TileHeader{0, 0, 0, 0, 4095, 4095}));
  send_bytes(raw.get(), std::vector<std::uint8_t>(1000, 7));
  ASSERT_TRUE(server.wait_finished(3000ms)) << "still waiting for the rest of the TILE";
  EXPECT_EQ(server.failure().reason(),
            fmt::format("pipeserver 0 (127.0.0.1:{}) sent nothing for 0.3 s in the middle of a "
                        "TILE message (frame 0, display 0, 4095x4095: 1000 of 50307075 bytes)",
                        my_port));
}

// A TILE_DELTA that declares more encoded bytes than any tile, or than its own tile's changes,
// can take is refused from its header, before anything is allocated; one whose bytes do not
// decode is refused too. Each in one line naming the pipeserver. (A 4x4 tile: 32 fixed bytes,
// then at most a 24-byte header, 1 byte of bitmap and 4 rows of 1 + 12 bytes.)
TEST(VizServerHostile, TileDeltasTooLargeOrNotDecodingAreRefusedInOneLine) {
  const std::vector<std::pair<std::uint32_t, std::string>> cases = {
      {4'000'000'000u, "TILE_DELTA payload of 4000000032 bytes, allowed 32..100618813"},
      {1000, "TILE_DELTA 4x4 with a payload of 1032 bytes, allowed 32..109"},
      {40, "TILE_DELTA 4x4 on display 0: not a frame message (magic or version)"}};
  for (const auto& [encoded, why] : cases) {
    CompositingServer server(one_display(1));
    server.start();
    Fd raw = connect_tcp("127.0.0.1", server.port(), 2000ms);
    const std::uint16_t my_port = local_port(raw.get());
    send_bytes(raw.get(), encode(Hello{0, 1}));
    ASSERT_EQ(first_reply(raw.get()).first, Kind::Welcome);
    send_bytes(raw.get(), encode_delta(TileHeader{0, 0, 0, 0, 4, 4}, encoded));
    if (encoded == 40) send_bytes(raw.get(), std::vector<std::uint8_t>(40, 0xAB));
    ASSERT_TRUE(server.wait_finished(3000ms));
    EXPECT_THAT(server.failure().reason(),
                HasSubstr(fmt::format("pipeserver 0 (127.0.0.1:{}): {}", my_port, why)));
  }
}

TEST(VizServerHostile, AStrangersErrorTextIsLoggedEscaped) {
  CompositingServer server(one_display(1));
  server.start();
  Fd raw = connect_tcp("127.0.0.1", server.port(), 2000ms);
  const std::uint16_t my_port = local_port(raw.get());
  const std::string text = "\x1b[2J\x1b]0;owned\x07gone\r\nvizserver: error: fake";
  send_bytes(raw.get(), encode_error_header(text.size()));
  send_bytes(raw.get(), std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
  ASSERT_TRUE(read_until_closed(raw.get(), 2000ms));
  ASSERT_EQ(server.errors().size(), 1u);
  EXPECT_EQ(server.errors()[0],
            fmt::format("connection from 127.0.0.1:{} gave up: "
                        "\\x1b[2J\\x1b]0;owned\\x07gone\\r\\nvizserver: error: fake",
                        my_port));
}

TEST(VizServerHostile, AStrangerWithoutTheRunsTokenIsRefusedAndTheRunGoesOn) {
  // Any peer that said HELLO with a free id took that pipeserver's place.
  auto o = one_display(1);
  o.token = *parse_token("00112233445566778899aabbccddeeff");
  CompositingServer server(o);
  server.start();
  RunToken guess = o.token;
  guess[15] ^= 1;
  for (const RunToken& wrong : {RunToken{}, guess}) {
    Fd stranger = connect_tcp("127.0.0.1", server.port(), 2000ms);
    const std::uint16_t its_port = local_port(stranger.get());
    send_bytes(stranger.get(), encode(Hello{0, 1, wrong}));
    const auto [kind, text] = first_reply(stranger.get());
    EXPECT_EQ(kind, Kind::Error);
    EXPECT_EQ(text, "HELLO as pipeserver 0 without this run's token");
    EXPECT_EQ(server.errors().back(),
              fmt::format("connection from 127.0.0.1:{}: refused: HELLO as pipeserver 0 without "
                          "this run's token",
                          its_port));
  }
  EXPECT_EQ(server.error_count(), 2u);
  SenderOptions with_token;
  with_token.token = o.token;
  auto s = TileSender::connect("127.0.0.1", server.port(), 0, 1, with_token);
  s.finish_frame(0, 0);
  s.wait_swapped(0, 3000ms);
  EXPECT_EQ(server.failure().reason(), "");
}

// A pipeserver's HELLO captured and sent again: to the next run's server (another token) it is a
// stranger's; to its own run's, once the pipeserver is in, a second claim of its id. Both are
// refused and counted, and the run goes on.
TEST(VizServerHostile, AReplayedHelloIsRefusedAndTheRunGoesOn) {
  auto earlier = one_display(1);
  earlier.token = new_run_token();
  auto o = one_display(1);
  o.token = new_run_token();
  CompositingServer server(o);
  server.start();
  const auto captured = encode(Hello{0, 1, earlier.token});
  Fd replay = connect_tcp("127.0.0.1", server.port(), 2000ms);
  send_bytes(replay.get(), captured);
  const auto [kind, text] = first_reply(replay.get());
  EXPECT_EQ(kind, Kind::Error);
  EXPECT_EQ(text, "HELLO as pipeserver 0 without this run's token");

  SenderOptions with_token;
  with_token.token = o.token;
  auto s = TileSender::connect("127.0.0.1", server.port(), 0, 1, with_token);
  Fd again = connect_tcp("127.0.0.1", server.port(), 2000ms);
  send_bytes(again.get(), encode(Hello{0, 1, o.token}));
  const auto [again_kind, again_text] = first_reply(again.get());
  EXPECT_EQ(again_kind, Kind::Error);
  EXPECT_EQ(again_text, "pipeserver 0 is already connected");
  EXPECT_EQ(server.error_count(), 2u);
  s.finish_frame(0, 0);
  s.wait_swapped(0, 3000ms);
  EXPECT_EQ(server.failure().reason(), "");
}

TEST(VizServerHostile, APipeserverWithoutTheTokenIsToldWhy) {
  auto o = one_display(1);
  o.token = new_run_token();
  CompositingServer server(o);
  server.start();
  try {
    TileSender::connect("127.0.0.1", server.port(), 0, 1);
    FAIL() << "welcomed without the token";
  } catch (const NetError& e) {
    EXPECT_EQ(std::string(e.what()),
              fmt::format("compositing server 127.0.0.1:{}: HELLO as pipeserver 0 without this "
                          "run's token",
                          server.port()));
  }
}

}  // namespace
}  // namespace l2::viz
