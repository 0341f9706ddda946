// --survive-host-loss at the edges (issues 32, 34): a pipeserver lost at frame 0, 1 or 2 (the
// run goes on), two lost (it goes on where the others' framebuffers hold every tile, or ends
// saying they cannot), one stopped (SIGSTOP) rather than killed (it ends naming it). Each says
// so in one line naming the pipeserver; none hangs, none leaves a process or a shared-memory
// link.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <regex>

#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;
using namespace testing_support;

constexpr auto kRunBound = 120s;

// Pipeserver `pipeserver`'s pid once it runs and has logged `frames` frames (0: as soon as it
// runs, before its first frame reaches anyone); -1 if that never happens.
pid_t pipeserver_at(const WallRun& run, int pipeserver, int frames) {
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (std::chrono::steady_clock::now() < deadline) {
    const auto pids = run.pipeservers(pipeserver);
    if (pids.size() == 1 && run.pipeserver_log_lines(pipeserver) >= frames) return pids.front();
    std::this_thread::sleep_for(2ms);
  }
  return -1;
}

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

// Two of four lost: the two left take every tile where their framebuffers hold them, or the run
// ends saying they cannot; both losses are named either way.
TEST(LostTwo, IsSurvivedOrEndsTheRunSayingWhy) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-lost-two-{}", getpid());
  WallRun run("lost-two", surviving_run(write_roomy_default_wall(dir), "60"));
  const pid_t first = pipeserver_at(run, 1, 3);
  ASSERT_GT(first, 0) << run.output();
  ASSERT_EQ(kill(first, SIGKILL), 0);
  const pid_t second = pipeserver_at(run, 2, 6);
  ASSERT_GT(second, 0) << run.output();
  ASSERT_EQ(kill(second, SIGKILL), 0);
  const ExitStatus status = run.wait(kRunBound);
  const std::string output = run.output();
  EXPECT_NE(output.find(fmt::format("pipeserver 1 (pid {}) killed by signal 9 (Killed)", first)),
            std::string::npos)
      << output;
  EXPECT_NE(output.find(fmt::format("pipeserver 2 (pid {}) killed by signal 9 (Killed)", second)),
            std::string::npos)
      << output;
  const std::string summary = slurp(run.out() / "summary.txt");
  if (status.code == 0) {
    EXPECT_NE(summary.find("balance: lost pipeserver 1"), std::string::npos) << summary;
    EXPECT_NE(summary.find("balance: lost pipeserver 2"), std::string::npos) << summary;
  } else {
    EXPECT_EQ(status.code, 1) << output;
    EXPECT_NE(output.find("the run cannot go on without it: the other pipeservers' framebuffers "
                          "cannot hold"),
              std::string::npos)
        << output;
  }
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
