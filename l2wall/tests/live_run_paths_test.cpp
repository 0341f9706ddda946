// `l2wall run` end to end on the DVI and vizserver paths: real pipeserver processes, shared
// memory, ptys and sockets.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "image/png_io.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace testing_support;

// The `swap` scene draws nothing: frame k is its clear colour everywhere (as pipeserver's
// scene.hpp defines it), so a kept picture says which frame it is by every pixel.
Rgb swap_colour(int k) {
  return {static_cast<std::uint8_t>((64 + 37 * k) % 256),
          static_cast<std::uint8_t>((128 + 101 * k) % 256),
          static_cast<std::uint8_t>((192 + 173 * k) % 256)};
}

// Pixels of `picture` that are not frame k's colour.
long not_of_frame(const RgbImage& picture, int k) {
  long other = 0;
  for (int y = 0; y < picture.height(); ++y)
    for (int x = 0; x < picture.width(); ++x) other += !(picture.at(x, y) == swap_colour(k));
  return other;
}

TEST(LiveRun, EveryDisplayFrameShowsTheInputFrameOneRefreshEarlier) {
  const int frames = 6;
  WallRun run("latency", {"--scene", "swap", "--frames", std::to_string(frames), "--refresh", "0",
                          "--keep", "every"});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  EXPECT_NE(output.find("latency: 1 frame "), std::string::npos) << output;
  EXPECT_NE(output.find("6 frames on 4 displays from 4 pipeservers"), std::string::npos) << output;
  // The pictures kept during the run (--keep every) took time the run's seconds include: the
  // pipeservers render the next frame meanwhile, so leaving it out would overstate the frame rate.
  std::smatch run_s, writing_s;
  ASSERT_TRUE(std::regex_search(output, run_s, std::regex("pipeservers in ([0-9.]+) s: ")));
  ASSERT_TRUE(std::regex_search(output, writing_s,
                                std::regex("of which ([0-9.]+) s writing the pictures saved")))
      << output;
  EXPECT_GT(std::stod(writing_s[1]), 0.0);
  EXPECT_GE(std::stod(run_s[1]), std::stod(writing_s[1])) << output;

  const auto rows = read_csv(run.out() / "report.csv");
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(frames + 1));
  ASSERT_EQ(rows[0][3], "latency_frames");
  for (int k = 1; k <= frames; ++k) {
    EXPECT_EQ(rows[k][0], std::to_string(k - 1));
    EXPECT_EQ(std::stoi(rows[k][2]) - std::stoi(rows[k][1]), 1) << "frame " << k - 1;
    EXPECT_EQ(rows[k][3], "1");
  }
  // Independently of the run's own bookkeeping: each kept display picture is, in every pixel,
  // the frame it was kept for (no frame stamp marks it: the stamps ride in the stamp strips).
  for (int k = 0; k < frames; ++k) {
    for (int d = 0; d < 4; ++d) {
      const RgbImage shown =
          read_png(run.out() / fmt::format("frame-{}", k) / fmt::format("display-{}.png", d));
      EXPECT_EQ(not_of_frame(shown, k), 0) << "frame " << k << " display " << d;
    }
  }
  EXPECT_TRUE(fs::exists(run.out() / "frame-0" / "wall.png"));
  expect_clean(run);
}

// The DVI path (shared memory, emulated Lightning-2) and the vizserver path (tiles over TCP to
// a compositing server) give the same displays, byte for byte, on five example walls: two
// sort-first, the sort-last and the hybrid one (DEPTH and KEY tiles composited on both), and the
// colour-matched one (its tables applied on both).
struct WallCase {
  const char* file;
  int displays, pipeservers;
  bool depth = false;  // DEPTH layers: their rows go out sparse and change as the bunny turns
};
class BothPaths : public ::testing::TestWithParam<WallCase> {};

TEST_P(BothPaths, GiveIdenticalDisplays) {
  const WallCase& c = GetParam();
  WallRun run(fmt::format("both-{}", c.pipeservers),
              {"--wall", fmt::format("{}/walls/{}", L2_SOURCE_DIR, c.file), "--frames", "10",
               "--refresh", "0", "--path", "both", "--compare"});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  EXPECT_NE(output.find(fmt::format("10 frames on {} displays from {} pipeservers", c.displays,
                                    c.pipeservers)),
            std::string::npos)
      << output;
  EXPECT_NE(output.find(fmt::format("compare: {} display pictures identical byte for byte",
                                    10 * c.displays)),
            std::string::npos)
      << output;
  EXPECT_NE(output.find("latency: 1 frame "), std::string::npos) << output;
  // The emulator predicted every pipeserver's frames after its first from the last layout (a
  // pipeserver's headers only change parity), and the comparison above covered those frames.
  // A depth layer's sparse rows (tilelayout/sparse_depth.hpp) follow what it drew, so its
  // frames may be found different and parsed; the comparison covers those too.
  std::smatch predicted;
  ASSERT_TRUE(std::regex_search(
      output, predicted,
      std::regex("emulator: ([0-9]+) input frames predicted from their input's last layout, "
                 "([0-9]+) of them found different")))
      << output;
  EXPECT_GE(std::stoi(predicted[1]), 9 * c.pipeservers) << output;
  if (!c.depth) {
    EXPECT_EQ(predicted[2], "0") << output;
  }
  // The kept pictures of both paths are there and equal, read back from the files.
  for (int d = 0; d < c.displays; ++d) {
    const RgbImage dvi = read_png(run.out() / "frame-9" / fmt::format("display-{}.png", d));
    const RgbImage viz =
        read_png(run.out() / "frame-9" / fmt::format("display-{}-vizserver.png", d));
    EXPECT_TRUE(dvi.width() == viz.width() && dvi.height() == viz.height() &&
                std::equal(dvi.data(), dvi.data() + dvi.stride() * dvi.height(), viz.data()))
        << "display " << d;
  }
  EXPECT_FALSE(fs::exists(run.out() / "mismatch-frame-0"));
  expect_clean(run);
}

// Two runs at once on one machine, one on each kind of path: their shared-memory links, ptys,
// ports and compositing server are their own, so both succeed and show the same pictures. The
// runs' links are watched as they run, so the test knows the two were at once (60 frames at
// 60 Hz: each run lasts longer than the other takes to start).
TEST(LiveRun, TwoRunsAtOnceBothSucceed) {
  const std::vector<std::string> args = {"--frames", "60", "--refresh", "60", "--keep", "last"};
  std::vector<std::string> dvi = args, both = args;
  dvi.insert(dvi.end(), {"--path", "dvi"});
  both.insert(both.end(), {"--path", "both", "--compare"});
  WallRun first("at-once-dvi", dvi), second("at-once-both", both);
  bool together = false;
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (!together && !first.ended() && !second.ended() &&
         std::chrono::steady_clock::now() < deadline) {
    together = first.leftover_segments().size() == 4 && second.leftover_segments().size() == 4;
    std::this_thread::sleep_for(5ms);
  }
  EXPECT_TRUE(together) << "the two runs' links were never there at the same time";
  for (WallRun* run : {&first, &second}) {
    const ExitStatus status = run->wait(60s);
    ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run->output();
    EXPECT_NE(run->output().find("60 frames on 4 displays from 4 pipeservers"), std::string::npos)
        << run->output();
    EXPECT_NE(run->output().find("latency: 1 frame "), std::string::npos) << run->output();
  }
  EXPECT_NE(second.output().find("compare: 240 display pictures identical byte for byte"),
            std::string::npos)
      << second.output();
  for (int d = 0; d < 4; ++d) {
    const std::string name = fmt::format("display-{}.png", d);
    const std::string dvi_picture = slurp(first.out() / "frame-59" / name);
    EXPECT_EQ(dvi_picture, slurp(second.out() / "frame-59" / name)) << name;
    EXPECT_EQ(dvi_picture,
              slurp(second.out() / "frame-59" / fmt::format("display-{}-vizserver.png", d)))
        << name;
  }
  expect_clean(first);
  expect_clean(second);
}

INSTANTIATE_TEST_SUITE_P(ExampleWalls, BothPaths,
                         ::testing::Values(WallCase{"kd-2x2.toml", 4, 4},
                                           WallCase{"projectors-2x1.toml", 2, 3},
                                           WallCase{"sort-last-512x384.toml", 1, 3, true},
                                           WallCase{"hybrid-2x1.toml", 2, 5, true},
                                           WallCase{"colour-matched-2x2.toml", 4, 4}));

// Asked for more refreshes than a DVI link carries, the emulator refreshes as fast as the link
// could (dvi_timing_test.cpp works the default wall's 800x600 framebuffers out by hand).
TEST(LiveRun, TheRefreshRateIsWhatTheLinkCarries) {
  WallRun run("link-cap", {"--frames", "3", "--refresh", "1000"});
  ASSERT_EQ(run.wait(60s).code, 0) << run.output();
  EXPECT_NE(run.output().find("l2wall: warning: framebuffers of 800x600 at 1000 Hz need a 1067.50 "
                              "MHz pixel clock, more than dual-link DVI carries (330 MHz): the "
                              "emulator refreshes at 453 Hz\n"),
            std::string::npos)
      << run.output();
  EXPECT_NE(slurp(run.out() / "summary.txt").find(" refreshes at 453 Hz)"), std::string::npos)
      << slurp(run.out() / "summary.txt");
}

TEST(LiveRun, VizserverPathAloneShowsEveryFrame) {
  WallRun run("viz",
              {"--scene", "swap", "--frames", "4", "--path", "vizserver", "--keep", "every"});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  for (int k = 0; k < 4; ++k) {
    for (int d = 0; d < 4; ++d) {
      const RgbImage shown =
          read_png(run.out() / fmt::format("frame-{}", k) / fmt::format("display-{}.png", d));
      EXPECT_EQ(not_of_frame(shown, k), 0) << "frame " << k << " display " << d;
    }
  }
  expect_clean(run);
}

// The `swap` scene draws nothing: every display pixel of frame k is that frame's clear colour,
// on both paths; no pixel carries a frame stamp (issue 56: the stamps ride in the stamp strips,
// which no display shows).
TEST(LiveRun, SwapSceneShowsEachFramesColourAndNoStamp) {
  const int frames = 4;
  WallRun run("swap", {"--scene", "swap", "--frames", std::to_string(frames), "--refresh", "0",
                       "--keep", "every", "--path", "both", "--compare"});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  EXPECT_NE(output.find("latency: 1 frame "), std::string::npos) << output;
  for (int k = 0; k < frames; ++k) {
    for (int d = 0; d < 4; ++d) {
      for (const char* path : {"", "-vizserver"}) {
        const RgbImage shown = read_png(run.out() / fmt::format("frame-{}", k) /
                                        fmt::format("display-{}{}.png", d, path));
        EXPECT_EQ(not_of_frame(shown, k), 0) << "frame " << k << " display " << d << path;
      }
    }
  }
  expect_clean(run);
}

}  // namespace
}  // namespace l2
