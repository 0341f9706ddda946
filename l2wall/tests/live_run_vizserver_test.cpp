// `l2wall run` and its compositing server, a `vizserver` process of its own: it listens where
// --viz-host and --viz-port say; killed with SIGKILL on the vizserver path alone and on both
// paths, or unable to bind --viz-port, it is named with the frame, the run keeps the displays it
// has, leaves no process or shm segment behind and exits non-zero; stopped (hung), it is named
// rather than the pipeservers that gave up on it. Real processes and sockets.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "image/png_io.hpp"
#include "l2wall/frame_stamp.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace testing_support;

// The frame a display picture of the `swap` scene shows: frame k is its clear colour everywhere
// (pipeserver's scene.hpp), ((64 + 37k), (128 + 101k), (192 + 173k)) mod 256, so k up to 255.
// -1 when the picture is not one such colour throughout.
int frame_shown(const fs::path& picture_dir, const std::string& suffix) {
  const RgbImage shown = read_png(picture_dir / fmt::format("display-0{}.png", suffix));
  for (int k = 0; k < 256; ++k) {
    const Rgb colour{static_cast<std::uint8_t>((64 + 37 * k) % 256),
                     static_cast<std::uint8_t>((128 + 101 * k) % 256),
                     static_cast<std::uint8_t>((192 + 173 * k) % 256)};
    bool all = true;
    for (int y = 0; y < shown.height() && all; ++y)
      for (int x = 0; x < shown.width() && all; ++x) all = shown.at(x, y) == colour;
    if (all) return k;
  }
  return -1;
}

// Waits until the run has kept frame `frame` (--keep K: its last picture is written just
// before the run counts it as shown). Returns the pid of the run's compositing server.
pid_t vizserver_after(const WallRun& run, int frame, const std::string& last_picture) {
  const auto deadline = std::chrono::steady_clock::now() + 20s;
  const fs::path picture = run.out() / fmt::format("frame-{}", frame) / last_picture;
  while (std::chrono::steady_clock::now() < deadline) {
    const auto servers = run.vizservers();
    if (servers.size() == 1 && fs::exists(picture)) return servers.front();
    std::this_thread::sleep_for(20ms);
  }
  return -1;
}

class KilledVizserver : public ::testing::TestWithParam<const char*> {};

TEST_P(KilledVizserver, IsNamedWithItsFrameAndEverythingIsCleanedUp) {
  const std::string path = GetParam();
  // A long READY timeout: on a loaded machine the pipeservers must not give up on their own
  // before the compositing server is killed (this test is about that kill).
  WallRun run("viz-killed-" + path, {"--scene", "swap", "--frames", "100000", "--path", path,
                                     "--keep", "3", "--ready-timeout", "10000"});
  const pid_t server = vizserver_after(run, 3, path == "both" ? "wall-vizserver.png" : "wall.png");
  ASSERT_GT(server, 0) << run.output();
  ASSERT_EQ(kill(server, SIGKILL), 0);
  const auto t0 = std::chrono::steady_clock::now();
  const ExitStatus status = run.wait(20s);
  // Well under a second on a quiet machine; room for a CI machine running two such tests.
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 10s);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << output;
  const std::string said = fmt::format(
      "l2wall: compositing server (vizserver pid {}) killed by signal 9 (Killed) at "
      "frame ",
      server);
  const auto at = output.find(said);
  ASSERT_NE(at, std::string::npos) << output;
  int frame = -1, kept = -1, kept_by_viz = -1;
  const int fields =
      std::sscanf(output.c_str() + at + said.size(),
                  "%d; the displays keep frame %d (DVI path) and frame %d (vizserver path)", &frame,
                  &kept, &kept_by_viz);
  ASSERT_GE(fields, 2) << output.substr(at);
  if (fields == 2) kept_by_viz = kept;
  EXPECT_GE(frame, 3) << "frame 3 was kept before the kill";
  EXPECT_EQ(kept_by_viz, frame - 1);
  // The displays it kept show what it said, read from the pixels: the vizserver's own pictures
  // on its path alone. With both paths the emulator's may be a frame ahead (it swapped frame K
  // while the run waited for the compositing server's K), and the vizserver's are beside them.
  const fs::path fault = run.out() / "fault";
  EXPECT_EQ(frame_shown(fault, ""), kept) << output;
  if (path == "both") {
    EXPECT_TRUE(kept == frame - 1 || kept == frame) << output;
    EXPECT_EQ(frame_shown(fault, "-vizserver"), kept_by_viz) << output;
  }
  EXPECT_NE(output.find("l2wall: displays as they were: "), std::string::npos) << output;
  expect_clean(run);
}

INSTANTIATE_TEST_SUITE_P(Paths, KilledVizserver, ::testing::Values("vizserver", "both"));

// A compositing server that hangs (stopped, its socket open): the pipeservers give up waiting
// for SWAPPED (ready-timeout x retries) and exit with "lost the compositing server"; the run
// names the server, not them. The stall timeout is set long so that only this can fire.
TEST(LiveRun, HungCompositingServerIsNamedNotThePipeserversThatGaveUp) {
  WallRun run("viz-hung", {"--frames", "100000", "--path", "vizserver", "--keep", "3",
                           "--ready-timeout", "500", "--stall-timeout", "60000"});
  const pid_t server = vizserver_after(run, 3, "wall.png");
  ASSERT_GT(server, 0) << run.output();
  ASSERT_EQ(kill(server, SIGSTOP), 0);
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << output;
  EXPECT_NE(output.find(fmt::format("l2wall: the compositing server (vizserver pid {}) stopped "
                                    "answering: pipeserver ",
                                    server)),
            std::string::npos)
      << output;
  EXPECT_NE(output.find("gave up waiting for it at frame "), std::string::npos) << output;
  EXPECT_EQ(output.find("exited with code"), std::string::npos) << output;
  expect_clean(run);  // a stopped process still ends on SIGKILL
}

TEST(LiveRun, AVizPortInUseIsNamedAndNothingIsLeft) {
  const HeldPort held;  // as another program would
  const int port = held.port;
  WallRun run("viz-port",
              {"--frames", "3", "--path", "vizserver", "--viz-port", std::to_string(port)});
  const ExitStatus status = run.wait(10s);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << output;
  EXPECT_NE(output.find(fmt::format("cannot listen on 127.0.0.1:{}: Address already in use", port)),
            std::string::npos)
      << output;
  EXPECT_TRUE(run.vizservers().empty());
  expect_clean(run);
}

// The compositing server listens where --viz-host and --viz-port say (here every interface, on
// a port that was free a moment ago), says so in its log, and the local pipeservers still reach it.
TEST(LiveRun, CompositingServerListensOnTheHostAndPortAsked) {
  int port = 0;
  {
    const HeldPort probe;
    port = probe.port;
  }
  WallRun run("viz-where", {"--frames", "2", "--path", "vizserver", "--viz-host", "0.0.0.0",
                            "--viz-port", std::to_string(port)});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  const std::string log = slurp(run.out() / "vizserver.log");
  EXPECT_EQ(log.substr(0, log.find('\n')), fmt::format("listening on 0.0.0.0:{}", port)) << log;
  EXPECT_NE(log.find("swapped frame 1: 16 tiles"), std::string::npos) << log;
  expect_clean(run);
}

}  // namespace
}  // namespace l2
