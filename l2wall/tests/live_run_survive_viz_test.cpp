// `l2wall run --path vizserver --balance strips --survive-host-loss` (issue 34): a pipeserver
// killed before its first frame, or after a few, no longer ends the run on the compositing
// server's path. l2wall tells the server it is lost (LOST on the display stream), the server's
// frames stop waiting for it, its tiles go to the others from the next layout on, the run goes
// to its last frame, the summary names it, the frame and the frames shown stale, and the last
// frames' displays equal a static run's byte for byte (frame stamps aside). Real processes and
// sockets.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <regex>
#include <string>
#include <vector>

#include "balanced_run.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;
using namespace testing_support;

constexpr int kFrames = 30;
constexpr int kVictim = 1;
constexpr auto kRunBound = 120s;

// The frames pipeserver 1 has logged when it is killed: 0 (before its first frame reaches the
// server) or 3.
class LostOnTheVizserverPath : public ::testing::TestWithParam<int> {};

TEST_P(LostOnTheVizserverPath, IsSurvivedAndTheDisplaysRecover) {
  const int at = GetParam();
  const fs::path dir =
      fs::temp_directory_path() / fmt::format("l2wall-survive-viz-{}-{}", at, getpid());
  const fs::path wall_file = write_roomy_default_wall(dir);
  const std::string keep = fmt::format("{},{}", kFrames - 2, kFrames - 1);
  const std::vector<std::string> common{"--wall",          wall_file.string(),
                                        "--scene",         "strips",
                                        "--frames",        std::to_string(kFrames),
                                        "--refresh",       "0",
                                        "--keep",          keep,
                                        "--ready-timeout", "5000",
                                        "--stall-timeout", "60000"};
  std::vector<std::string> args = common;
  args.insert(args.end(), {"--path", "vizserver", "--balance", "strips", "--survive-host-loss"});
  WallRun fixed(fmt::format("survive-viz-static-{}", at), common);
  WallRun survivor(fmt::format("survive-viz-{}", at), args);

  const pid_t victim = pipeserver_at(survivor, kVictim, at);
  ASSERT_GT(victim, 0) << survivor.output();
  ASSERT_EQ(kill(victim, SIGKILL), 0);
  const ExitStatus status = survivor.wait(kRunBound);
  ASSERT_TRUE(fixed.wait(kRunBound).ok()) << fixed.output();
  const std::string output = survivor.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;

  EXPECT_NE(output.find(fmt::format("l2wall: pipeserver {} (pid {}) killed by signal 9 (Killed) "
                                    "while rendering frame ",
                                    kVictim, victim)),
            std::string::npos)
      << output;
  const std::string summary = slurp(survivor.out() / "summary.txt");
  EXPECT_NE(summary.find(fmt::format("l2wall run: {} frames", kFrames)), std::string::npos)
      << summary;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      summary, m,
      std::regex(fmt::format("balance: lost pipeserver {} \\(pid {}\\) killed by signal 9 "
                             "\\(Killed\\) while rendering frame (\\d+), [0-9.]+ s into the "
                             "run; its tiles went to the others from frame (\\d+); (\\d+) frames? "
                             "stale \\(shown incomplete or late\\)",
                             kVictim, victim))))
      << summary;
  const int died_in = std::stoi(m[1].str());
  const int first_without = std::stoi(m[2].str());
  EXPECT_GE(died_in, at);
  EXPECT_EQ(std::stoi(m[3].str()), first_without - died_in);
  ASSERT_LE(first_without, kFrames - 3) << "killed too late to see the displays recover";
  EXPECT_EQ(summary.find(fmt::format("limited by pipeserver {}", kVictim)), std::string::npos)
      << summary;

  // The server was told, and said so in its notes.
  EXPECT_NE(output.find(fmt::format("pipeserver {} lost: the run goes on without it", kVictim)),
            std::string::npos)
      << output;

  const Wall wall = load_wall(wall_file);
  expect_displays_equal_stamps_aside(fixed, plan_layout(wall), survivor, layouts_of(survivor, wall),
                                     {kFrames - 2, kFrames - 1});
  expect_clean(fixed);
  expect_clean(survivor);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Frames, LostOnTheVizserverPath, ::testing::Values(0, 3));

}  // namespace
}  // namespace l2
