// Pipeservers and the server as real processes: one killed with SIGKILL mid-frame, two
// composing one frame, and the vizserver executable writing PNGs.
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "base/child_process.hpp"
#include "image/png_io.hpp"
#include "viz_link/tile_sender.hpp"
#include "vizserver/compositing_server.hpp"
#include "vizserver/display_watcher.hpp"

namespace l2::viz {
namespace {

// How long a wait for something that should happen may take before the test gives up: it
// returns as soon as it happens, so only a failing case waits this long. Generous for the
// ASan build on a loaded 2-core machine, where a process start or exit can take seconds.
constexpr auto kPatience = std::chrono::milliseconds(60000);

using namespace std::chrono_literals;
using ::testing::HasSubstr;

// A program with its stdout on a pipe, read line by line.
ChildProcess spawn(std::vector<std::string> argv) {
  return ChildProcess(std::move(argv), {}, Capture{true, false});
}

// What a shell's $? would show once it ends, nullopt while it still runs after `timeout`.
std::optional<int> exit_of(ChildProcess& child, std::chrono::milliseconds timeout) {
  const auto status = child.wait_for(timeout);
  return status ? std::optional<int>(status->shell_code()) : std::nullopt;
}

ServerOptions options(std::vector<std::pair<int, int>> sizes, int pipeservers) {
  ServerOptions o;
  o.display_sizes = std::move(sizes);
  o.pipeservers = pipeservers;
  o.accept_timeout = 5000ms;
  o.stall_timeout = 5000ms;
  return o;
}

std::vector<std::string> client(std::uint16_t port, int id, int displays, int frame,
                                std::vector<std::string> rest) {
  std::vector<std::string> args = {VIZSERVER_TEST_CLIENT, std::to_string(port), std::to_string(id),
                                   std::to_string(displays), std::to_string(frame)};
  args.insert(args.end(), rest.begin(), rest.end());
  return args;
}

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / fmt::format("vizserver-{}-{}", name, ::getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(VizServerProcess, PipeserverKilledMidFrameIsReportedWithServerAndFrame) {
  CompositingServer server(options({{16, 16}}, 2));
  server.start();
  auto s0 = TileSender::connect("127.0.0.1", server.port(), 0, 1);
  ChildProcess child = spawn(client(server.port(), 1, 1, 0, {"--hang", "0,0,0,4,4,ff0000"}));
  ASSERT_EQ(child.read_line(Stream::Out, kPatience), "sent");
  child.signal(SIGKILL);
  ASSERT_EQ(exit_of(child, 2000ms), 128 + SIGKILL);
  const auto t0 = Clock::now();
  try {
    server.wait_frame(0, kPatience);
    FAIL() << "frame 0 swapped";
  } catch (const NetError& e) {
    EXPECT_THAT(e.what(), HasSubstr("pipeserver 1 disconnected during frame 0 (1 tiles "
                                    "received, no FRAME_DONE) (127.0.0.1:"));
  }
  EXPECT_LT(Clock::now() - t0, 1000ms);
  // The surviving pipeserver learns why instead of waiting out its timeout.
  try {
    s0.wait_swapped(0, 3000ms);
    FAIL() << "frame 0 swapped";
  } catch (const NetError& e) {
    EXPECT_THAT(e.what(), HasSubstr("pipeserver 1 disconnected during frame 0"));
  }
}

TEST(VizServerProcess, TwoPipeserverProcessesComposeOneFrame) {
  CompositingServer server(options({{8, 4}, {4, 4}}, 2));
  server.start();
  ChildProcess c0 = spawn(client(server.port(), 0, 2, 7, {"0,0,0,6,4,102030", "1,0,0,4,4,405060"}));
  ChildProcess c1 = spawn(client(server.port(), 1, 2, 7, {"0,4,0,4,2,708090"}));
  EXPECT_EQ(c0.read_line(Stream::Out, kPatience), "swapped 7");
  EXPECT_EQ(c1.read_line(Stream::Out, kPatience), "swapped 7");
  EXPECT_EQ(exit_of(c0, 2000ms), 0);
  EXPECT_EQ(exit_of(c1, 2000ms), 0);
  const FramePtr f = server.wait_frame(7, 1000ms);
  RgbImage want0(8, 4), want1(4, 4, Rgb{0x40, 0x50, 0x60});
  want0.fill_rect(0, 0, 6, 4, Rgb{0x10, 0x20, 0x30});
  want0.fill_rect(4, 0, 4, 2, Rgb{0x70, 0x80, 0x90});  // pipeserver 1 wins the overlap
  EXPECT_EQ(f->displays[0], want0);
  EXPECT_EQ(f->displays[1], want1);
}

TEST(VizServerProcess, ExecutableWritesThePngsOfEachFrame) {
  const auto dir = fresh_dir("exe");
  ChildProcess exe = spawn({VIZSERVER_EXE, "--displays", "16x8,8x8", "--pipeservers", "1",
                            "--viz-port", "0", "--frames", "1", "--out", dir.string()});
  const auto line = exe.read_line(Stream::Out, kPatience).value_or("");
  ASSERT_THAT(line, HasSubstr("listening on 127.0.0.1:"));
  const auto port = static_cast<std::uint16_t>(std::stoi(line.substr(line.rfind(':') + 1)));
  auto s = TileSender::connect("127.0.0.1", port, 0, 2);
  // A 3x2 gradient tile on display 0 taken from inside a 5-pixel-wide framebuffer row.
  std::vector<std::uint8_t> fb(5 * 2 * 3, 0xEE);
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 3; ++c) {
      std::uint8_t* p = fb.data() + (r * 5 + 1 + c) * 3;
      p[0] = static_cast<std::uint8_t>(10 * c);
      p[1] = static_cast<std::uint8_t>(100 + r);
      p[2] = 5;
    }
  }
  s.send_tile(0, {0, 13, 6, 3, 2}, fb.data() + 3, 15);
  const std::vector<std::uint8_t> grey(8 * 8 * 3, 128);
  s.send_tile(0, {1, 0, 0, 8, 8}, grey.data(), 24);
  s.finish_frame(0, 2);
  s.wait_swapped(0, kPatience);
  EXPECT_EQ(exe.read_line(Stream::Out, kPatience),
            "swapped frame 0: 2 tiles, 0 clipped rows, 0 rows for missing displays");
  EXPECT_EQ(exit_of(exe, kPatience), 0);
  RgbImage want0(16, 8);
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 3; ++c) {
      want0.set(13 + c, 6 + r,
                Rgb{static_cast<std::uint8_t>(10 * c), static_cast<std::uint8_t>(100 + r), 5});
    }
  }
  EXPECT_EQ(read_png(dir / "display-0-frame-0.png"), want0);
  EXPECT_EQ(read_png(dir / "display-1-frame-0.png"), RgbImage(8, 8, Rgb{128, 128, 128}));
  std::filesystem::remove_all(dir);
}

TEST(VizServerProcess, ExecutableExitsNonZeroWhenAPipeserverDies) {
  const auto dir = fresh_dir("dies");
  ChildProcess exe = spawn({VIZSERVER_EXE, "--displays", "8x8", "--pipeservers", "1", "--frames",
                            "1", "--out", dir.string()});
  const auto line = exe.read_line(Stream::Out, kPatience).value_or("");
  ASSERT_THAT(line, HasSubstr("listening on 127.0.0.1:"));
  const auto port = static_cast<std::uint16_t>(std::stoi(line.substr(line.rfind(':') + 1)));
  ChildProcess pipeserver = spawn(client(port, 0, 1, 0, {"--hang", "0,0,0,2,2,ffffff"}));
  ASSERT_EQ(pipeserver.read_line(Stream::Out, kPatience), "sent");
  pipeserver.signal(SIGKILL);
  EXPECT_EQ(exit_of(exe, 3000ms), 1);
  EXPECT_FALSE(std::filesystem::exists(dir / "display-0-frame-0.png"));
  std::filesystem::remove_all(dir);
}

// The way l2wall runs it: no PNGs, the displays streamed back to whoever started it, and the
// port it bound told on the stream before any pipeserver connects.
TEST(VizServerProcess, ExecutableStreamsEveryFrameToItsWatcher) {
  const auto dir = fresh_dir("stream");
  const Fd listener = listen_tcp("127.0.0.1", 0);
  ChildProcess exe =
      spawn({VIZSERVER_EXE, "--displays", "8x4", "--pipeservers", "1", "--frames", "2",
             "--display-stream", fmt::format("127.0.0.1:{}", local_port(listener.get())), "--log",
             (dir / "log.txt").string()});
  Fd stream = accept_within(listener, kPatience);
  ASSERT_TRUE(stream);
  const Listening l = read_listening(stream.get(), Clock::now() + kPatience, "vizserver");
  EXPECT_EQ(l.display_count, 1u);
  EXPECT_EQ(l.pipeserver_count, 1u);
  DisplayWatcher watcher(std::move(stream), "vizserver", l.display_count);
  auto s = TileSender::connect("127.0.0.1", static_cast<std::uint16_t>(l.port), 0, 1);
  for (std::uint32_t k = 0; k < 2; ++k) {
    const std::vector<std::uint8_t> tile(4 * 4 * 3, static_cast<std::uint8_t>(0x40 + k));
    s.send_tile(k, {0, 2, 0, 4, 4}, tile.data(), 12);
    s.finish_frame(k, 1);
    s.wait_swapped(k, kPatience);
    const FramePtr f = watcher.take(k, kPatience);
    ASSERT_TRUE(f) << "frame " << k;
    RgbImage want(8, 4);
    want.fill_rect(2, 0, 4, 4,
                   Rgb{static_cast<std::uint8_t>(0x40 + k), static_cast<std::uint8_t>(0x40 + k),
                       static_cast<std::uint8_t>(0x40 + k)});
    EXPECT_EQ(f->displays.at(0), want) << "frame " << k;
  }
  EXPECT_EQ(exit_of(exe, kPatience), 0);
  EXPECT_EQ(exe.read_line(Stream::Out, 100ms), std::nullopt) << "lines go to --log, not stdout";
  std::ifstream log(dir / "log.txt");
  std::string first;
  std::getline(log, first);
  EXPECT_EQ(first, fmt::format("listening on 127.0.0.1:{}", l.port));
  std::filesystem::remove_all(dir);
}

TEST(VizServerProcess, APortItCannotBindReachesTheWatcherAsError) {
  const Fd taken = listen_tcp("127.0.0.1", 0);
  const Fd listener = listen_tcp("127.0.0.1", 0);
  ChildProcess exe = spawn({VIZSERVER_EXE, "--displays", "8x4", "--pipeservers", "1", "--viz-port",
                            std::to_string(local_port(taken.get())), "--display-stream",
                            fmt::format("127.0.0.1:{}", local_port(listener.get()))});
  Fd stream = accept_within(listener, kPatience);
  ASSERT_TRUE(stream);
  try {
    read_listening(stream.get(), Clock::now() + kPatience, "vizserver");
    FAIL() << "it listened on a taken port";
  } catch (const NetError& e) {
    EXPECT_THAT(e.what(), HasSubstr(fmt::format("vizserver: cannot listen on 127.0.0.1:{}: ",
                                                local_port(taken.get()))));
  }
  EXPECT_EQ(exit_of(exe, kPatience), 1);
}

TEST(VizServerProcess, ExecutableEndsWhenItsWatcherGoesAway) {
  Fd listener = listen_tcp("127.0.0.1", 0);
  ChildProcess exe =
      spawn({VIZSERVER_EXE, "--displays", "8x4", "--pipeservers", "1", "--display-stream",
             fmt::format("127.0.0.1:{}", local_port(listener.get()))});
  Fd stream = accept_within(listener, kPatience);
  ASSERT_TRUE(stream);
  read_listening(stream.get(), Clock::now() + kPatience, "vizserver");
  stream.reset();  // l2wall died: no one is left to compose for
  EXPECT_EQ(exit_of(exe, 3000ms), 1);
}

// How l2wall starts it: the run's token in its environment. A HELLO without the token is
// refused; the pipeserver with it composes the frame.
TEST(VizServerProcess, ExecutableWithARunTokenRefusesAHelloWithoutIt) {
  const auto dir = fresh_dir("token");
  const RunToken token = new_run_token();
  ::setenv(kTokenVariable, token_text(token).c_str(), 1);
  ChildProcess exe = spawn({VIZSERVER_EXE, "--displays", "4x4", "--pipeservers", "1", "--frames",
                            "1", "--out", dir.string()});
  ::unsetenv(kTokenVariable);
  const auto line = exe.read_line(Stream::Out, kPatience).value_or("");
  ASSERT_THAT(line, HasSubstr("listening on 127.0.0.1:"));
  const auto port = static_cast<std::uint16_t>(std::stoi(line.substr(line.rfind(':') + 1)));
  EXPECT_THROW(TileSender::connect("127.0.0.1", port, 0, 1), NetError);
  SenderOptions with_token;
  with_token.token = token;
  auto s = TileSender::connect("127.0.0.1", port, 0, 1, with_token);
  s.finish_frame(0, 0);
  s.wait_swapped(0, kPatience);
  EXPECT_EQ(exit_of(exe, kPatience), 0);
  std::filesystem::remove_all(dir);
}

// A pipeserver paced by the compositing server alone (no back-channel) waits for the swap of
// frame 0 as long as one paced by READY does: that swap also waits for the other pipeservers'
// start-up. With 250 ms waits it gave up after 1 s ("timed out (waiting for SWAPPED for frame
// 0)"), while the run's other hosts were still starting on a loaded machine. The other three
// pipeservers of the default wall (four 640x480 displays) come 1.5 s late here; frame 0 is the
// last frame of the first run and the first of two in the second.
TEST(VizServerProcess, APipeserverWaitsForTheOthersStartUpBeforeItsFirstSwap) {
  for (const int frames : {1, 2}) {
    const auto dir = fresh_dir(fmt::format("late-start-{}", frames));
    ChildProcess exe =
        spawn({VIZSERVER_EXE, "--displays", "640x480,640x480,640x480,640x480", "--pipeservers", "4",
               "--viz-port", "0", "--frames", std::to_string(frames), "--accept-timeout", "20000",
               "--out", dir.string()});
    const auto line = exe.read_line(Stream::Out, kPatience).value_or("");
    ASSERT_THAT(line, HasSubstr("listening on 127.0.0.1:"));
    const auto port = static_cast<std::uint16_t>(std::stoi(line.substr(line.rfind(':') + 1)));
    ChildProcess pipeserver(
        {PIPESERVER_EXE, "--live", "--pipeserver", "0", "--frames", std::to_string(frames), "--viz",
         fmt::format("127.0.0.1:{}", port), "--ready-timeout", "250", "--report",
         (dir / "pipeserver-0.log").string()},
        {}, Capture{false, true});
    std::this_thread::sleep_for(1500ms);
    std::vector<TileSender> late;
    for (int id = 1; id < 4; ++id) late.push_back(TileSender::connect("127.0.0.1", port, id, 4));
    for (int k = 0; k < frames; ++k) {
      const auto frame = static_cast<std::uint32_t>(k);
      for (TileSender& s : late) s.finish_frame(frame, 0);
      for (TileSender& s : late) s.wait_swapped(frame, 20000ms);
    }
    const Finished f = pipeserver.finish(20000ms);
    EXPECT_EQ(f.status.shell_code(), 0) << frames << " frames: " << f.err;
    EXPECT_EQ(exit_of(exe, kPatience), 0) << frames << " frames";
    std::filesystem::remove_all(dir);
  }
}

TEST(VizServerProcess, ExecutableHelpAndBadArguments) {
  ChildProcess help = spawn({VIZSERVER_EXE, "--help"});
  std::string text;
  while (auto l = help.read_line(Stream::Out, kPatience)) text += *l + "\n";
  EXPECT_EQ(exit_of(help, kPatience), 0);
  for (const char* opt :
       {"--displays", "--pipeservers", "--viz-port", "--viz-host", "--frames", "--out",
        "--accept-timeout", "--stall-timeout", "--display-stream", "--log"}) {
    EXPECT_THAT(text, HasSubstr(opt));
  }
  ChildProcess bad =
      spawn({VIZSERVER_EXE, "--displays", "16y8", "--pipeservers", "1", "--out", "/tmp/x"});
  EXPECT_EQ(exit_of(bad, kPatience), 2);
  ChildProcess nowhere = spawn({VIZSERVER_EXE, "--displays", "16x8", "--pipeservers", "1"});
  EXPECT_EQ(exit_of(nowhere, kPatience), 2);  // neither --out nor --display-stream
  ChildProcess bad_stream = spawn(
      {VIZSERVER_EXE, "--displays", "16x8", "--pipeservers", "1", "--display-stream", "localhost"});
  EXPECT_EQ(exit_of(bad_stream, kPatience), 2);
  // An --out folder that cannot be made ends the run before it listens (it failed only at the
  // first swap, after the pipeservers had connected).
  ChildProcess bad_out = spawn(
      {VIZSERVER_EXE, "--displays", "16x8", "--pipeservers", "1", "--out", "/etc/passwd/frames"});
  EXPECT_EQ(bad_out.read_line(Stream::Out, kPatience), std::nullopt);  // no "listening on" line
  EXPECT_EQ(exit_of(bad_out, kPatience), 1);
}

}  // namespace
}  // namespace l2::viz
