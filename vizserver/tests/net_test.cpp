// The compositing server and TileSender over real sockets on 127.0.0.1, pipeservers as threads.
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <poll.h>
#include <sys/socket.h>

#include <chrono>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "raw_peer.hpp"
#include "viz_link/tile_sender.hpp"
#include "viz_link/wire.hpp"
#include "vizserver/compositing_server.hpp"

namespace l2::viz {
namespace {

using namespace std::chrono_literals;
using testing::first_reply;
using ::testing::HasSubstr;
using testing::read_until_closed;
using testing::send_bytes;

// The colour the test expects at display pixel (x, y) of `display` in `frame`. Chosen here,
// independently of the code under test; every pixel differs from its neighbours.
Rgb pattern(int display, int x, int y, std::uint32_t frame) {
  return {static_cast<std::uint8_t>(x * 7 + display * 50 + static_cast<int>(frame) * 3),
          static_cast<std::uint8_t>(y * 13 + 1), static_cast<std::uint8_t>((x ^ y) + 100)};
}

// A pipeserver framebuffer: tiles at (fb_x, fb_y), garbage everywhere else so a wrong stride
// or offset shows up as wrong pixels.
struct PlacedTile {
  TileTarget target;
  int fb_x = 0, fb_y = 0;
};

RgbImage render(const std::vector<PlacedTile>& tiles, std::uint32_t frame) {
  RgbImage fb(120, 48, Rgb{0xAB, 0xCD, 0xEF});
  for (const PlacedTile& t : tiles) {
    for (int r = 0; r < t.target.h; ++r) {
      for (int c = 0; c < t.target.w; ++c) {
        fb.set(t.fb_x + c, t.fb_y + r,
               pattern(t.target.display, t.target.x + c, t.target.y + r, frame));
      }
    }
  }
  return fb;
}

void send_frame(TileSender& s, const std::vector<PlacedTile>& tiles, std::uint32_t frame) {
  const RgbImage fb = render(tiles, frame);
  for (const PlacedTile& t : tiles) {
    s.send_tile(frame, t.target, fb.data() + t.fb_y * fb.stride() + t.fb_x * 3, fb.stride());
  }
  s.finish_frame(frame, static_cast<std::uint32_t>(tiles.size()));
}

ServerOptions options(std::vector<std::pair<int, int>> sizes, int pipeservers) {
  ServerOptions o;
  o.display_sizes = std::move(sizes);
  o.pipeservers = pipeservers;
  o.accept_timeout = 5000ms;
  o.stall_timeout = 5000ms;
  return o;
}

std::string first_difference(const RgbImage& got, const RgbImage& want) {
  if (got.width() != want.width() || got.height() != want.height()) return "size differs";
  for (int y = 0; y < want.height(); ++y) {
    for (int x = 0; x < want.width(); ++x) {
      const Rgb g = got.at(x, y), w = want.at(x, y);
      if (!(g == w)) {
        return fmt::format("({}, {}): got {},{},{} want {},{},{}", x, y, g.r, g.g, g.b, w.r, w.g,
                           w.b);
      }
    }
  }
  return "";
}

TEST(VizServerNet, ThreePipeserverThreadsComposeEveryPixelOfEveryFrame) {
  // Display 0 (64x32) in four 32x16 tiles, display 1 (48x40) in two 48x20 tiles; pipeserver i
  // renders tiles i and i+3, side by side in its framebuffer.
  const std::vector<TileTarget> all = {{0, 0, 0, 32, 16},   {0, 32, 0, 32, 16}, {0, 0, 16, 32, 16},
                                       {0, 32, 16, 32, 16}, {1, 0, 0, 48, 20},  {1, 0, 20, 48, 20}};
  CompositingServer server(options({{64, 32}, {48, 40}}, 3));
  server.start();
  constexpr std::uint32_t kFrames = 3;
  std::vector<std::string> thread_errors(3);
  std::vector<std::thread> threads;
  for (int id = 0; id < 3; ++id) {
    threads.emplace_back([&, id] {
      try {
        const std::vector<PlacedTile> mine = {{all[id], 2, 1}, {all[id + 3], 2 + 32 + 2 + 20, 0}};
        auto sender = TileSender::connect("127.0.0.1", server.port(), id, 2);
        for (std::uint32_t f = 0; f < kFrames; ++f) {
          send_frame(sender, mine, f);
          sender.wait_swapped(f, 5000ms);
        }
      } catch (const std::exception& e) {
        thread_errors[id] = e.what();
      }
    });
  }
  for (std::uint32_t f = 0; f < kFrames; ++f) {
    const FramePtr frame = server.wait_frame(f, 5000ms);
    ASSERT_EQ(frame->displays.size(), 2u);
    EXPECT_EQ(frame->tiles, 6u);
    for (int d = 0; d < 2; ++d) {
      const RgbImage& got = frame->displays[d];
      RgbImage want(got.width(), got.height());
      for (int y = 0; y < want.height(); ++y) {
        for (int x = 0; x < want.width(); ++x) want.set(x, y, pattern(d, x, y, f));
      }
      EXPECT_EQ(first_difference(got, want), "") << "frame " << f << " display " << d;
    }
  }
  for (auto& t : threads) t.join();
  for (const auto& e : thread_errors) EXPECT_EQ(e, "");
  EXPECT_EQ(server.counts(), StripErrorCounts{});
  EXPECT_TRUE(server.wait_finished(2000ms));  // everyone left after the last frame
  EXPECT_EQ(server.failure().reason(), "");
}

TEST(VizServerNet, LargeStridedTilesSurvivePartialSendsAndReceives) {
  // 1000x1100 tiles (3.3 MB each, 1100 row spans: more than IOV_MAX per sendmsg) cut out of a
  // wider framebuffer, from two threads at once: far more than a socket buffer holds, so
  // both ends go through partial transfers.
  constexpr int kW = 1000, kH = 1100, kFbWidth = kW + 37;
  CompositingServer server(options({{kW, kH}, {kW, kH}}, 2));
  server.start();
  std::vector<std::string> thread_errors(2);
  std::vector<std::thread> threads;
  for (int id = 0; id < 2; ++id) {
    threads.emplace_back([&, id] {
      try {
        RgbImage fb(kFbWidth, kH, Rgb{1, 2, 3});
        for (int y = 0; y < kH; ++y) {
          for (int x = 0; x < kW; ++x) fb.set(x + 37, y, pattern(id, x, y, 0));
        }
        auto sender = TileSender::connect("127.0.0.1", server.port(), id, 2);
        sender.send_tile(0, {id, 0, 0, kW, kH}, fb.data() + 37 * 3, fb.stride());
        sender.finish_frame(0, 1);
        sender.wait_swapped(0, 10000ms);
      } catch (const std::exception& e) {
        thread_errors[id] = e.what();
      }
    });
  }
  const FramePtr f = server.wait_frame(0, 10000ms);
  for (auto& t : threads) t.join();
  for (const auto& e : thread_errors) EXPECT_EQ(e, "");
  for (int d = 0; d < 2; ++d) {
    RgbImage want(kW, kH);
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) want.set(x, y, pattern(d, x, y, 0));
    }
    EXPECT_EQ(first_difference(f->displays[d], want), "") << "display " << d;
  }
}

TEST(VizServerNet, OverlapFollowsPipeserverNumberNotArrivalTime) {
  CompositingServer server(options({{16, 8}}, 2));
  server.start();
  auto s0 = TileSender::connect("127.0.0.1", server.port(), 0, 1);
  auto s1 = TileSender::connect("127.0.0.1", server.port(), 1, 1);
  const std::vector<std::uint8_t> red(8 * 8 * 3, 0), blue(8 * 8 * 3, 0), green(8 * 8 * 3, 0);
  auto fill = [](std::vector<std::uint8_t> v, int channel) {
    for (std::size_t i = static_cast<std::size_t>(channel); i < v.size(); i += 3) v[i] = 200;
    return v;
  };
  const auto r = fill(red, 0), g = fill(green, 1), b = fill(blue, 2);
  // Pipeserver 1 sends and finishes first; 0's tiles over it arrive afterwards.
  s1.send_tile(0, {0, 4, 0, 8, 8}, r.data(), 24);
  s1.finish_frame(0, 1);
  std::this_thread::sleep_for(50ms);
  s0.send_tile(0, {0, 0, 0, 8, 8}, g.data(), 24);
  s0.send_tile(0, {0, 2, 4, 8, 4}, b.data(), 24);  // later tile of 0: over its first one
  s0.finish_frame(0, 2);
  const FramePtr f = server.wait_frame(0, 5000ms);
  const RgbImage& d = f->displays[0];
  EXPECT_EQ(d.at(1, 1), (Rgb{0, 200, 0}));  // 0's first tile alone
  EXPECT_EQ(d.at(3, 5), (Rgb{0, 0, 200}));  // 0's later tile over its first
  EXPECT_EQ(d.at(5, 1), (Rgb{200, 0, 0}));  // 1 over 0's first tile
  EXPECT_EQ(d.at(6, 6), (Rgb{200, 0, 0}));  // 1 over 0's later tile
  EXPECT_EQ(d.at(12, 2), (Rgb{0, 0, 0}));   // 1's tile ends at column 11
  EXPECT_EQ(d.at(11, 2), (Rgb{200, 0, 0}));
  s0.wait_swapped(0, 2000ms);
  s1.wait_swapped(0, 2000ms);
}

TEST(VizServerNet, TilesOutsideTheirDisplayAreClippedAndCounted) {
  CompositingServer server(options({{8, 8}}, 1));
  server.start();
  auto s = TileSender::connect("127.0.0.1", server.port(), 0, 1);
  const std::vector<std::uint8_t> white(4 * 4 * 3, 255);
  s.send_tile(0, {0, 6, 6, 4, 4}, white.data(), 12);   // 2 rows partly in, 2 rows out
  s.send_tile(0, {0, -2, 0, 4, 1}, white.data(), 12);  // 1 row partly in
  s.send_tile(0, {3, 0, 0, 4, 4}, white.data(), 12);   // no display 3: 4 rows
  s.finish_frame(0, 3);
  const FramePtr f = server.wait_frame(0, 5000ms);
  EXPECT_EQ(f->counts.clips, 5u);
  EXPECT_EQ(f->counts.missing_display, 4u);
  EXPECT_EQ(server.counts().clips, 5u);
  RgbImage want(8, 8);
  want.fill_rect(6, 6, 2, 2, Rgb{255, 255, 255});
  want.fill_rect(0, 0, 2, 1, Rgb{255, 255, 255});
  EXPECT_EQ(first_difference(f->displays[0], want), "");
}

TEST(VizServerNet, BadMagicClosesOnlyThatConnectionAndNamesThePeer) {
  CompositingServer server(options({{4, 4}}, 1));
  server.start();
  Fd raw = connect_tcp("127.0.0.1", server.port(), 2000ms);
  const std::uint16_t my_port = local_port(raw.get());
  const std::string junk = "GET / HTTP/1.1\r\n\r\n";
  const iovec part{const_cast<char*>(junk.data()), junk.size()};
  send_all(raw.get(), std::span(&part, 1), Clock::now() + 1000ms, "server");
  const auto [kind, text] = first_reply(raw.get());
  ASSERT_EQ(kind, Kind::Error);
  const std::string expected =
      fmt::format("connection from 127.0.0.1:{}: bad magic 0x20544547", my_port);
  EXPECT_THAT(text, HasSubstr(expected));
  ASSERT_EQ(server.errors().size(), 1u);
  EXPECT_THAT(server.errors()[0], HasSubstr(expected));
  // The run goes on: the real pipeserver still gets its frame through.
  auto s = TileSender::connect("127.0.0.1", server.port(), 0, 1);
  s.finish_frame(0, 0);
  s.wait_swapped(0, 2000ms);
  EXPECT_EQ(server.failure().reason(), "");
}

TEST(VizServerNet, TileBeforeHelloIsRefusedBeforeItsPixelsArrive) {
  // The server allocated the announced 48 MiB and waited for them before it looked whether the
  // peer had said HELLO: twenty such strangers took it to 987 MB.
  CompositingServer server(options({{4, 4}}, 1));
  server.start();
  Fd raw = connect_tcp("127.0.0.1", server.port(), 2000ms);
  const std::uint16_t my_port = local_port(raw.get());
  send_bytes(raw.get(), encode(TileHeader{0, 0, 0, 0, 4095, 4095}));  // no pixels follow
  const std::optional<std::string> reply = read_until_closed(raw.get(), 2000ms);
  ASSERT_TRUE(reply) << "still open, waiting for the pixels";
  const std::string expected =
      fmt::format("connection from 127.0.0.1:{}: TILE before HELLO", my_port);
  EXPECT_THAT(*reply, HasSubstr(expected));
  ASSERT_EQ(server.errors().size(), 1u);
  EXPECT_EQ(server.errors()[0], expected);
  auto s = TileSender::connect("127.0.0.1", server.port(), 0, 1);
  s.finish_frame(0, 0);
  s.wait_swapped(0, 2000ms);  // the run goes on
}

TEST(VizServerNet, StrangersBeyondSixteenMakeRoomOldestFirst) {
  CompositingServer server(options({{4, 4}}, 1));
  server.start();
  std::vector<Fd> strangers;
  for (int i = 0; i < 16; ++i) {
    strangers.push_back(connect_tcp("127.0.0.1", server.port(), 2000ms));
    std::this_thread::sleep_for(5ms);  // accepted in this order
  }
  const std::uint16_t oldest = local_port(strangers[0].get());
  // The pipeserver is the seventeenth connection: the oldest stranger gives way to it.
  auto s = TileSender::connect("127.0.0.1", server.port(), 0, 1);
  s.finish_frame(0, 0);
  s.wait_swapped(0, 2000ms);
  EXPECT_EQ(read_until_closed(strangers[0].get(), 2000ms), std::string());
  EXPECT_EQ(read_until_closed(strangers[1].get(), 100ms), std::nullopt);
  ASSERT_EQ(server.errors().size(), 1u);
  EXPECT_EQ(server.errors()[0],
            fmt::format("connection from 127.0.0.1:{} closed to make room: 16 connections had not "
                        "said HELLO (1 closed so far)",
                        oldest));
}

TEST(VizServerNet, StrangerTricklingBytesIsClosedAtTheAcceptTimeout) {
  // The limit counted from the last byte received, so a byte every 100 ms kept a connection
  // that never completes HELLO open for ever.
  auto o = options({{4, 4}}, 1);
  o.accept_timeout = 400ms;
  CompositingServer server(o);
  server.start();
  auto s = TileSender::connect("127.0.0.1", server.port(), 0, 1);  // the run itself is fine
  Fd raw = connect_tcp("127.0.0.1", server.port(), 2000ms);
  const std::uint16_t my_port = local_port(raw.get());
  const auto hello = encode(Hello{0, 1});
  const auto t0 = Clock::now();
  std::optional<std::string> reply;
  for (std::size_t i = 0; i < hello.size() && !reply; ++i) {
    send_bytes(raw.get(), std::span(hello.data() + i, 1));
    reply = read_until_closed(raw.get(), 100ms);
  }
  ASSERT_TRUE(reply) << "still open after trickling a whole HELLO";
  EXPECT_LT(Clock::now() - t0, 10 * o.accept_timeout);  // room for a loaded machine
  // The ERROR itself may be lost to a reset: a byte sent as the server closes is unread there.
  ASSERT_EQ(server.errors().size(), 1u);
  EXPECT_EQ(server.errors()[0],
            fmt::format("connection from 127.0.0.1:{}: no complete HELLO within 0.4 s", my_port));
}

TEST(VizServerNet, OversizeLengthFromAPipeserverEndsTheRunWithItsName) {
  CompositingServer server(options({{4, 4}}, 1));
  server.start();
  auto s = TileSender::connect("127.0.0.1", server.port(), 0, 1);
  auto forged = encode(TileHeader{0, 0, 0, 0, 1, 1});
  put_u32(forged.data() + 8, 0xFFFFFFF0);
  const iovec part{forged.data(), forged.size()};
  send_all(s.fd(), std::span(&part, 1), Clock::now() + 1000ms, "server");
  const auto t0 = Clock::now();
  try {
    s.wait_swapped(0, 3000ms);
    FAIL() << "wait_swapped returned";
  } catch (const NetError& e) {
    EXPECT_THAT(e.what(), HasSubstr("pipeserver 0 (127.0.0.1:"));
    EXPECT_THAT(e.what(), HasSubstr("TILE payload of 4294967280 bytes, allowed 24..50307099"));
  }
  EXPECT_LT(Clock::now() - t0, 2000ms);
  EXPECT_THAT(server.failure().reason(), HasSubstr("TILE payload of 4294967280 bytes"));
  EXPECT_THROW(server.wait_frame(0, 1000ms), NetError);
}

TEST(VizServerNet, MisconfiguredPipeserversAreRefusedAtConnect) {
  CompositingServer server(options({{4, 4}, {4, 4}}, 2));
  server.start();
  try {
    TileSender::connect("127.0.0.1", server.port(), 0, 3);
    FAIL() << "connected with the wrong display count";
  } catch (const NetError& e) {
    EXPECT_THAT(e.what(), HasSubstr("HELLO from pipeserver 0 announces 3 displays, this server "
                                    "composes 2"));
  }
  auto first = TileSender::connect("127.0.0.1", server.port(), 1, 2);
  EXPECT_THROW(
      {
        try {
          TileSender::connect("127.0.0.1", server.port(), 1, 2);
        } catch (const NetError& e) {
          EXPECT_THAT(e.what(), HasSubstr("pipeserver 1 is already connected"));
          throw;
        }
      },
      NetError);
  EXPECT_THROW(TileSender::connect("127.0.0.1", server.port(), 7, 2), NetError);
  EXPECT_EQ(server.errors().size(), 3u);
  EXPECT_EQ(server.failure().reason(), "");
}

TEST(VizServerNet, ServerThatDiesIsNoticedByAWaitingPipeserver) {
  auto server = std::make_unique<CompositingServer>(options({{4, 4}}, 2));
  server->start();
  const std::uint16_t port = server->port();
  auto s = TileSender::connect("127.0.0.1", port, 0, 1);
  s.finish_frame(0, 0);
  std::thread killer([&] {
    std::this_thread::sleep_for(100ms);
    server.reset();
  });
  const auto t0 = Clock::now();
  try {
    s.wait_swapped(0, 5000ms);
    FAIL() << "wait_swapped returned";
  } catch (const NetError& e) {
    EXPECT_THAT(e.what(), HasSubstr(fmt::format("compositing server 127.0.0.1:{} closed the "
                                                "connection (waiting for SWAPPED for frame 0)",
                                                port)));
  }
  EXPECT_LT(Clock::now() - t0, 2000ms);
  killer.join();
  // Nobody listens any more: connecting gives up within its timeout.
  SenderOptions quick;
  quick.connect_timeout = 200ms;
  EXPECT_THROW(TileSender::connect("127.0.0.1", port, 0, 1, quick), NetError);
}

TEST(VizServerNet, SilentPipeserverIsReportedAfterTheStallTimeout) {
  auto o = options({{4, 4}}, 2);
  o.stall_timeout = 300ms;
  CompositingServer server(o);
  server.start();
  auto s0 = TileSender::connect("127.0.0.1", server.port(), 0, 1);
  auto s1 = TileSender::connect("127.0.0.1", server.port(), 1, 1);
  const std::vector<std::uint8_t> px(3, 9);
  s0.send_tile(0, {0, 0, 0, 1, 1}, px.data(), 3);  // ... and never FRAME_DONE
  s1.finish_frame(0, 0);
  const auto t0 = Clock::now();
  try {
    server.wait_frame(0, 5000ms);
    FAIL() << "frame 0 swapped";
  } catch (const NetError& e) {
    EXPECT_THAT(e.what(), HasSubstr("pipeserver 0 (127.0.0.1:"));
    EXPECT_THAT(e.what(), HasSubstr("sent nothing for 0.3 s while frame 0 waits for it"));
  }
  EXPECT_LT(Clock::now() - t0, 10 * o.stall_timeout);  // room for a loaded machine
  EXPECT_THROW(s1.wait_swapped(0, 2000ms), NetError);
}

TEST(VizServerNet, MissingPipeserverEndsTheRunAtTheAcceptTimeout) {
  auto o = options({{4, 4}}, 2);
  o.accept_timeout = 200ms;
  CompositingServer server(o);
  server.start();
  auto s0 = TileSender::connect("127.0.0.1", server.port(), 0, 1);
  try {
    server.wait_frame(0, 5000ms);
    FAIL() << "frame 0 swapped";
  } catch (const NetError& e) {
    EXPECT_THAT(e.what(), HasSubstr("only 1 of 2 pipeservers said HELLO within 0.2 s"));
  }
}

TEST(VizServerNet, PeerThatNeverSaysHelloIsClosedAtTheAcceptTimeout) {
  auto o = options({{4, 4}}, 1);
  o.accept_timeout = 200ms;
  CompositingServer server(o);
  server.start();
  auto s = TileSender::connect("127.0.0.1", server.port(), 0, 1);
  Fd idle = connect_tcp("127.0.0.1", server.port(), 1000ms);
  const std::uint16_t idle_port = local_port(idle.get());
  std::uint8_t head[kHeaderBytes];
  const auto t0 = Clock::now();
  recv_all(idle.get(), head, kHeaderBytes, Clock::now() + 2000ms, "server");  // its ERROR
  EXPECT_LT(Clock::now() - t0, 10 * o.accept_timeout);  // room for a loaded machine
  ASSERT_EQ(server.errors().size(), 1u);
  EXPECT_EQ(server.errors()[0], fmt::format("connection from 127.0.0.1:{}: no complete HELLO "
                                            "within 0.2 s",
                                            idle_port));
  s.finish_frame(0, 0);  // the pipeserver is unaffected
  s.wait_swapped(0, 2000ms);
}

TEST(VizServerNet, WaitingForAFrameNobodySendsEndsWhenEveryoneLeft) {
  CompositingServer server(options({{4, 4}}, 1));
  server.start();
  {
    auto s = TileSender::connect("127.0.0.1", server.port(), 0, 1);
    s.finish_frame(0, 0);
    s.wait_swapped(0, 2000ms);
  }
  EXPECT_NE(server.wait_frame(0, 1000ms), nullptr);
  const auto t0 = Clock::now();
  EXPECT_THROW(server.wait_frame(5, 5000ms), NetError);
  EXPECT_LT(Clock::now() - t0, 2000ms);
}

}  // namespace
}  // namespace l2::viz
