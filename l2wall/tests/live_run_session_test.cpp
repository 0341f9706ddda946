// A session of overlapping windows through `l2wall run`: every display of every kept frame
// equals its reference render (`pipeserver --reference`) byte for byte, but for the frame
// stamps, which are checked to carry their frame; a window moved from the control page moves on
// every display in the same frame.
#include <sys/stat.h>

#include "control_page_run.hpp"
#include "session_references.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

using namespace testing_support;

Rgb pattern(int x, int y) {
  return {static_cast<std::uint8_t>(x * 3), static_cast<std::uint8_t>(y * 5),
          static_cast<std::uint8_t>(x ^ y)};
}

// The default wall's canvas is 1300x980; the windows cross the mullions and the wall's edge.
const char* kSession = R"(
background = 0x302010

[[window]]
source = "mesh"
x = 40
y = 30
width = 760
height = 560

[[window]]
source = "picture"
content = "pattern.png"
fit = "1:1"
x = 500
y = 380
width = 400
height = 300
z = 2

[[window]]
source = "isosurface"
x = 720
y = 420
width = 640
height = 600
z = 1

[[window]]
source = "picture"
content = "pattern.png"
fit = "fit"
x = -100
y = 600
width = 500
height = 500
z = 3
)";

fs::path write_pattern(const fs::path& dir) {
  fs::create_directories(dir);
  RgbImage picture(320, 240);
  for (int y = 0; y < picture.height(); ++y)
    for (int x = 0; x < picture.width(); ++x) picture.set(x, y, pattern(x, y));
  write_png(dir / "pattern.png", picture);
  return dir / "pattern.png";
}

TEST(SessionOnTheWall, EveryDisplayEqualsItsReference) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-session-{}", getpid());
  write_pattern(dir);
  std::ofstream(dir / "session.toml") << kSession;
  // A movie window too, where the ffmpeg tool can make one: FFV1, lossless, so nearest
  // sampling shows its pixels as decoded, and the movie frame changes with the frame.
  const fs::path movie = dir / "clip.mkv";
  if (run({"/usr/bin/ffmpeg", "-loglevel", "error", "-y", "-f", "lavfi", "-i",
           "testsrc2=size=200x150:rate=10", "-frames:v", "3", "-c:v", "ffv1", "-pix_fmt", "bgr0",
           movie.string()},
          60s)
          .status.ok()) {
    std::ofstream(dir / "session.toml", std::ios::app)
        << "\n[[window]]\nsource = \"movie\"\ncontent = \"clip.mkv\"\nfit = \"stretch\"\n"
           "x = 880\ny = 40\nwidth = 380\nheight = 300\nz = 4\n";
  } else {
    std::fprintf(stderr, "no ffmpeg tool: the session has no movie window\n");
  }
  constexpr int kFrames = 3;
  WallRun run("session",
              {"--scene", "session", "--session", (dir / "session.toml").string(), "--frames",
               std::to_string(kFrames), "--keep", "every", "--refresh", "0"});
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  for (int frame = 0; frame < kFrames; ++frame) expect_references(run, frame, dir / "session.toml");
  expect_clean(run);
  fs::remove_all(dir);
}

// A picture window over the swap scene's window, which a test moves while the wall runs.
struct MovingSession {
  static constexpr int kFrames = 60;
  fs::path dir;

  explicit MovingSession(const std::string& name)
      : dir(fs::temp_directory_path() / fmt::format("l2wall-{}-{}", name, getpid())) {
    write_pattern(dir);
    const std::string swap =
        "[[window]]\nsource = \"swap\"\nx = 100\ny = 100\nwidth = 400\nheight = 300\n";
    const std::string picture =
        "[[window]]\nsource = \"picture\"\ncontent = \"pattern.png\"\n"
        "fit = \"1:1\"\nz = 1\nwidth = 200\nheight = 150\n";
    std::ofstream(dir / "session.toml") << swap << picture << "x = 300\ny = 200\n";
    std::ofstream(dir / "moved.toml") << swap << picture << "x = 600\ny = 420\n";
  }
  ~MovingSession() { fs::remove_all(dir); }

  std::vector<std::string> args() const {
    return {"--scene",   "session",
            "--session", (dir / "session.toml").string(),
            "--frames",  std::to_string(kFrames),
            "--keep",    "every"};
  }

  // After the run, moved by "move 1 600 420 200 150": every frame before the one the
  // coordinator's WINDOWS lines moved it in shows it in its old place on every display, every
  // frame from it on in its new place, across a mullion.
  void expect_moved_once(const WallRun& run) const {
    std::ifstream lines(run.out() / "windows.txt");
    int moved = -1;
    int frame = 0;
    for (std::string line; std::getline(lines, line); ++frame) {
      const bool there = line.find(" 1 600 420 200 150") != std::string::npos;
      if (there && moved < 0) moved = frame;
      EXPECT_EQ(there, moved >= 0) << line;  // moved once, and stays
    }
    ASSERT_GT(moved, 5);
    ASSERT_LT(moved, kFrames);
    EXPECT_NE(slurp(run.out() / "summary.txt")
                  .find(fmt::format("windows: move 1 600 420 200 150 from frame {}", moved)),
              std::string::npos);
    // Every display, around the frame it moved in and at the end, equals its session's
    // reference.
    for (const int k : {moved - 2, moved - 1, moved, moved + 1, kFrames - 1})
      expect_references(run, k, dir / (k < moved ? "session.toml" : "moved.toml"));
    // And every frame: the picture's corner in its old place on display 0 (canvas 310,210)
    // until the frame it moved in, its corner beyond the mullions on display 3 (canvas 670,510)
    // from it.
    const auto at = [&run](int k, int display, int x, int y) {
      return read_png(run.out() / fmt::format("frame-{}", k) /
                      fmt::format("display-{}.png", display))
          .at(x, y);
    };
    for (int k = 0; k < kFrames; ++k) {
      EXPECT_EQ(at(k, 0, 310, 210) == pattern(10, 10), k < moved) << "frame " << k;
      EXPECT_EQ(at(k, 3, 10, 10) == pattern(70, 90), k >= moved) << "frame " << k;
    }
  }
};

TEST(SessionOnTheWall, AWindowMovedFromThePageMovesOnEveryDisplayInOneFrame) {
  const MovingSession session("session-page");
  PageRun run("session-move", session.args());
  run.wait_for_frame(5);
  // Refusals are answered as such and change nothing: the window still moves once.
  EXPECT_EQ(run.post("window?action=move&id=9&x=600&y=420&w=200&h=150", 404),
            nlohmann::json({{"error", "window not changed: window 9 is not in the session"}}));
  EXPECT_EQ(run.post("window?action=move&id=1&x=600&y=420&w=0&h=150", 400),
            nlohmann::json({{"error",
                             "window not changed: command 'move 1 600 420 0 150': W must be an "
                             "integer 1..16384, got '0'"}}));
  EXPECT_EQ(run.post("window?action=move&id=1&x=600&y=420&w=200&h=150"),
            nlohmann::json({{"done", "window: move 1 600 420 200 150 from the next frame"}}));
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  session.expect_moved_once(run);
  expect_clean(run);
}

// The same command as a line on l2wall's stdin (--window-stdin), here a pipe the test writes
// once frame 5 is on the displays; a command that cannot be taken is said on stderr.
TEST(SessionOnTheWall, AWindowMovedFromStdinMovesOnEveryDisplayInOneFrame) {
  const MovingSession session("session-stdin");
  const fs::path fifo = session.dir / "commands";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::vector<std::string> args = session.args();
  args.push_back("--window-stdin");
  WallRun run("session-stdin", args, {}, false, "", false, fifo.string());
  std::ofstream commands(fifo);  // opens once the shell opened its end for l2wall
  wait_for_file(run.out() / "frame-5", 60s);
  commands << "move 1 600 420 200 150\nraise 7\n" << std::flush;
  commands.close();
  const ExitStatus status = run.wait(120s);
  ASSERT_TRUE(status.ok()) << status.describe() << "\n" << run.output();
  session.expect_moved_once(run);
  EXPECT_NE(run.output().find("l2wall: window: move 1 600 420 200 150 from the next frame\n"),
            std::string::npos);
  EXPECT_NE(run.output().find("l2wall: window not changed: window 7 is not in the session\n"),
            std::string::npos);
  expect_clean(run);
}

// A malformed session is refused before any pipeserver starts, in one line naming file, line
// and field.
TEST(SessionOnTheWall, AMalformedSessionIsOneLine) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("l2wall-session-bad-{}", getpid());
  fs::create_directories(dir);
  std::ofstream(dir / "session.toml") << "[[window]]\nsource = \"swap\"\nx = 0\ny = 0\n"
                                         "width = 10\nheight = 10\nz = \"top\"\n";
  WallRun run("session-bad", {"--scene", "session", "--session", (dir / "session.toml").string()});
  const ExitStatus status = run.wait(60s);
  EXPECT_EQ(status.code, 1) << status.describe();
  EXPECT_EQ(run.output(), fmt::format("l2wall: {}:7: window[0].z: must be an integer, got a "
                                      "string\n",
                                      (dir / "session.toml").string()));
  expect_clean(run);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace l2
