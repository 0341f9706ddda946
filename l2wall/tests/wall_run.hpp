// A live `l2wall run` driven by a test: its own folder, output captured, and what it must
// leave behind checked (shm segments, pipeserver processes).
#pragma once

#include <arpa/inet.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>
#include "base/child_process.hpp"
#include "base/process_table.hpp"
#include "image/png_io.hpp"
#include "l2wall/frame_stamp.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/survival.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2::testing_support {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

inline std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A test's own folder for what it writes before a run (pictures, wall files): empty when made,
// named by the test and the process so parallel tests never share one, and removed when the
// test ends, a failed ASSERT included.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(fs::temp_directory_path() / fmt::format("l2wall-{}-{}", name, getpid())) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

// One l2wall run in its own folder; its output goes to DIR/output.txt.
class WallRun {
 public:
  // How long a run stopped by SIGTERM has to end its own way before it is killed.
  static constexpr std::chrono::seconds kStopGrace{10};

  // `before` gets the --out folder (made, empty) before l2wall starts. `own_session`: l2wall
  // leads a session and process group of its own (setsid), which its pipeservers join, as a
  // command started from a terminal leads the terminal's foreground group. `launcher`: words
  // (shell syntax) that start l2wall, e.g. "mpirun -np 6"; pid() is then the launcher's.
  // `progress`: without --no-progress, so the run decides for itself (its stderr is a file).
  // `input`: a file (a pipe) for l2wall's stdin.
  WallRun(const std::string& name, const std::vector<std::string>& args,
          const std::function<void(const fs::path& out)>& before = {}, bool own_session = false,
          const std::string& launcher = "", bool progress = false, const std::string& input = "")
      : dir_(folder_for(name)) {
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "out");
    if (before) before(dir_ / "out");
    // setsid execs l2wall in place (this shell leads no group), so pid() stays l2wall's.
    std::string command =
        fmt::format("exec {}{}'{}' run --out '{}'{}", own_session ? "setsid " : "",
                    launcher.empty() ? "" : launcher + " ", L2WALL_PATH, (dir_ / "out").string(),
                    progress ? "" : " --no-progress");
    for (const auto& a : args) command += " '" + a + "'";
    command += fmt::format(" > '{}' 2>&1", (dir_ / "output.txt").string());
    if (!input.empty()) command += fmt::format(" < '{}'", input);
    // exec: the shell becomes l2wall, so pid() is l2wall's and names its shm segments.
    process_.emplace(std::vector<std::string>{"/bin/sh", "-c", command});
  }
  // The folder a run of this name works in; its --out is out/ in it.
  static fs::path folder_for(const std::string& name) {
    return fs::temp_directory_path() / fmt::format("l2wall-test-{}-{}", getpid(), name);
  }
  // A run still going is stopped as a user stops it (SIGTERM, as Ctrl-C): l2wall ends its
  // pipeservers one by one and removes their links, which takes longer than ChildProcess's
  // half-second grace; killed in the middle, it would leave the rest of them behind.
  ~WallRun() {
    if (process_ && !process_->poll()) process_->terminate(kStopGrace);
    process_.reset();
    fs::remove_all(dir_);
  }
  ExitStatus wait(std::chrono::milliseconds timeout) {
    auto status = process_->wait_for(timeout);
    if (!status) {
      ADD_FAILURE() << "l2wall did not end within " << timeout.count() << " ms";
      status = process_->terminate(kStopGrace);
    }
    return *status;
  }
  // Whether l2wall has ended (reaped here; wait() then returns at once).
  bool ended() { return process_->poll().has_value(); }
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
  std::vector<pid_t> pipeservers(int pipeserver = -1) const {
    return processes_with_command_line(
        "/" + link_prefix() + (pipeserver >= 0 ? fmt::format("{}", pipeserver) + '\0' : ""));
  }
  // Processes whose command line names this run's output folder: its pipeservers (--report
  // OUT/pipeserver-<i>.log) and its compositing server (--log OUT/vizserver.log), on every path.
  std::vector<pid_t> processes_naming(const std::string& what) const {
    return processes_with_command_line((out() / what).string());
  }
  std::vector<pid_t> vizservers() const { return processes_naming("vizserver.log"); }
  // The frames pipeserver `pipeserver` has logged ("frame K ..." lines: its log opens with the
  // renderer it decided on).
  int pipeserver_frames_logged(int pipeserver) const {
    std::ifstream in(out() / fmt::format("pipeserver-{}.log", pipeserver));
    int frames = 0;
    for (std::string l; std::getline(in, l);) frames += l.rfind("frame ", 0) == 0;
    return frames;
  }

 private:
  fs::path dir_;
  std::optional<ChildProcess> process_;
};

// A TCP port on 127.0.0.1 held until destroyed: listening (connections wait in its backlog), or
// only bound, so that connections to it are refused and no other program can take it meanwhile.
class HeldPort {
 public:
  enum class Mode { kListening, kRefusing };
  explicit HeldPort(Mode mode = Mode::kListening) : fd_(socket(AF_INET, SOCK_STREAM, 0)) {
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof addr;
    if (!fd_ || bind(fd_.get(), reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 ||
        (mode == Mode::kListening && listen(fd_.get(), 1) != 0) ||
        getsockname(fd_.get(), reinterpret_cast<sockaddr*>(&addr), &len) != 0)
      ADD_FAILURE() << "cannot hold a TCP port";
    port = ntohs(addr.sin_port);
  }
  int port = 0;

 private:
  Fd fd_;
};

inline std::vector<std::vector<std::string>> read_csv(const fs::path& path) {
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

inline void expect_clean(const WallRun& run) {
  EXPECT_TRUE(run.leftover_segments().empty())
      << "shm segment left: " << run.leftover_segments().front();
  EXPECT_TRUE(run.pipeservers().empty()) << "orphan pipeserver pid " << run.pipeservers().front();
  const auto children = run.processes_naming("");
  EXPECT_TRUE(children.empty()) << "orphan process pid " << children.front();
}

// The default wall with framebuffers large enough for three pipeservers to hold the tiles of
// four (the default wall's own 800x600 cannot), and more of the balancer's re-cut layouts fit.
// `extra` goes at the end ([balance], say).
inline fs::path write_roomy_default_wall(const fs::path& dir, const std::string& extra = "") {
  std::string text(default_wall_toml());
  for (const auto& [from, to] :
       {std::pair{std::string("framebuffer_width = 800"), std::string("framebuffer_width = 1024")},
        std::pair{std::string("framebuffer_height = 600"),
                  std::string("framebuffer_height = 768")}}) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  fs::create_directories(dir);
  const fs::path file = dir / "roomy-default.toml";
  std::ofstream(file) << text << extra;
  return file;
}

// Four 320x240 displays cut into 320x60 tiles for four pipeservers, their framebuffers 322 wide
// (one tile a row, after its gap) and `height` high, written to DIR/`name`.
inline constexpr int kGridFramebufferWidth = 322;
inline std::string grid_wall(int height) {
  return fmt::format(
      "[display_grid]\ncolumns = 2\nrows = 2\nwidth = 320\nheight = 240\n"
      "[tiling]\nkind = \"grid\"\ntile_width = 320\ntile_height = 60\n"
      "[pipeservers]\ncount = 4\nframebuffer_width = {}\nframebuffer_height = {}\n",
      kGridFramebufferWidth, height);
}

// The grid wall at the framebuffer height tilelayout finds for `lost` losses, written to
// DIR/`name`.
inline fs::path grid_wall_surviving(const fs::path& dir, const std::string& name, int lost) {
  const std::optional<int> height = survival_height(parse_wall(grid_wall(240), "grid.toml"), lost);
  EXPECT_TRUE(height);
  fs::create_directories(dir);
  const fs::path file = dir / name;
  std::ofstream(file) << grid_wall(height.value_or(240));
  return file;
}

// Waits until `path` exists (a frame's folder the run keeps, a file it writes); whether it does.
inline bool wait_for_file(const fs::path& path, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!fs::exists(path) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(20ms);
  return fs::exists(path);
}

// Pipeserver `pipeserver`'s pid once it runs and has logged `frames` frames (0: as soon as it
// runs, before its first frame reaches anyone); -1 if that never happens. Found by its log
// (--report OUT/pipeserver-<i>.log), which it has on every path.
inline pid_t pipeserver_at(const WallRun& run, int pipeserver, int frames) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    const auto pids = run.processes_naming(fmt::format("pipeserver-{}.log", pipeserver));
    if (pids.size() == 1 && run.pipeserver_frames_logged(pipeserver) >= frames) return pids.front();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return -1;
}

// Waits until pipeserver `pipeserver` has published a few frames; returns its pid.
inline pid_t running_pipeserver(const WallRun& run, int pipeserver) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (std::chrono::steady_clock::now() < deadline) {
    const auto pids = run.pipeservers(pipeserver);
    if (pids.size() == 1 && run.pipeserver_frames_logged(pipeserver) >= 3) return pids.front();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return -1;
}

// Pixels of the kept displays of frame `frame` of `wall` that are not `expected(u, v)`, the
// canvas pixel each shows, every pipeserver's frame-stamp pixel aside (a framebuffer with no
// room for a stamp strip marks its first tile's first pixel with the frame). The first three
// are each a failure saying where and what.
template <class Expected>
long wrong_canvas_pixels(const WallRun& run, const Wall& wall, int frame, Expected expected) {
  const TileLayout layout = plan_layout(wall);
  long wrong = 0;
  for (const Display& display : wall.displays) {
    const RgbImage shown = read_png(run.out() / fmt::format("frame-{}", frame) /
                                    fmt::format("display-{}.png", display.id));
    std::vector<std::pair<int, int>> stamps;
    for (const PipeserverPlan& plan : layout.pipeservers) {
      const DisplayTile& t = plan.tiles.front().tile;
      if (t.display == display.id) stamps.emplace_back(t.on_display.x, t.on_display.y);
    }
    const Rect r = display.on_canvas();
    for (int y = 0; y < shown.height(); ++y) {
      for (int x = 0; x < shown.width(); ++x) {
        if (std::find(stamps.begin(), stamps.end(), std::pair{x, y}) != stamps.end()) continue;
        const Rgb want = expected(r.x + x, r.y + y), got = shown.at(x, y);
        if (got == want || ++wrong > 3) continue;
        ADD_FAILURE() << fmt::format(
            "display {} pixel {},{} (canvas {},{}): {},{},{} instead of {},{},{}", display.id, x, y,
            r.x + x, r.y + y, got.r, got.g, got.b, want.r, want.g, want.b);
      }
    }
  }
  return wrong;
}

}  // namespace l2::testing_support
