// --survive-host-loss at the edges (issues 32, 34): a pipeserver lost at frame 0, 1 or 2 (the
// run goes on), two lost (it goes on where tilelayout says two framebuffers hold every tile, and
// ends saying they cannot on a wall that survives only one), one stopped (SIGSTOP) rather than
// killed (it ends naming it). Each says so in one line naming the pipeserver; none hangs, none
// leaves a process or a shared-memory link.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <fstream>
#include <optional>
#include <regex>
#include <utility>

#include "tilelayout/survival.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;
using namespace testing_support;

constexpr auto kRunBound = 120s;

std::vector<std::string> surviving_run(const fs::path& wall, const std::string& frames,
                                       const std::string& stall_ms = "60000") {
  return {"--wall",
          wall.string(),
          "--scene",
          "strips",
          "--frames",
          frames,
          "--refresh",
          "30",
          "--balance",
          "strips",
          "--survive-host-loss",
          "--ready-timeout",
          "5000",
          "--stall-timeout",
          stall_ms};
}

class LostAtFrame : public ::testing::TestWithParam<int> {};

// Lost at frame 0 (before its first frame reaches anyone), 1 or 2: the run goes on without it,
// says so in one line, and every frame reaches the displays.
TEST_P(LostAtFrame, IsSurvived) {
  const int at = GetParam();
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-lost-{}-{}", at, getpid());
  WallRun run(fmt::format("lost-{}", at), surviving_run(write_roomy_default_wall(dir), "60"));
  const pid_t victim = pipeserver_at(run, 1, at);
  ASSERT_GT(victim, 0) << run.output();
  ASSERT_EQ(kill(victim, SIGKILL), 0);
  const ExitStatus status = run.wait(kRunBound);
  const std::string output = run.output();
  const std::string named =
      fmt::format("pipeserver 1 (pid {}) killed by signal 9 (Killed)", victim);
  EXPECT_NE(output.find(named), std::string::npos) << output;
  const std::string summary = slurp(run.out() / "summary.txt");
  EXPECT_EQ(status.code, 0) << output;
  EXPECT_NE(
      output.find(named + fmt::format(" while rendering frame {}; the run goes on without it", at)),
      std::string::npos)
      << output;
  EXPECT_NE(summary.find("l2wall run: 60 frames"), std::string::npos) << summary;
  EXPECT_TRUE(std::regex_search(
      summary, std::regex("balance: lost pipeserver 1 \\(pid \\d+\\) killed by signal 9")))
      << summary;
  EXPECT_EQ(summary.find("limited by pipeserver 1"), std::string::npos) << summary;
  expect_clean(run);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Frames, LostAtFrame, ::testing::Values(0, 1, 2));

// Kills pipeserver 1 once it has logged 3 frames, then pipeserver 2 once it has logged 6; the
// two pids.
std::pair<pid_t, pid_t> kill_two(const WallRun& run) {
  const pid_t first = pipeserver_at(run, 1, 3);
  EXPECT_GT(first, 0) << run.output();
  if (first > 0) {
    EXPECT_EQ(kill(first, SIGKILL), 0);
  }
  const pid_t second = pipeserver_at(run, 2, 6);
  EXPECT_GT(second, 0) << run.output();
  if (second > 0) {
    EXPECT_EQ(kill(second, SIGKILL), 0);
  }
  return {first, second};
}

std::string killed(int pipeserver, pid_t pid) {
  return fmt::format("pipeserver {} (pid {}) killed by signal 9 (Killed)", pipeserver, pid);
}

// Two of four lost on a wall whose framebuffers tilelayout says hold every tile on any two
// pipeservers: the run goes on to its last frame, and the summary names both losses.
TEST(LostTwo, IsSurvivedWhereTilelayoutSaysTwoLeftHoldEveryTile) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-lost-two-{}", getpid());
  const fs::path wall_file = grid_wall_surviving(dir, "two.toml", 2);
  ASSERT_EQ(survival(load_wall(wall_file)).survives, 2);
  WallRun run("lost-two", surviving_run(wall_file, "40"));
  const auto [first, second] = kill_two(run);
  const ExitStatus status = run.wait(kRunBound);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 0) << output;
  EXPECT_NE(output.find(killed(1, first)), std::string::npos) << output;
  EXPECT_NE(output.find(killed(2, second)), std::string::npos) << output;
  const std::string summary = slurp(run.out() / "summary.txt");
  EXPECT_NE(summary.find("l2wall run: 40 frames"), std::string::npos) << summary;
  EXPECT_NE(summary.find("balance: lost " + killed(1, first)), std::string::npos) << summary;
  EXPECT_NE(summary.find("balance: lost " + killed(2, second)), std::string::npos) << summary;
  expect_clean(run);
  fs::remove_all(dir);
}

// Two of four lost on the same wall sized for one loss only: two framebuffers carry fewer tile
// pixels than the displays have, whatever the cut, so the second loss ends the run in one line
// saying why, and the run names both.
TEST(LostTwo, EndsTheRunSayingWhyWhereTheWallSurvivesOnlyOne) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-lost-one-{}", getpid());
  const fs::path wall_file = grid_wall_surviving(dir, "one.toml", 1);
  const Wall wall = load_wall(wall_file);
  ASSERT_EQ(survival(wall).survives, 1);
  ASSERT_LT(2 * wall.framebuffer_height * (kGridFramebufferWidth - 2), 4 * 320 * 240);
  WallRun run("lost-two-ends", surviving_run(wall_file, "100000"));
  const auto [first, second] = kill_two(run);
  const ExitStatus status = run.wait(kRunBound);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << output;
  EXPECT_NE(output.find(killed(1, first) + " while rendering frame "), std::string::npos) << output;
  EXPECT_NE(output.find(killed(2, second) + " while rendering frame "), std::string::npos)
      << output;
  EXPECT_NE(output.find(", and the run cannot go on without it: the other pipeservers' "
                        "framebuffers cannot hold pipeserver 2's tiles: "),
            std::string::npos)
      << output;
  expect_clean(run);
  fs::remove_all(dir);
}

// Stopped, not killed: it is still there, so nothing is survived; the run ends at the stall
// timeout naming it as stopped, and the stopped process is ended with the rest.
TEST(Stopped, EndsTheRunNamingItAsStopped) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-stopped-{}", getpid());
  WallRun run("stopped", surviving_run(write_roomy_default_wall(dir), "100000", "3000"));
  const pid_t victim = pipeserver_at(run, 1, 3);
  ASSERT_GT(victim, 0) << run.output();
  ASSERT_EQ(kill(victim, SIGSTOP), 0);
  const ExitStatus status = run.wait(kRunBound);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << output;
  EXPECT_TRUE(std::regex_search(
      output, std::regex(fmt::format("l2wall: no display swap for 3000 ms: pipeserver 1 \\(pid "
                                     "{}\\) did not deliver frame \\d+ \\(stopped",
                                     victim))))
      << output;
  EXPECT_EQ(output.find("goes on without it"), std::string::npos) << output;
  expect_clean(run);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace l2
