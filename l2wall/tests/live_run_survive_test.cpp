// `l2wall run --balance strips --survive-host-loss`: a pipeserver killed mid-run no longer ends
// the run. Its tiles go to the others within a few frames, and the last frames' displays equal
// those of a static run byte for byte (frame stamps aside). Without the option the same kill
// ends the run, named; and when the others' framebuffers cannot hold the dead pipeserver's tiles
// the run ends with that said in one line. Real processes, links and sockets.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "balanced_run.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;
using namespace testing_support;

constexpr int kFrames = 40;
constexpr int kVictim = 1;
// Generous: two runs of four pipeservers each share a loaded 2-core machine.
constexpr auto kRunBound = 120s;

std::vector<LayoutMessage> layout_lines(const WallRun& run) {
  std::vector<LayoutMessage> lines;
  std::istringstream in(slurp(run.out() / "layouts.txt"));
  for (std::string line; std::getline(in, line);) lines.push_back(decode_layout(line));
  return lines;
}

int frames_logged(const WallRun& run, int pipeserver) {
  return run.pipeserver_frames_logged(pipeserver);  // one a frame published, none once killed
}

// --balance strips and kd alike.
class LiveRunSurviveMode : public ::testing::TestWithParam<std::string> {};

TEST_P(LiveRunSurviveMode, AKilledPipeserversTilesGoToTheOthersAndTheDisplaysRecover) {
  const std::string mode = GetParam();
  const fs::path dir =
      fs::temp_directory_path() / fmt::format("l2wall-survive-{}-{}", mode, getpid());
  const fs::path wall_file = write_roomy_default_wall(dir);
  const std::string keep = fmt::format("{},{}", kFrames - 2, kFrames - 1);
  const std::vector<std::string> common{"--wall", wall_file.string(), "--scene", "strips",
                                        "--frames", std::to_string(kFrames), "--refresh", "0",
                                        "--keep", keep,
                                        // Patience for a loaded machine: writing the kept
                                        // pictures holds the READYs of the next frame.
                                        "--ready-timeout", "5000", "--stall-timeout", "60000"};
  // As fast as possible (--refresh 0) the emulator refreshes only when a link changes: the
  // signal lost with the pipeserver must count as a change, or a group it held up never completes.
  std::vector<std::string> args = common;
  args.insert(args.end(), {"--balance", mode, "--survive-host-loss"});
  WallRun fixed("survive-static-" + mode, common);
  WallRun survivor("survive-" + mode, args);

  const pid_t victim = running_pipeserver(survivor, kVictim);
  ASSERT_GT(victim, 0) << survivor.output();
  const int logged_at_kill = frames_logged(survivor, kVictim);
  ASSERT_EQ(kill(victim, SIGKILL), 0);
  const auto t0 = std::chrono::steady_clock::now();
  const ExitStatus status = survivor.wait(kRunBound);
  const double run_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(fixed.wait(kRunBound).ok()) << fixed.output();
  const std::string output = survivor.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;

  // Said at once, and in the summary: the pipeserver, how it ended, the frame, when, the stale
  // frames.
  EXPECT_NE(output.find(fmt::format("l2wall: pipeserver {} (pid {}) killed by signal 9 (Killed) "
                                    "while rendering frame ",
                                    kVictim, victim)),
            std::string::npos)
      << output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      output, m,
      std::regex(fmt::format("balance: lost pipeserver {} \\(pid {}\\) killed by signal 9 "
                             "\\(Killed\\) while rendering frame (\\d+), ([0-9.]+) s into the "
                             "run; its tiles went to the others from frame (\\d+); (\\d+) frames? "
                             "stale \\(shown incomplete or late\\)",
                             kVictim, victim))))
      << output;
  const int died_in = std::stoi(m[1].str());
  const int first_without = std::stoi(m[3].str());
  const int stale = std::stoi(m[4].str());
  std::printf(
      "%s: pipeserver %d killed while rendering frame %d; its tiles elsewhere from frame %d; "
      "%d frames stale; the run ended %.2f s after the kill\n",
      mode.c_str(), kVictim, died_in, first_without, stale, run_s);
  // The frame named is the one it never delivered: the last it logged was the one before (or
  // it died between publishing a frame and logging it).
  const int logged = frames_logged(survivor, kVictim);
  EXPECT_GE(died_in, logged_at_kill);
  EXPECT_GE(died_in, logged);
  EXPECT_LE(died_in, logged + 1);
  EXPECT_LE(stale, 3);
  EXPECT_EQ(stale, first_without - died_in);
  ASSERT_LE(first_without, kFrames - 3) << "killed too late to see the displays recover";
  EXPECT_NE(output.find("balance: 0 of "), std::string::npos) << output;  // no mixed swap

  // report.csv: its render time, READY wait and retries for the frames it rendered only.
  const auto rows = read_csv(survivor.out() / "report.csv");
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(kFrames + 1));
  const auto column =
      std::find(rows[0].begin(), rows[0].end(), fmt::format("render_ms_{}", kVictim));
  ASSERT_NE(column, rows[0].end());
  const auto c = static_cast<std::size_t>(column - rows[0].begin());
  for (int k = 0; k < kFrames; ++k) {
    const auto& row = rows[static_cast<std::size_t>(k + 1)];
    EXPECT_EQ(row.size() > c && !row[c].empty(), k < logged) << "frame " << k;
  }
  EXPECT_NE(output.find(fmt::format("render time of pipeserver {} (median", kVictim)),
            std::string::npos);

  // Every layout from then on gives it nothing and names it gone; the others plan them alike.
  const Wall wall = load_wall(wall_file);
  const std::vector<LayoutMessage> lines = layout_lines(survivor);
  ASSERT_EQ(lines.size(), static_cast<std::size_t>(kFrames));
  for (int k = 0; k < kFrames; ++k) {
    const LayoutMessage& line = lines[static_cast<std::size_t>(k)];
    const bool without = k >= first_without;
    EXPECT_EQ(line.gone, without ? std::vector<int>{kVictim} : std::vector<int>{}) << k;
    EXPECT_EQ(std::count(line.pipeservers.begin(), line.pipeservers.end(), kVictim) == 0, without)
        << k;
  }

  // The last frames: every display as the static run's, each survivor's stamp saying the frame.
  expect_displays_equal_stamps_aside(fixed, plan_layout(wall), survivor, layouts_of(survivor, wall),
                                     {kFrames - 2, kFrames - 1});
  expect_clean(fixed);
  expect_clean(survivor);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Modes, LiveRunSurviveMode, ::testing::Values("strips", "kd"));

// The default stays: balancing without the option, the same kill ends the run, named.
TEST(LiveRunSurvive, WithoutTheOptionAKilledPipeserverEndsTheBalancedRun) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-nosurvive-{}", getpid());
  WallRun run("nosurvive", {"--wall", write_roomy_default_wall(dir).string(), "--scene", "strips",
                            "--frames", "100000", "--refresh", "30", "--balance", "strips",
                            "--ready-timeout", "5000", "--stall-timeout", "60000"});
  const pid_t victim = running_pipeserver(run, kVictim);
  ASSERT_GT(victim, 0) << run.output();
  ASSERT_EQ(kill(victim, SIGKILL), 0);
  const ExitStatus status = run.wait(kRunBound);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << status.describe() << "\n" << output;
  EXPECT_NE(output.find(fmt::format("l2wall: pipeserver {} (pid {}) killed by signal 9 (Killed) "
                                    "while rendering frame ",
                                    kVictim, victim)),
            std::string::npos)
      << output;
  EXPECT_EQ(output.find("goes on without it"), std::string::npos) << output;
  expect_clean(run);
  fs::remove_all(dir);
}

// Two pipeservers on one display, each framebuffer one tile wide: the survivor has no room for
// the other's tile, whatever the strips' edges. The run says so as it starts, and at the kill
// ends saying why in one line (not that it goes on first); no frame it never rendered is stale.
TEST(LiveRunSurvive, AFullWallEndsTheRunSayingTheOthersCannotHoldTheTiles) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-full-{}", getpid());
  fs::create_directories(dir);
  const fs::path wall = dir / "full.toml";
  std::ofstream(wall) << "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 200\nheight = 100\n"
                         "[tiling]\nkind = \"strips\"\nstrips = 1\nsubstrips = 2\n"
                         "[pipeservers]\ncount = 2\nframebuffer_width = 160\n"
                         "framebuffer_height = 100\n"
                         "[balance]\nmode = \"strips\"\nsurvive_host_loss = true\n";
  WallRun run("full", {"--wall", wall.string(), "--scene", "strips", "--frames", "100000",
                       "--refresh", "30", "--ready-timeout", "5000", "--stall-timeout", "60000"});
  const pid_t victim = running_pipeserver(run, kVictim);
  ASSERT_GT(victim, 0) << run.output();
  ASSERT_EQ(kill(victim, SIGKILL), 0);
  const ExitStatus status = run.wait(kRunBound);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << status.describe() << "\n" << output;
  EXPECT_NE(output.find(fmt::format("l2wall: {}:14: balance.survive_host_loss: the wall survives "
                                    "the loss of no pipeserver (framebuffers 160x100); 1: needs "
                                    "framebuffer_height >= 200; a pipeserver that dies ends the "
                                    "run\n",
                                    wall.string())),
            std::string::npos)
      << output;
  EXPECT_EQ(output.find("goes on without it"), std::string::npos) << output;
  EXPECT_EQ(output.find("stale"), std::string::npos) << output;
  EXPECT_EQ(slurp(run.out() / "summary.txt").find("stale"), std::string::npos);
  std::smatch m;
  EXPECT_TRUE(std::regex_search(
      output, m,
      std::regex(fmt::format("\nl2wall: pipeserver {0} \\(pid {1}\\) killed by signal 9 "
                             "\\(Killed\\) while rendering frame \\d+, and the run cannot go on "
                             "without it: the other pipeservers' framebuffers cannot hold "
                             "pipeserver {0}'s tiles: [^\n]*{2}:\\d+: pipeserver 0: tile 1 "
                             "[^\n]* does not fit the 160x100 framebuffer[^\n]*\n",
                             kVictim, victim, wall.string()))))
      << output;
  expect_clean(run);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace l2
