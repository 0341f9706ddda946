// The display stream (compositing server -> l2wall): its bytes, and DisplaySender against
// DisplayWatcher over real sockets on 127.0.0.1 with the sender on its own thread — every pixel
// of every frame arrives, a slow watcher holds the sender back, and every way the stream can
// end is reported. Also the SwapQueue between the server thread and its writer. In the TSan
// run: the watcher's reader thread and the queue are what l2wall and vizserver share threads by.
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/socket.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "display_sender.hpp"
#include "swap_queue.hpp"
#include "vizserver/display_stream.hpp"
#include "vizserver/display_watcher.hpp"

namespace l2::viz {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

// The colour the test expects at (x, y) of `display` in `frame`, chosen here.
Rgb pattern(int display, int x, int y, std::uint32_t frame) {
  return {static_cast<std::uint8_t>(x * 5 + display * 70), static_cast<std::uint8_t>(y * 3 + 7),
          static_cast<std::uint8_t>(frame * 11 + 1)};
}

ComposedFrame make_frame(std::uint32_t number, const std::vector<std::pair<int, int>>& sizes) {
  ComposedFrame f;
  f.frame = number;
  f.tiles = 3 + number;
  f.counts.clips = 2;
  f.counts.missing_display = 1;
  for (std::size_t d = 0; d < sizes.size(); ++d) {
    RgbImage image(sizes[d].first, sizes[d].second);
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x)
        image.set(x, y, pattern(static_cast<int>(d), x, y, number));
    f.displays.push_back(std::move(image));
  }
  return f;
}

// Both ends of one stream: the sender's end is connected (on this thread, as the server would
// from its own process), the watcher's accepted and its LISTENING read.
struct StreamPair {
  Fd listener = listen_tcp("127.0.0.1", 0);
  std::optional<DisplaySender> sender;
  Fd accepted;
  Listening listening;

  StreamPair() {
    sender.emplace(DisplaySender::connect("127.0.0.1", local_port(listener.get())));
    sender->send_listening({4321, 2, 3});
    accepted = accept_within(listener, 5000ms);
    listening = read_listening(accepted.get(), Clock::now() + 5000ms, "test stream");
  }
};

TEST(DisplayStreamWire, ListeningDisplayAndShownBytes) {
  const auto l = encode(Listening{0x1234, 2, 3});
  // "L2VZ", version 2, kind 16, payload 12, then the three u32s, all little-endian.
  const std::vector<std::uint8_t> want{'L',  '2',  'V', 'Z', 2, 0, 16, 0, 12, 0, 0, 0,
                                       0x34, 0x12, 0,   0,   2, 0, 0,  0, 3,  0, 0, 0};
  EXPECT_EQ(std::vector<std::uint8_t>(l.begin(), l.end()), want);
  const auto d = encode(DisplayHeader{7, 1, 640, 480});
  EXPECT_EQ(d[6], 17);
  EXPECT_EQ(get_u32(d.data() + 8), 16u + 640 * 480 * 3);
  const auto s = encode(Shown{7, 4, 16, 2, 1});
  EXPECT_EQ(s[6], 18);
  EXPECT_EQ(get_u32(s.data() + 8), 20u);
  EXPECT_EQ(get_u32(s.data() + 24), 2u);
}

TEST(DisplayStreamWire, RefusesOtherKindsAndImpossibleSizes) {
  auto header = encode(DisplayHeader{0, 0, 4, 4});
  put_u16(header.data() + 6, 3);  // a TILE of the pipeserver protocol
  const auto tile =
      decode_header(std::span<const std::uint8_t, kHeaderBytes>(header.data(), kHeaderBytes),
                    Protocol::DisplayStream);
  ASSERT_FALSE(tile.ok());
  EXPECT_EQ(tile.reason(), "message kind 3 is not one of the display stream");
  put_u16(header.data() + 6, 18);  // SHOWN claiming more than its fixed 20 bytes
  put_u32(header.data() + 8, 21);
  const auto shown =
      decode_header(std::span<const std::uint8_t, kHeaderBytes>(header.data(), kHeaderBytes),
                    Protocol::DisplayStream);
  ASSERT_FALSE(shown.ok());
  EXPECT_EQ(shown.reason(), "SHOWN payload of 21 bytes, allowed 20..20");
  EXPECT_EQ(validate(DisplayHeader{0, 0, 0, 4}, 16).reason(),
            "DISPLAY of 0x4 pixels, each side must be 1..16384");
  EXPECT_EQ(validate(DisplayHeader{0, 0, 2, 2}, 16 + 11).reason(),
            "DISPLAY 2x2 needs a payload of 28 bytes, header says 27");
  EXPECT_TRUE(validate(DisplayHeader{0, 0, 2, 2}, 28).ok());
}

TEST(DisplayStream, EveryPixelOfEveryFrameArrivesAndTheEndIsReported) {
  const std::vector<std::pair<int, int>> sizes{{16, 8}, {8, 4}};
  StreamPair p;
  EXPECT_EQ(p.listening.port, 4321u);
  EXPECT_EQ(p.listening.display_count, 2u);
  EXPECT_EQ(p.listening.pipeserver_count, 3u);
  std::thread server([&] {
    for (std::uint32_t k = 0; k < 5; ++k) p.sender->send_frame(make_frame(k, sizes));
    p.sender.reset();  // closes: the end of the stream
  });
  DisplayWatcher watcher(std::move(p.accepted), "test stream", p.listening.display_count, 2);
  for (std::uint32_t k = 0; k < 5; ++k) {
    const FramePtr f = watcher.take(k, 5000ms);
    ASSERT_TRUE(f) << "frame " << k;
    EXPECT_EQ(f->frame, k);
    EXPECT_EQ(f->tiles, 3 + k);
    EXPECT_EQ(f->counts.clips, 2u);
    EXPECT_EQ(f->counts.missing_display, 1u);
    ASSERT_EQ(f->displays.size(), 2u);
    for (int d = 0; d < 2; ++d) {
      const RgbImage& image = f->displays[static_cast<std::size_t>(d)];
      ASSERT_EQ(image.width(), sizes[static_cast<std::size_t>(d)].first);
      ASSERT_EQ(image.height(), sizes[static_cast<std::size_t>(d)].second);
      for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
          ASSERT_EQ(image.at(x, y), pattern(d, x, y, k)) << "frame " << k << " display " << d;
    }
  }
  server.join();
  try {
    watcher.take(5, 2000ms);
    FAIL() << "frame 5 arrived";
  } catch (const NetError& e) {
    EXPECT_STREQ(e.what(), "test stream closed the connection");
  }
  EXPECT_FALSE(watcher.ended_with_error_message());
}

// The most a TCP send buffer may grow to here (autotuning's limit, tcp_wmem's third field).
std::size_t send_buffer_limit() {
  std::ifstream in("/proc/sys/net/ipv4/tcp_wmem");
  std::size_t min = 0, initial = 0, max = 0;
  in >> min >> initial >> max;
  return max > 0 ? max : 4u << 20;
}

TEST(DisplayStream, ASlowWatcherHoldsTheSenderBack) {
  // 3 MB frames. The receive buffer is fixed small: left to autotuning it may grow to
  // tcp_rmem's limit (32 MB here, ten frames), which hid the flow control in a CI run.
  const std::vector<std::pair<int, int>> sizes{{1024, 1024}};
  const std::size_t frame_bytes = 1024u * 1024u * 3u;
  StreamPair p;
  const int wanted = 256 << 10;
  ASSERT_EQ(setsockopt(p.accepted.get(), SOL_SOCKET, SO_RCVBUF, &wanted, sizeof wanted), 0);
  int receive_buffer = 0;
  socklen_t length = sizeof receive_buffer;
  ASSERT_EQ(getsockopt(p.accepted.get(), SOL_SOCKET, SO_RCVBUF, &receive_buffer, &length), 0);
  // What may be ahead of the watcher's takes: the 2 frames it holds, what both socket buffers
  // can hold (rounded up to whole frames), and the frame the sender is in the middle of.
  const std::size_t buffered = static_cast<std::size_t>(receive_buffer) + send_buffer_limit();
  const int bound = 2 + static_cast<int>((buffered + frame_bytes - 1) / frame_bytes) + 1;
  ASSERT_LT(bound, 12) << "the buffers alone could hold every frame: nothing to show";
  std::atomic<int> sent{0};
  std::thread server([&] {
    const ComposedFrame f = make_frame(0, sizes);
    for (std::uint32_t k = 0; k < 12; ++k) {
      ComposedFrame next = f;
      next.frame = k;
      p.sender->send_frame(next);
      ++sent;
    }
  });
  DisplayWatcher watcher(std::move(p.accepted), "test stream", p.listening.display_count, 2);
  // Until the sender stops getting further (slow under TSan on a loaded machine: no fixed sleep).
  int ahead = 0;
  for (const auto deadline = Clock::now() + 15s; Clock::now() < deadline;) {
    const int before = sent.load();
    std::this_thread::sleep_for(300ms);
    ahead = sent.load();
    if (ahead == before && ahead >= 2) break;
  }
  EXPECT_GE(ahead, 2);
  EXPECT_LE(ahead, bound) << "the watcher holds 2 frames, the socket buffers " << buffered / 1024
                          << " KiB; the rest must wait for it";
  for (std::uint32_t k = 0; k < 12; ++k) EXPECT_TRUE(watcher.take(k, 5000ms)) << "frame " << k;
  server.join();
  EXPECT_EQ(sent.load(), 12);
}

TEST(DisplayStream, TheServersErrorLineEndsTheStream) {
  StreamPair p;
  p.sender->send_frame(make_frame(0, {{4, 4}}));
  p.sender->send_error("pipeserver 2 disconnected during frame 1");
  DisplayWatcher watcher(std::move(p.accepted), "test stream", p.listening.display_count);
  EXPECT_TRUE(watcher.take(0, 5000ms));
  try {
    watcher.take(1, 5000ms);
    FAIL() << "frame 1 arrived";
  } catch (const NetError& e) {
    EXPECT_STREQ(e.what(), "pipeserver 2 disconnected during frame 1");
  }
  EXPECT_TRUE(watcher.ended_with_error_message());
}

TEST(DisplayStream, ASkippedFrameIsNamed) {
  StreamPair p;
  p.sender->send_frame(make_frame(0, {{4, 4}}));
  p.sender->send_frame(make_frame(2, {{4, 4}}));
  DisplayWatcher watcher(std::move(p.accepted), "test stream", p.listening.display_count);
  EXPECT_TRUE(watcher.take(0, 5000ms));
  try {
    watcher.take(1, 5000ms);
    FAIL() << "frame 1 arrived";
  } catch (const NetError& e) {
    EXPECT_STREQ(e.what(), "test stream: frame 1 is not in the stream (it went on to frame 2)");
  }
  EXPECT_TRUE(watcher.take(2, 5000ms));
}

TEST(DisplayStream, MoreDisplaysThanAnnouncedBreakTheProtocol) {
  // LISTENING said 2 displays; DISPLAY messages of one frame were taken without a bound before
  // its SHOWN, up to 768 MiB each.
  StreamPair p;
  p.sender->send_frame(make_frame(0, {{4, 4}, {4, 4}, {4, 4}}));
  DisplayWatcher watcher(std::move(p.accepted), "test stream", p.listening.display_count);
  try {
    watcher.take(0, 5000ms);
    FAIL() << "frame 0 arrived";
  } catch (const NetError& e) {
    EXPECT_STREQ(e.what(),
                 "test stream: DISPLAY 2 of frame 0, but the stream announced 2 displays");
  }
}

TEST(DisplayStream, AMessageCutOffByTheServersDeathIsNamed) {
  Fd listener = listen_tcp("127.0.0.1", 0);
  Fd raw = connect_tcp("127.0.0.1", local_port(listener.get()), 5000ms);
  Fd accepted = accept_within(listener, 5000ms);
  const auto head = encode(DisplayHeader{0, 0, 4, 4});
  const std::uint8_t some_pixels[10] = {};
  const iovec parts[] = {{const_cast<std::uint8_t*>(head.data()), head.size()},
                         {const_cast<std::uint8_t*>(some_pixels), sizeof some_pixels}};
  send_all(raw.get(), parts, Clock::now() + 5000ms, "test");
  raw.reset();
  DisplayWatcher watcher(std::move(accepted), "test stream", 1);
  try {
    watcher.take(0, 5000ms);
    FAIL() << "frame 0 arrived";
  } catch (const NetError& e) {
    EXPECT_STREQ(e.what(), "test stream closed the connection in the middle of a DISPLAY message");
  }
  EXPECT_FALSE(watcher.ended_with_error_message());
}

TEST(SwapQueue, AFullQueueHoldsTheServerThreadUntilTakenOrClosed) {
  SwapQueue queue(2);
  std::atomic<int> pushed{0};
  std::thread server([&] {
    for (std::uint32_t k = 0; k < 4; ++k) {
      auto f = std::make_shared<ComposedFrame>();
      f->frame = k;
      queue.push(f);
      ++pushed;
    }
  });
  std::this_thread::sleep_for(200ms);
  EXPECT_EQ(pushed.load(), 2);
  for (std::uint32_t k = 0; k < 3; ++k) {
    const FramePtr f = queue.pop(5000ms);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->frame, k);
  }
  server.join();  // the fourth went in once there was room
  EXPECT_EQ(queue.pop(5000ms)->frame, 3u);
  EXPECT_FALSE(queue.pop(10ms));

  // Closed: a push into a full queue no longer waits, so the server thread can always stop.
  SwapQueue full(1);
  full.push(std::make_shared<ComposedFrame>());
  std::thread stuck([&] { full.push(std::make_shared<ComposedFrame>()); });
  std::this_thread::sleep_for(50ms);
  full.close();
  stuck.join();
}

}  // namespace
}  // namespace l2::viz
