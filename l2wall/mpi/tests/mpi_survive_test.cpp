// `mpirun --mca orte_enable_recovery 1 --mca orte_abort_on_non_zero_status 0 ... l2wall run
// --mpi --balance strips --survive-host-loss`: a pipeserver rank killed (SIGKILL) mid-run, or
// before its first frame, or two of them where the room allows, no longer ends the run; where
// the others cannot hold its tiles the run ends saying so. The coordinator learns it from the
// rank's liveness connection, the board column stops waiting for its frames, its tiles go to the
// others, and the last frames' displays equal a static one-machine run's byte for byte, frame
// stamps aside. With mpirun's default (the job ends with any rank) the option is refused, saying
// what mpirun needs. Real mpirun over the TCP transport.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "balanced_run.hpp"
#include "base/process_table.hpp"
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

// The run's ranks still running 10 s after mpirun ended, each as "pid (state): command line":
// mpirun ends its job's ranks as it ends, but one may still be ending as mpirun exits.
std::string ranks_left(const WallRun& run) {
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  std::vector<pid_t> left = ranks_running(run);
  while (!left.empty() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(20ms);
    left = ranks_running(run);
  }
  std::string said;
  for (const pid_t p : left) {
    std::string cmdline = process_command_line(p);
    std::replace(cmdline.begin(), cmdline.end(), '\0', ' ');
    const char state = process_state(p);
    said += fmt::format("{} ({}): {}\n", p, state != '\0' ? state : '?', cmdline);
  }
  return said;
}

// Waits for the run under an mpirun that keeps the job, whose exit status says little (Open
// MPI 4.1 then exits 0 whatever its ranks did, 1 when l2wall ended it): what matters is the
// output. mpirun must end: after a loss l2wall ends it, since it may not end by itself.
void wait_keeping_job(WallRun& run, const MpirunBase& base) {
  wait_mpirun(run, base, 180s);
}

// Its pid once pipeserver `pipeserver` has joined the MPI session (its log is opened after)
// and logged `frames` frames; -1 if that never happens.
pid_t joined_pipeserver(const WallRun& run, int pipeserver, int frames) {
  const fs::path log = run.out() / fmt::format("pipeserver-{}.log", pipeserver);
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (std::chrono::steady_clock::now() < deadline) {
    const auto pids = run.processes_naming(log.filename().string());
    if (pids.size() == 1 && fs::exists(log) && run.pipeserver_frames_logged(pipeserver) >= frames)
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

// The words naming pipeserver `pipeserver` (pid `pid`) gone, as a regex, up to the frame.
std::string gone_words(int pipeserver, pid_t pid) {
  return fmt::format(
      "pipeserver {} \\(rank \\d+ on [^,]+, pid {}\\) is gone \\(its connection to the "
      "coordinator closed: killed or crashed\\) while rendering frame ",
      pipeserver, pid);
}

Loss loss_said(const std::string& output, int pipeserver, pid_t victim) {
  const std::string gone = gone_words(pipeserver, victim);
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
                         "MPI's mpirun may not end a job that lost a rank by itself; every "
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

  // Runs `wall` under an mpirun that keeps the job.
  void start(const fs::path& wall) {
    survivor_.emplace("mpi-survive", surviving_args(wall), std::function<void(const fs::path&)>{},
                      false, mpirun(base_, 6, true));
  }
  // SIGKILLs pipeserver `pipeserver`'s rank once it has joined the session and logged `frames`
  // frames; its pid.
  pid_t kill_at(int pipeserver, int frames) {
    const pid_t victim = joined_pipeserver(*survivor_, pipeserver, frames);
    EXPECT_GT(victim, 0) << survivor_->output();
    if (victim > 0) {
      EXPECT_EQ(kill(victim, SIGKILL), 0);
    }
    return victim;
  }
  // Waits for the end: mpirun ended by l2wall, no rank left. The output.
  std::string finish() {
    wait_keeping_job(*survivor_, base_);
    const std::string output = survivor_->output();
    expect_job_ended(output);
    EXPECT_EQ(ranks_left(*survivor_), "") << "ranks left running";
    return output;
  }
  // The default wall's run with pipeserver kVictim killed at `frames`: every frame rendered.
  // What the run said of the loss.
  Loss kill_victim_at(int frames) {
    start(wall_);
    const pid_t victim = kill_at(kVictim, frames);
    const std::string output = finish();
    EXPECT_NE(
        output.find(fmt::format("l2wall run: {} frames on 4 displays from 4 pipeservers", kFrames)),
        std::string::npos)
        << output;
    return loss_said(output, kVictim, victim);
  }

  // The static one-machine run of the same frames: what the displays must show.
  void expect_displays_as_static() {
    std::vector<std::string> args = surviving_args(wall_);
    args.resize(args.size() - 4);  // no --mpi, no balancing
    WallRun fixed("mpi-survive-static", args);
    ASSERT_TRUE(fixed.wait(120s).ok()) << fixed.output();
    const Wall wall = load_wall(wall_);
    expect_displays_equal_stamps_aside(fixed, plan_layout(wall), *survivor_,
                                       layouts_of(*survivor_, wall), {kFrames - 2, kFrames - 1});
  }

  fs::path dir_, wall_;
  MpirunBase base_;
  std::optional<WallRun> survivor_;
};

TEST_F(MpiSurvive, APipeserverRankKilledMidRunIsSurvivedWithTheDisplaysOfAStaticRun) {
  const Loss loss = kill_victim_at(3);
  // It had logged 3 frames; the coordinator names the frame it awaited from it, which may be
  // the third when that frame's notice was still on its way as the loss was found.
  ASSERT_GE(loss.died_in, 2) << survivor_->output();
  std::printf(
      "pipeserver %d killed while rendering frame %d; its tiles elsewhere from frame %d; "
      "%d frames stale\n",
      kVictim, loss.died_in, loss.first_without, loss.stale);
  EXPECT_LE(loss.stale, 3);
  EXPECT_EQ(loss.stale, loss.first_without - loss.died_in);
  ASSERT_LE(loss.first_without, kFrames - 3) << "killed too late to see the displays recover";
  const std::string output = survivor_->output();
  EXPECT_NE(output.find("balance: 0 of "), std::string::npos) << output;  // no mixed swap
  EXPECT_NE(output.find("swap lock: every display"), std::string::npos) << output;
  expect_layouts_without_victim(*survivor_, loss.first_without);
  expect_displays_as_static();
}

// Killed once it has joined the session, before its first frame reached anyone: the run waits
// for the others' first frames only.
TEST_F(MpiSurvive, APipeserverRankKilledBeforeItsFirstFrameIsSurvived) {
  const Loss loss = kill_victim_at(0);
  const std::string output = survivor_->output();
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
  expect_layouts_without_victim(*survivor_, loss.first_without);
  expect_displays_as_static();
}

// A pipeserver rank that fails by its own error (its report cannot be written on its host: the
// log a dangling link) says its exit code on its liveness connection before it ends: it is
// lost as a child that exited with code 1 is on one machine, not as one killed or crashed, and
// the run goes on without it.
TEST_F(MpiSurvive, APipeserverRankThatFailsByItsOwnErrorIsNamedByItsExitCodeAndSurvived) {
  survivor_.emplace(
      "mpi-survive", surviving_args(wall_),
      [](const fs::path& out) {
        fs::create_symlink("/nonexistent/l2wall-test/pipeserver.log",
                           out / fmt::format("pipeserver-{}.log", kVictim));
      },
      false, mpirun(base_, 6, true));
  const std::string output = finish();
  EXPECT_NE(output.find(fmt::format("pipeserver {}: cannot write report ", kVictim)),
            std::string::npos)
      << output;
  EXPECT_TRUE(std::regex_search(
      output, std::regex(fmt::format("l2wall: pipeserver {} \\(rank 2 on [^,]+, pid \\d+\\) "
                                     "exited with code 1 while rendering frame 0; the run goes on "
                                     "without it \\(--survive-host-loss\\)",
                                     kVictim))))
      << output;
  EXPECT_EQ(output.find("killed or crashed"), std::string::npos) << output;
  EXPECT_NE(
      output.find(fmt::format("l2wall run: {} frames on 4 displays from 4 pipeservers", kFrames)),
      std::string::npos)
      << output;
}

// Two of four lost where tilelayout says two framebuffers hold every tile: the run goes on to
// its last frame, naming both.
TEST_F(MpiSurvive, TwoRanksLostAreSurvivedWhereTwoFramebuffersHoldEveryTile) {
  start(grid_wall_surviving(dir_, "two.toml", 2));
  const pid_t first = kill_at(1, 3);
  const pid_t second = kill_at(2, 6);
  const std::string output = finish();
  EXPECT_NE(output.find(fmt::format("l2wall run: {} frames", kFrames)), std::string::npos)
      << output;
  EXPECT_GE(loss_said(output, 1, first).died_in, 2) << output;  // as above: a notice in flight
  EXPECT_GE(loss_said(output, 2, second).died_in, 5) << output;
}

// On a wall whose other framebuffers cannot hold the lost one's tiles the run ends, saying so
// in one line; mpirun is ended too (its MPI_Abort ends only the coordinator).
TEST_F(MpiSurvive, ALossTheOthersCannotHoldEndsTheRunSayingSo) {
  const fs::path wall = dir_ / "none.toml";  // tilelayout: survives the loss of no pipeserver
  std::ofstream(wall) << grid_wall(240);
  start(wall);
  const pid_t victim = kill_at(1, 3);
  wait_keeping_job(*survivor_, base_);
  const std::string output = survivor_->output();
  EXPECT_TRUE(std::regex_search(
      output, std::regex("\nl2wall: " + gone_words(1, victim) +
                         "\\d+, and the run cannot go on without it: the other pipeservers' "
                         "framebuffers cannot hold pipeserver 1's tiles: [^\n]*does not fit")))
      << output;
  EXPECT_EQ(output.find("l2wall run: 40 frames"), std::string::npos) << output;
  EXPECT_EQ(ranks_left(*survivor_), "") << "ranks left running";
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
