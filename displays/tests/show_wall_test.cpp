// show_wall as a user runs it: a child process on a private Xvfb, its exit code, its error text
// and the screenshots it writes of what the screen showed.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "displays/wall_view.hpp"
#include "displays/wall_window.hpp"
#include "image/png_io.hpp"
#include "screen_fixture.hpp"
#ifdef L2_HAVE_WALL_FILE
#include "tilelayout/test_pattern.hpp"
#include "tilelayout/wall_file.hpp"
#endif

extern char** environ;

namespace l2 {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

struct ChildRun {
  int exit_code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

ChildRun run_show_wall(std::vector<std::string> args, const fs::path& work) {
  args.insert(args.begin(), SHOW_WALL_EXE);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const fs::path out = work / "stdout.txt", err = work / "stderr.txt";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  ChildRun run;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0) {
    int status = 0;
    waitpid(pid, &status, 0);
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  posix_spawn_file_actions_destroy(&actions);
  run.out = slurp(out);
  run.err = slurp(err);
  return run;
}

class ShowWall : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    work_ = fs::temp_directory_path() / fmt::format("l2-show-wall-{}-{}", getpid(), info->name());
    fs::remove_all(work_);
    fs::create_directories(work_ / "displays");
  }
  void TearDown() override { fs::remove_all(work_); }
  fs::path work_;
};

TEST_F(ShowWall, HelpNamesEveryOption) {
  const ChildRun run = run_show_wall({"--help"}, work_);
  EXPECT_EQ(run.exit_code, 0);
  for (const char* option : {"--displays-from", "--wall", "--show", "--frames", "--screenshot",
                             "--refresh", "--no-vsync", "monitors"}) {
    EXPECT_THAT(run.out, HasSubstr(option));
  }
}

TEST_F(ShowWall, EmptyFolderIsAClearError) {
  const ChildRun run = run_show_wall({"--displays-from", (work_ / "displays").string()}, work_);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("displays: no display-0.png to show"));
}

#ifdef L2_HAVE_WALL_FILE
// The acceptance test: the default wall in the wall window for 5 frames; what the
// window shows, read back, equals the display images written for it, pixel for pixel.
TEST_F(ShowWall, DefaultWallWindowShowsTheWrittenDisplayImagesExactly) {
  const Wall wall = default_wall();
  std::vector<RgbImage> written;
  for (const Display& d : wall.displays) {
    RgbImage image(d.width, d.height);
    for (int y = 0; y < d.height; ++y) {
      for (int x = 0; x < d.width; ++x) image.set(x, y, test_pattern(d.id, x, y));
    }
    write_png(work_ / "displays" / fmt::format("display-{}.png", d.id), image);
    written.push_back(std::move(image));
  }
  std::ofstream(work_ / "default.toml") << default_wall_toml();
  const Rect extent = wall_extent(wall);
  L2_START_XVFB(xvfb, extent.w + 16,
                extent.h + WallWindow::kOverlayHeight + WallWindow::kDecorationAllowance + 16);
  const ChildRun run =
      run_show_wall({"--displays-from", (work_ / "displays").string(), "--wall",
                     (work_ / "default.toml").string(), "--frames", "5", "--screenshot",
                     (work_ / "shots").string(), "--no-vsync", "--refresh", "200"},
                    work_);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const Display& d : wall.displays) {
    const RgbImage shown = read_png(work_ / "shots" / fmt::format("display-{}.png", d.id));
    EXPECT_TRUE(shown == written[d.id]) << "display " << d.id;
  }
}
#endif

TEST_F(ShowWall, DisplaysInARowAreShownExactly) {
  std::vector<RgbImage> written;
  for (int d = 0; d < 3; ++d) {
    written.push_back(testing::distinct_picture(d, 160 + 8 * d, 120));
    write_png(work_ / "displays" / fmt::format("display-{}.png", d), written.back());
  }
  L2_START_XVFB(xvfb, 1024, 768);
  const ChildRun run =
      run_show_wall({"--displays-from", (work_ / "displays").string(), "--frames", "5",
                     "--screenshot", (work_ / "shots").string(), "--no-vsync"},
                    work_);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (int d = 0; d < 3; ++d) {
    EXPECT_TRUE(read_png(work_ / "shots" / fmt::format("display-{}.png", d)) == written[d]);
  }
  const RgbImage window = read_png(work_ / "shots" / "window-0.png");
  EXPECT_EQ(window.width(), 160 + 168 + 176 + 2 * 16);  // mullions of 16 between the three
}

TEST_F(ShowWall, MonitorsModeWithFewerMonitorsThanDisplaysFailsListingThem) {
  for (int d = 0; d < 2; ++d) {
    write_png(work_ / "displays" / fmt::format("display-{}.png", d), RgbImage(64, 48));
  }
  L2_START_XVFB(xvfb, 800, 600);
  const ChildRun run = run_show_wall(
      {"--displays-from", (work_ / "displays").string(), "--show", "monitors", "--frames", "1"},
      work_);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("--show monitors needs one monitor per display: 2 displays, "
                                 "but GLFW sees 1 monitor: [0] \""));
  EXPECT_THAT(run.err, HasSubstr("800x600 at (0,0)"));
}

}  // namespace
}  // namespace l2
