// A desktop on the wall through `l2wall run --scene vnc`: a private Xvnc (TigerVNC) on a display
// it picks itself, loopback only, showing a known picture on its root window. Every display
// must equal the desktop at its canvas position, 1:1, as the X server itself gives the root
// back (XGetImage, not RFB); a desktop that changes every ~30 ms must never show two states at
// once; and an unreachable server, a refused password, a server gone or a desktop resized
// mid-run are one line.
#include <sys/stat.h>

#include <atomic>
#include <set>
#include <thread>
#include <tuple>

#include "session_references.hpp"
#include "wall_run.hpp"
#include "wide_wall.hpp"
#include "xvnc_desktop.hpp"

namespace l2 {
namespace {

using namespace testing_support;

class VncRun : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!installed("Xvnc")) GTEST_SKIP() << "Xvnc is not installed (tigervnc-standalone-server)";
  }
};

// Every display of frame `frame` against `desktop` at the display's canvas position (black
// past the desktop's edge), each pipeserver's frame stamp aside; returns the wrong pixels.
long wrong_pixels(const WallRun& run, const Wall& wall, int frame, const RgbImage& desktop) {
  return wrong_canvas_pixels(run, wall, frame, [&](int u, int v) {
    return u < desktop.width() && v < desktop.height() ? desktop.at(u, v) : Rgb{};
  });
}

void expect_desktop_on(const std::string& name, const fs::path& wall_file, const Xvnc& vnc,
                       const RgbImage& desktop, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args{"--scene", "vnc", "--content", vnc.address, "--frames", "3"};
  if (!wall_file.empty()) args.insert(args.end(), {"--wall", wall_file.string()});
  args.insert(args.end(), extra.begin(), extra.end());
  WallRun run(name, args);
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << run.output();
  const Wall wall = wall_file.empty() ? default_wall() : load_wall(wall_file);
  EXPECT_EQ(wrong_pixels(run, wall, 2, desktop), 0) << name;
  EXPECT_NE(run.output().find("vnc: desktop " + std::to_string(vnc.width) + "x" +
                              std::to_string(vnc.height)),
            std::string::npos)
      << run.output();
  expect_clean(run);
}

TEST_F(VncRun, EveryDisplayIsTheDesktopAtItsCanvasPosition) {
  Xvnc vnc;
  XClient x(vnc.server->display());
  x.show_on_root(position_picture(vnc.width, vnc.height));
  // What the X server itself holds: the expected desktop, not what RFB carried.
  const RgbImage desktop = x.read(x.root(), 0, 0, vnc.width, vnc.height);
  ASSERT_EQ(desktop.at(300, 260), (Rgb{300 & 255, 260 & 255, 16 + 1 + 1}));
  expect_desktop_on("vnc-default", {}, vnc, desktop);
  const fs::path dir = WallRun::folder_for("vnc-walls");
  fs::create_directories(dir);
  expect_desktop_on("vnc-3x1", write_wide_wall(dir), vnc, desktop);
  fs::remove_all(dir);
}

TEST_F(VncRun, ADesktopChangingEveryFewFramesIsNeverTorn) {
  Xvnc vnc;
  // Six colours, one after another every ~30 ms, for as long as the run lasts.
  const std::vector<std::string> colours{"#ff0000", "#00ff00", "#0000ff",
                                         "#ffff00", "#00ffff", "#ff00ff"};
  std::atomic<bool> stop{false};
  std::thread painter([&] {
    for (std::size_t i = 0; !stop; ++i) {
      run_shell(fmt::format("DISPLAY={} xsetroot -solid '{}'", vnc.server->display(),
                            colours[i % colours.size()]),
                10s);
      std::this_thread::sleep_for(30ms);
    }
  });
  const int frames = 40;
  WallRun run("vnc-tearing", {"--scene", "vnc", "--content", vnc.address, "--frames",
                              std::to_string(frames), "--keep", "every"});
  const ExitStatus status = run.wait(180s);
  stop = true;
  painter.join();
  ASSERT_TRUE(status.ok()) << run.output();
  const Wall wall = default_wall();
  const TileLayout layout = plan_layout(wall);
  std::set<std::tuple<int, int, int>> seen;
  for (int k = 0; k < frames; ++k) {
    std::set<std::tuple<int, int, int>> in_frame;
    for (const Display& display : wall.displays) {
      const RgbImage shown = read_png(run.out() / fmt::format("frame-{}", k) /
                                      fmt::format("display-{}.png", display.id));
      for (int y = 0; y < shown.height(); ++y) {
        for (int x = 0; x < shown.width(); ++x) {
          bool stamp = false;
          for (const PipeserverPlan& plan : layout.pipeservers) {
            const DisplayTile& t = plan.tiles.front().tile;
            stamp =
                stamp || (t.display == display.id && t.on_display.x == x && t.on_display.y == y);
          }
          if (stamp) continue;
          const Rgb c = shown.at(x, y);
          in_frame.insert({c.r, c.g, c.b});
        }
      }
    }
    EXPECT_EQ(in_frame.size(), 1u)
        << "frame " << k << " shows " << in_frame.size() << " colours at once";
    seen.insert(in_frame.begin(), in_frame.end());
  }
  // The desktop did change during the run: the frames followed it.
  EXPECT_GE(seen.size(), 3u);
  expect_clean(run);
}

TEST_F(VncRun, APasswordFileOpensAServerThatWantsOne) {
  if (!installed("vncpasswd")) GTEST_SKIP() << "vncpasswd is not installed (tigervnc-tools)";
  const fs::path dir = WallRun::folder_for("vnc-password");
  fs::create_directories(dir);
  const fs::path right = dir / "right.passwd", wrong = dir / "wrong.passwd";
  ASSERT_TRUE(run_shell(fmt::format("echo wall-pw1 | vncpasswd -f > '{}'", right.string()), 10s)
                  .status.ok());
  ASSERT_TRUE(run_shell(fmt::format("echo other-pw | vncpasswd -f > '{}'", wrong.string()), 10s)
                  .status.ok());
  Xvnc vnc(right);
  XClient x(vnc.server->display());
  x.show_on_root(position_picture(vnc.width, vnc.height));
  const RgbImage desktop = x.read(x.root(), 0, 0, vnc.width, vnc.height);
  expect_desktop_on("vnc-password-ok", {}, vnc, desktop, {"--vnc-password-file", right.string()});

  WallRun refused("vnc-password-wrong", {"--scene", "vnc", "--content", vnc.address, "--frames",
                                         "3", "--vnc-password-file", wrong.string()});
  EXPECT_EQ(refused.wait(60s).code, 1);
  const std::string said = refused.output();
  EXPECT_EQ(said.rfind("l2wall: vnc " + vnc.address + ": the server refused the password", 0), 0u)
      << said;
  EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 1) << said;

  WallRun none("vnc-password-none", {"--scene", "vnc", "--content", vnc.address, "--frames", "3"});
  EXPECT_EQ(none.wait(60s).code, 1);
  EXPECT_EQ(none.output(), "l2wall: vnc " + vnc.address +
                               ": the server wants a password: give it with --vnc-password-file\n");
  fs::remove_all(dir);
}

TEST_F(VncRun, AServerThatCannotBeReachedIsOneLine) {
  const HeldPort closed(HeldPort::Mode::kRefusing);
  const int port = closed.port;
  const std::string address = fmt::format("127.0.0.1::{}", port);
  WallRun run("vnc-unreachable", {"--scene", "vnc", "--content", address, "--frames", "3"});
  EXPECT_EQ(run.wait(60s).code, 1);
  const std::string out = run.output();
  EXPECT_EQ(
      out.rfind(fmt::format("l2wall: vnc {}: cannot connect to 127.0.0.1 port {}: ", address, port),
                0),
      0u)
      << out;
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << out;
  expect_clean(run);
}

TEST_F(VncRun, AServerGoneMidRunEndsTheRunNamingIt) {
  auto vnc = std::make_unique<Xvnc>();
  const std::string address = vnc->address;
  WallRun run("vnc-gone", {"--scene", "vnc", "--content", address, "--frames", "100000"});
  // Once frames reach the displays, the server goes.
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (run.pipeserver_frames_logged(0) < 3 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(50ms);
  ASSERT_GE(run.pipeserver_frames_logged(0), 3) << run.output();
  vnc.reset();
  EXPECT_EQ(run.wait(60s).code, 1);
  EXPECT_NE(run.output().find("l2wall: vnc " + address + ": the server closed the connection"),
            std::string::npos)
      << run.output();
  expect_clean(run);
}

TEST_F(VncRun, ADesktopResizedMidRunEndsTheRunSayingSo) {
  if (!installed("xrandr")) GTEST_SKIP() << "xrandr is not installed (x11-xserver-utils)";
  Xvnc vnc;
  WallRun run("vnc-resized", {"--scene", "vnc", "--content", vnc.address, "--frames", "100000"});
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (run.pipeserver_frames_logged(0) < 3 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(50ms);
  ASSERT_GE(run.pipeserver_frames_logged(0), 3) << run.output();
  ASSERT_TRUE(run_shell(fmt::format("DISPLAY={} xrandr -s 1024x768", vnc.server->display()), 30s)
                  .status.ok());
  EXPECT_EQ(run.wait(60s).code, 1);
  EXPECT_EQ(run.output().rfind(fmt::format("l2wall: vnc {}: the desktop changed size from {}x{} "
                                           "to 1024x768; the run shows one size\n",
                                           vnc.address, vnc.width, vnc.height),
                               0),
            0u)
      << run.output();
  expect_clean(run);
}

// A wall of four overlapping windows: the desktop (laid on its window by fill, so nearest
// sampling picks some of its pixels), a model, a picture at 1:1 and a movie stretched. Every
// display of every frame must equal the reference render of the same session with the desktop
// window showing a picture of the desktop as the X server holds it: a vnc window draws a
// desktop as a picture window draws a picture. Mid-run, the desktop window moves (a line on
// stdin): from the frame the coordinator moved it in, every display shows it in its new place.
TEST_F(VncRun, AWallOfFourWindowsWithADesktopEqualsItsReference) {
  Xvnc vnc;
  XClient x(vnc.server->display());
  x.show_on_root(position_picture(vnc.width, vnc.height));
  const fs::path dir = WallRun::folder_for("vnc-windows-files");
  fs::create_directories(dir);
  write_png(dir / "desktop.png", x.read(x.root(), 0, 0, vnc.width, vnc.height));
  write_png(dir / "pattern.png", position_picture(300, 200));
  ASSERT_TRUE(run({"/usr/bin/ffmpeg", "-loglevel", "error", "-y", "-f", "lavfi", "-i",
                   "testsrc2=size=160x120:rate=10", "-frames:v", "3", "-c:v", "ffv1", "-pix_fmt",
                   "bgr0", (dir / "clip.mkv").string()},
                  60s)
                  .status.ok());
  // The default wall's canvas is 1300x980: every window crosses a mullion.
  const std::string others =
      "[[window]]\nsource = \"mesh\"\nx = 500\ny = 60\nwidth = 700\nheight = 520\n"
      "[[window]]\nsource = \"picture\"\ncontent = \"pattern.png\"\nfit = \"1:1\"\nz = 2\n"
      "x = 560\ny = 420\nwidth = 260\nheight = 180\n"
      "[[window]]\nsource = \"movie\"\ncontent = \"clip.mkv\"\nfit = \"stretch\"\nz = 3\n"
      "x = 880\ny = 600\nwidth = 380\nheight = 300\n";
  const auto desktop = [](const std::string& source, const std::string& content, int left,
                          int top) {
    return fmt::format(
        "[[window]]\nid = 9\nsource = \"{}\"\ncontent = \"{}\"\nfit = \"fill\"\nz = 1\n"
        "x = {}\ny = {}\nwidth = 620\nheight = 400\n",
        source, content, left, top);
  };
  std::ofstream(dir / "session.toml") << desktop("vnc", vnc.address, 40, 300) << others;
  std::ofstream(dir / "reference.toml") << desktop("picture", "desktop.png", 40, 300) << others;
  std::ofstream(dir / "moved.toml") << desktop("picture", "desktop.png", 300, 80) << others;

  const fs::path fifo = dir / "commands";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  constexpr int kFrames = 16;
  WallRun run("vnc-windows",
              {"--scene", "session", "--session", (dir / "session.toml").string(), "--frames",
               std::to_string(kFrames), "--keep", "every", "--refresh", "0", "--window-stdin"},
              {}, false, "", false, fifo.string());
  std::ofstream commands(fifo);  // opens once the shell opened its end for l2wall
  wait_for_file(run.out() / "frame-3", 60s);
  commands << "move 9 300 80 620 400\n" << std::flush;
  commands.close();
  const ExitStatus status = run.wait(180s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  // The frame the coordinator moved it in.
  std::ifstream lines(run.out() / "windows.txt");
  int moved = -1, frame = 0;
  for (std::string line; std::getline(lines, line) && moved < 0; ++frame)
    if (line.find(" 9 300 80 620 400") != std::string::npos) moved = frame;
  ASSERT_GT(moved, 1);
  ASSERT_LT(moved, kFrames);
  for (const int k : {0, moved - 1, moved, kFrames - 1})
    expect_references(run, k, dir / (k < moved ? "reference.toml" : "moved.toml"));
  EXPECT_NE(run.output().find(fmt::format("window 9: vnc: desktop {}x{}", vnc.width, vnc.height)),
            std::string::npos)
      << run.output();
  expect_clean(run);
  fs::remove_all(dir);
}

// A desktop window's server that cannot be reached, refuses the password or goes mid-run is
// the vnc scene's one line, naming the window.
TEST_F(VncRun, ADesktopWindowsErrorsNameTheWindow) {
  const fs::path dir = WallRun::folder_for("vnc-window-errors-files");
  fs::create_directories(dir);
  const auto session = [&dir](const std::string& name, const std::string& address,
                              const std::string& password) {
    std::ofstream(dir / name) << "[[window]]\nsource = \"swap\"\nx = 0\ny = 0\nwidth = 300\n"
                                 "height = 200\n[[window]]\nid = 2\nsource = \"vnc\"\ncontent = \""
                              << address << "\"\n"
                              << password << "x = 100\ny = 100\nwidth = 900\nheight = 700\n";
    return std::vector<std::string>{"--scene",  "session", "--session", (dir / name).string(),
                                    "--frames", "100000"};
  };
  const HeldPort closed(HeldPort::Mode::kRefusing);
  const std::string nobody = fmt::format("127.0.0.1::{}", closed.port);
  WallRun unreachable("vnc-window-unreachable", session("a.toml", nobody, ""));
  EXPECT_EQ(unreachable.wait(60s).code, 1);
  const std::string said = unreachable.output();
  EXPECT_EQ(
      said.rfind(fmt::format("l2wall: window 2: vnc {}: cannot connect to 127.0.0.1 port {}: ",
                             nobody, closed.port),
                 0),
      0u)
      << said;
  EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 1) << said;

  if (installed("vncpasswd")) {
    ASSERT_TRUE(run_shell(fmt::format("echo wall-pw1 | vncpasswd -f > '{}/right'; echo other-pw | "
                                      "vncpasswd -f > '{}/wrong'",
                                      dir.string(), dir.string()),
                          10s)
                    .status.ok());
    Xvnc locked(dir / "right");
    WallRun refused("vnc-window-refused",
                    session("b.toml", locked.address, "password_file = \"wrong\"\n"));
    EXPECT_EQ(refused.wait(60s).code, 1);
    EXPECT_EQ(
        refused.output().rfind(
            "l2wall: window 2: vnc " + locked.address + ": the server refused the password", 0),
        0u)
        << refused.output();
  }

  auto vnc = std::make_unique<Xvnc>();
  const std::string address = vnc->address;
  WallRun gone("vnc-window-gone", session("c.toml", address, ""));
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (gone.pipeserver_frames_logged(0) < 3 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(50ms);
  ASSERT_GE(gone.pipeserver_frames_logged(0), 3) << gone.output();
  vnc.reset();
  EXPECT_EQ(gone.wait(60s).code, 1);
  EXPECT_NE(
      gone.output().find("l2wall: window 2: vnc " + address + ": the server closed the connection"),
      std::string::npos)
      << gone.output();
  expect_clean(gone);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace l2
