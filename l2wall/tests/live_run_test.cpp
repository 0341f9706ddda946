// `l2wall run` end to end: real pipeserver processes, real shared memory, real ptys.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "frame_stamp.hpp"
#include "image/png_io.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// One l2wall run in its own folder; its output goes to DIR/output.txt.
class WallRun {
 public:
  WallRun(const std::string& name, const std::vector<std::string>& args)
      : dir_(fs::temp_directory_path() / fmt::format("l2wall-test-{}-{}", getpid(), name)) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::string command =
        fmt::format("exec '{}' run --out '{}' --no-progress", L2WALL_PATH, (dir_ / "out").string());
    for (const auto& a : args) command += " '" + a + "'";
    command += fmt::format(" > '{}' 2>&1", (dir_ / "output.txt").string());
    // exec: the shell becomes l2wall, so pid() is l2wall's and names its shm segments.
    process_.emplace(std::vector<std::string>{"/bin/sh", "-c", command});
  }
  ~WallRun() {
    process_.reset();
    fs::remove_all(dir_);
  }
  ExitStatus wait(std::chrono::milliseconds timeout) {
    auto status = process_->wait_for(timeout);
    if (!status) {
      ADD_FAILURE() << "l2wall did not end within " << timeout.count() << " ms";
      status = process_->terminate();
    }
    return *status;
  }
  std::string output() const { return slurp(dir_ / "output.txt"); }
  fs::path out() const { return dir_ / "out"; }
  pid_t pid() const { return process_->pid(); }
  std::string link_prefix() const { return fmt::format("l2-{}-in", pid()); }

  // Shared-memory segments of this run still in /dev/shm.
  std::vector<std::string> leftover_segments() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator("/dev/shm")) {
      const std::string n = e.path().filename().string();
      if (n.rfind(link_prefix(), 0) == 0) names.push_back(n);
    }
    return names;
  }
  // Processes whose command line names one of this run's links: its pipeservers.
  std::vector<pid_t> pipeservers(int server = -1) const {
    std::vector<pid_t> pids;
    const std::string needle =
        "/" + link_prefix() + (server >= 0 ? fmt::format("{}", server) + '\0' : "");
    for (const auto& e : fs::directory_iterator("/proc")) {
      const std::string n = e.path().filename().string();
      if (n.find_first_not_of("0123456789") != std::string::npos) continue;
      const std::string cmdline = slurp(e.path() / "cmdline");
      if (cmdline.find(needle) != std::string::npos) pids.push_back(std::stoi(n));
    }
    return pids;
  }
  int host_log_lines(int server) const {
    std::ifstream in(out() / fmt::format("host-{}.log", server));
    int lines = 0;
    for (std::string l; std::getline(in, l);) ++lines;
    return lines;
  }

 private:
  fs::path dir_;
  std::optional<ChildProcess> process_;
};

std::vector<std::vector<std::string>> read_csv(const fs::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string c; std::getline(s, c, ',');) cells.push_back(c);
    rows.push_back(cells);
  }
  return rows;
}

void expect_clean(const WallRun& run) {
  EXPECT_TRUE(run.leftover_segments().empty())
      << "shm segment left: " << run.leftover_segments().front();
  EXPECT_TRUE(run.pipeservers().empty()) << "orphan pipeserver pid " << run.pipeservers().front();
}

TEST(LiveRun, EveryDisplayFrameShowsTheInputFrameOneRefreshEarlier) {
  const int frames = 6;
  WallRun run("latency", {"--frames", std::to_string(frames), "--refresh", "0", "--keep", "every"});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  EXPECT_NE(output.find("latency: 1 frame "), std::string::npos) << output;
  EXPECT_NE(output.find("6 frames on 4 displays from 4 pipeservers"), std::string::npos) << output;

  const auto rows = read_csv(run.out() / "report.csv");
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(frames + 1));
  ASSERT_EQ(rows[0][3], "latency_frames");
  for (int k = 1; k <= frames; ++k) {
    EXPECT_EQ(rows[k][0], std::to_string(k - 1));
    EXPECT_EQ(std::stoi(rows[k][2]) - std::stoi(rows[k][1]), 1) << "frame " << k - 1;
    EXPECT_EQ(rows[k][3], "1");
  }
  // Independently of the run's own bookkeeping: each kept display picture carries, at every
  // host's first tile, the number of the frame it was kept for.
  const TileLayout layout = plan_layout(default_wall());
  for (int k = 0; k < frames; ++k) {
    for (const ServerPlan& plan : layout.servers) {
      const DisplayTile& t = plan.tiles.front().tile;
      const RgbImage shown = read_png(run.out() / fmt::format("frame-{}", k) /
                                      fmt::format("display-{}.png", t.display));
      const Rgb px = shown.at(t.on_display.x, t.on_display.y);
      const std::uint8_t bytes[3] = {px.r, px.g, px.b};
      EXPECT_EQ(decode_stamp(bytes), k) << "server " << plan.server << " display " << t.display;
    }
  }
  EXPECT_TRUE(fs::exists(run.out() / "frame-0" / "wall.png"));
  expect_clean(run);
}

// The DVI path (shared memory, emulated Lightning-2) and the vizserver path (tiles over TCP to
// a compositing server) give the same displays, byte for byte, on two example walls.
struct WallCase {
  const char* file;
  int displays, servers;
};
class BothPaths : public ::testing::TestWithParam<WallCase> {};

TEST_P(BothPaths, GiveIdenticalDisplays) {
  const WallCase& c = GetParam();
  WallRun run(fmt::format("both-{}", c.servers),
              {fmt::format("{}/walls/{}", L2_SOURCE_DIR, c.file), "--frames", "10", "--refresh",
               "0", "--path", "both", "--compare"});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  EXPECT_NE(output.find(
                fmt::format("10 frames on {} displays from {} pipeservers", c.displays, c.servers)),
            std::string::npos)
      << output;
  EXPECT_NE(output.find(fmt::format("compare: {} display pictures identical byte for byte",
                                    10 * c.displays)),
            std::string::npos)
      << output;
  EXPECT_NE(output.find("latency: 1 frame "), std::string::npos) << output;
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

INSTANTIATE_TEST_SUITE_P(ExampleWalls, BothPaths,
                         ::testing::Values(WallCase{"kd-2x2.toml", 4, 4},
                                           WallCase{"projectors-2x1.toml", 2, 3}));

TEST(LiveRun, VizserverPathAloneShowsEveryFrame) {
  WallRun run("viz", {"--frames", "4", "--path", "vizserver", "--keep", "every"});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  const TileLayout layout = plan_layout(default_wall());
  for (int k = 0; k < 4; ++k) {
    const DisplayTile& t = layout.servers.front().tiles.front().tile;
    const RgbImage shown =
        read_png(run.out() / fmt::format("frame-{}", k) / fmt::format("display-{}.png", t.display));
    const Rgb px = shown.at(t.on_display.x, t.on_display.y);
    const std::uint8_t bytes[3] = {px.r, px.g, px.b};
    EXPECT_EQ(decode_stamp(bytes), k);
  }
  expect_clean(run);
}

// Waits until pipeserver `server` has published a few frames; returns its pid.
pid_t running_pipeserver(const WallRun& run, int server) {
  const auto deadline = std::chrono::steady_clock::now() + 20s;
  while (std::chrono::steady_clock::now() < deadline) {
    const auto pids = run.pipeservers(server);
    if (pids.size() == 1 && run.host_log_lines(server) >= 3) return pids.front();
    std::this_thread::sleep_for(20ms);
  }
  return -1;
}

TEST(LiveRun, KilledPipeserverIsNamedAndEverythingIsCleanedUp) {
  WallRun run("killed", {"--frames", "100000", "--refresh", "60"});
  const pid_t victim = running_pipeserver(run, 1);
  ASSERT_GT(victim, 0) << run.output();
  ASSERT_EQ(kill(victim, SIGKILL), 0);
  const auto t0 = std::chrono::steady_clock::now();
  const ExitStatus status = run.wait(10s);
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 5s);
  const std::string output = run.output();
  EXPECT_FALSE(status.ok());
  EXPECT_NE(output.find(fmt::format("pipeserver 1 (pid {}) killed by signal 9", victim)),
            std::string::npos)
      << output;
  EXPECT_NE(output.find("while rendering frame "), std::string::npos) << output;
  EXPECT_TRUE(fs::exists(run.out() / "fault" / "display-0.png")) << output;
  expect_clean(run);
}

TEST(LiveRun, HungPipeserverIsNamedWithinTheStallTimeout) {
  WallRun run("hung", {"--frames", "100000", "--refresh", "60", "--stall-timeout", "1000"});
  const pid_t victim = running_pipeserver(run, 2);
  ASSERT_GT(victim, 0) << run.output();
  ASSERT_EQ(kill(victim, SIGSTOP), 0);
  const auto t0 = std::chrono::steady_clock::now();
  const ExitStatus status = run.wait(10s);
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 5s);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << output;
  EXPECT_NE(output.find(fmt::format("pipeserver 2 (pid {}) did not deliver frame", victim)),
            std::string::npos)
      << output;
  expect_clean(run);
}

TEST(LiveRun, TerminatedRunEndsItsHostsAndRemovesTheirLinks) {
  WallRun run("sigterm", {"--frames", "100000", "--refresh", "60"});
  ASSERT_GT(running_pipeserver(run, 0), 0) << run.output();
  ASSERT_EQ(kill(run.pid(), SIGTERM), 0);
  const ExitStatus status = run.wait(10s);
  const std::string output = run.output();
  EXPECT_EQ(status.code, 1) << output;
  EXPECT_NE(output.find("stopped by signal 15"), std::string::npos) << output;
  expect_clean(run);
}

TEST(LiveRun, LineNoiseAndADroppedReadyAreRecovered) {
  WallRun run("noise", {"--frames", "6", "--refresh", "0", "--inject-noise", "1", "--drop-ready",
                        "3", "--ready-timeout", "200"});
  const ExitStatus status = run.wait(30s);
  const std::string output = run.output();
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << output;
  EXPECT_NE(output.find("1 READY dropped"), std::string::npos) << output;
  EXPECT_NE(output.find("latency: 1 frame "), std::string::npos) << output;
  for (int i = 0; i < 4; ++i) {
    const auto at = output.find(fmt::format("back-channel host {}: resyncs ", i));
    ASSERT_NE(at, std::string::npos) << output;
    int resyncs = 0, noise = 0, sync_sent = 0;
    ASSERT_EQ(std::sscanf(output.c_str() + at,
                          "back-channel host %*d: resyncs %d noise_bytes %d sync_sent %d", &resyncs,
                          &noise, &sync_sent),
              3)
        << output.substr(at, 80);
    EXPECT_GT(resyncs, 0) << "host " << i;
    EXPECT_GT(noise, 0) << "host " << i;
    if (i == 0) {
      EXPECT_GE(sync_sent, 1);
    }
  }
  expect_clean(run);
}

}  // namespace
}  // namespace l2
