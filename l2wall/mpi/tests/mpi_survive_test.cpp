// `mpirun --mca orte_enable_recovery 1 --mca orte_abort_on_non_zero_status 0 ... l2wall run
// --mpi --balance strips --survive-host-loss`: a pipeserver rank killed (SIGKILL) mid-run, or
// before its first frame, no longer ends the run. The coordinator learns it from the rank's
// liveness connection, the board column stops waiting for its frames, its tiles go to the others,
// and the last frames' displays equal a static one-machine run's byte for byte, frame stamps
// aside. With mpirun's default (the job ends with any rank) the option is refused, saying what
// mpirun needs. Real mpirun over the TCP transport.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "balanced_run.hpp"
#include "mpirun_run.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace std::chrono_literals;
using namespace testing_support;

constexpr int kFrames = 40;
constexpr int kVictim = 1;

// The run's ranks still running: processes naming its output folder, but mpirun (pid()).
std::vector<pid_t> ranks_running(const WallRun& run) {
  std::vector<pid_t> ranks;
  for (const pid_t p : run.processes_naming(""))
    if (p != run.pid()) ranks.push_back(p);
  return ranks;
}

// Waits for the run under an mpirun that keeps the job, whose exit status says little (Open
// MPI 4.1 then exits 0 whatever its ranks did, 1 when l2wall ended it after a loss): what
// matters is the output. Once every rank has ended, an mpirun that has not ended 15 s later
// hangs in its own teardown (Open MPI 4.1, as mpi_fault_test.sh meets): killed and said in one
// line, and the test goes on.
void wait_keeping_job(WallRun& run, const MpirunBase& base) {
  const auto deadline = std::chrono::steady_clock::now() + 180s;
  std::optional<std::chrono::steady_clock::time_point> ranks_gone;
  while (!run.ended()) {
    const auto now = std::chrono::steady_clock::now();
    ASSERT_LT(now, deadline) << "the run did not end within 180 s\n" << run.output();
    if (!ranks_running(run).empty()) {
      ranks_gone.reset();
    } else if (!ranks_gone) {
      ranks_gone = now;
    } else if (now - *ranks_gone > 15s) {
      std::printf("(mpirun %d hung after every rank had ended: killed)\n", run.pid());
      kill(run.pid(), SIGKILL);
      break;
    }
    std::this_thread::sleep_for(50ms);
  }
  wait_mpirun(run, base, 10s);
}

// Its pid once pipeserver `pipeserver` has joined the MPI session (its log is opened after)
// and logged `frames` frames; -1 if that never happens.
pid_t joined_pipeserver(const WallRun& run, int pipeserver, int frames) {
  const fs::path log = run.out() / fmt::format("pipeserver-{}.log", pipeserver);
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (std::chrono::steady_clock::now() < deadline) {
    const auto pids = run.processes_naming(log.filename().string());
    if (pids.size() == 1 && fs::exists(log) && run.pipeserver_log_lines(pipeserver) >= frames)
      return pids.front();
    std::this_thread::sleep_for(2ms);
  }
  return -1;
}

std::vector<std::string> surviving_args(const fs::path& wall) {
  return {"--wall",          wall.string(),
          "--scene",         "strips",
          "--frames",        std::to_string(kFrames),
          "--refresh",       "0",
          "--keep",          fmt::format("{},{}", kFrames - 2, kFrames - 1),
          "--ready-timeout", "5000",
          "--stall-timeout", "60000",
          "--mpi",           "--balance",
          "strips",          "--survive-host-loss"};
}

// What the run said of the loss, from its summary: the frame the pipeserver died rendering,
// the first without it, the frames stale.
struct Loss {
  int died_in = -1, first_without = -1, stale = -1;
};

Loss loss_said(const std::string& output, pid_t victim) {
  const std::string gone = fmt::format(
      "pipeserver {} \\(rank \\d+ on [^,]+, pid {}\\) is gone \\(its connection to the "
      "coordinator closed: killed or crashed\\) while rendering frame ",
      kVictim, victim);
  EXPECT_TRUE(std::regex_search(output, std::regex("l2wall: " + gone +
                                                   "\\d+; the run goes on without it "
                                                   "\\(--survive-host-loss\\)")))
      << output;
  std::smatch m;
  Loss loss;
  if (!std::regex_search(output, m,
                         std::regex("balance: lost " + gone +
                                    "(\\d+), ([0-9.]+) s into the run; its tiles went to the "
                                    "others from frame (\\d+); (\\d+) frames? stale")))
    return loss;
  loss.died_in = std::stoi(m[1].str());
  loss.first_without = std::stoi(m[3].str());
  loss.stale = std::stoi(m[4].str());
  return loss;
}

// mpirun, which would wait for ever for the lost rank, was asked to end the job, in one line.
void expect_job_ended(const std::string& output) {
  EXPECT_TRUE(std::regex_search(
      output, std::regex("\nl2wall: --mpi: ending the job \\(SIGTERM to mpirun, pid \\d+\\): Open "
                         "MPI's mpirun does not end a job that lost a rank by itself; every "
                         "rank's part is done\n")))
      << output;
}

// Every layout from the first without it gives it nothing and names it gone.
void expect_layouts_without_victim(const WallRun& run, int first_without) {
  std::istringstream in(slurp(run.out() / "layouts.txt"));
  int k = 0;
  for (std::string text; std::getline(in, text); ++k) {
    const LayoutMessage line = decode_layout(text);
    const bool without = k >= first_without;
    EXPECT_EQ(line.gone, without ? std::vector<int>{kVictim} : std::vector<int>{}) << k;
    EXPECT_EQ(std::count(line.pipeservers.begin(), line.pipeservers.end(), kVictim) == 0, without)
        << k;
  }
  EXPECT_EQ(k, kFrames);
}

class MpiSurvive : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("l2wall-mpi-survive-{}", getpid());
    wall_ = write_roomy_default_wall(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The static one-machine run of the same frames: what the displays must show.
  void expect_displays_as_static(const WallRun& survivor) {
    std::vector<std::string> args = surviving_args(wall_);
    args.resize(args.size() - 4);  // no --mpi, no balancing
    WallRun fixed("mpi-survive-static", args);
    ASSERT_TRUE(fixed.wait(120s).ok()) << fixed.output();
    const Wall wall = load_wall(wall_);
    expect_displays_equal_stamps_aside(fixed, plan_layout(wall), survivor,
                                       layouts_of(survivor, wall), {kFrames - 2, kFrames - 1});
  }

  fs::path dir_, wall_;
};

TEST_F(MpiSurvive, APipeserverRankKilledMidRunIsSurvivedWithTheDisplaysOfAStaticRun) {
  const MpirunBase base;
  WallRun survivor("mpi-survive", surviving_args(wall_), {}, false, mpirun(base, 6, true));
  const pid_t victim = joined_pipeserver(survivor, kVictim, 3);
  ASSERT_GT(victim, 0) << survivor.output();
  ASSERT_EQ(kill(victim, SIGKILL), 0);
  wait_keeping_job(survivor, base);
  const std::string output = survivor.output();
  EXPECT_NE(
      output.find(fmt::format("l2wall run: {} frames on 4 displays from 4 pipeservers", kFrames)),
      std::string::npos)
      << output;
  const Loss loss = loss_said(output, victim);
  ASSERT_GE(loss.died_in, 3) << output;
  expect_job_ended(output);
  std::printf(
      "pipeserver %d killed while rendering frame %d; its tiles elsewhere from frame %d; "
      "%d frames stale\n",
      kVictim, loss.died_in, loss.first_without, loss.stale);
  EXPECT_LE(loss.stale, 3);
  EXPECT_EQ(loss.stale, loss.first_without - loss.died_in);
  ASSERT_LE(loss.first_without, kFrames - 3) << "killed too late to see the displays recover";
  EXPECT_NE(output.find("balance: 0 of "), std::string::npos) << output;  // no mixed swap
  EXPECT_NE(output.find("swap lock: every display"), std::string::npos) << output;
  expect_layouts_without_victim(survivor, loss.first_without);
  EXPECT_TRUE(ranks_running(survivor).empty());
  expect_displays_as_static(survivor);
}

// Killed once it has joined the session, before its first frame reached anyone: the run waits
// for the others' first frames only.
TEST_F(MpiSurvive, APipeserverRankKilledBeforeItsFirstFrameIsSurvived) {
  const MpirunBase base;
  WallRun survivor("mpi-survive-0", surviving_args(wall_), {}, false, mpirun(base, 6, true));
  const pid_t victim = joined_pipeserver(survivor, kVictim, 0);
  ASSERT_GT(victim, 0) << survivor.output();
  ASSERT_EQ(kill(victim, SIGKILL), 0);
  wait_keeping_job(survivor, base);
  const std::string output = survivor.output();
  EXPECT_NE(
      output.find(fmt::format("l2wall run: {} frames on 4 displays from 4 pipeservers", kFrames)),
      std::string::npos)
      << output;
  const Loss loss = loss_said(output, victim);
  expect_job_ended(output);
  // Its first frame may have gone out between the look at its log and the kill.
  EXPECT_GE(loss.died_in, 0) << output;
  EXPECT_LE(loss.died_in, 1) << output;
  std::printf("pipeserver %d killed while rendering frame %d\n", kVictim, loss.died_in);
  // Lost while the run starts, before every first frame: at the run's second 0.
  if (loss.died_in == 0) {
    EXPECT_NE(output.find("while rendering frame 0, 0.00 s into the run"), std::string::npos)
        << output;
  }
  EXPECT_LE(loss.first_without, 3) << output;
  expect_layouts_without_victim(survivor, loss.first_without);
  EXPECT_TRUE(ranks_running(survivor).empty());
  expect_displays_as_static(survivor);
}

// mpirun's default ends the job with any rank: refused before anything runs, saying what mpirun
// needs.
TEST(MpiSurviveRefused, WithoutAnMpirunThatKeepsTheJob) {
  const MpirunBase base;
  WallRun run("mpi-survive-refused",
              {"--frames", "2", "--mpi", "--balance", "strips", "--survive-host-loss"}, {}, false,
              mpirun(base));
  EXPECT_FALSE(wait_mpirun(run, base, 120s).ok());
  EXPECT_NE(run.output().find("l2wall: --survive-host-loss: over MPI (--mpi) needs an mpirun that "
                              "keeps the job when a rank dies: mpirun --mca "
                              "orte_enable_recovery 1 --mca orte_abort_on_non_zero_status 0 ..."),
            std::string::npos)
      << run.output();
}

}  // namespace
}  // namespace l2
