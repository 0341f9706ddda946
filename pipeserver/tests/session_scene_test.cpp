// A session of overlapping windows on the default wall: every display reassembled from the
// pipeservers' frames equals its reference render; a picture window at 1:1 shows its source's
// pixels at their canvas places, clipped at the wall's edge and hidden behind the mullions;
// where windows overlap the one in front shows.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "image/png_io.hpp"
#include "pipeserver/pipeserver.hpp"
#include "test_support.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

Rgb window_pattern(int x, int y) {
  return {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y),
          static_cast<std::uint8_t>(x / 7 + y / 5 + 1)};
}

constexpr int kSourceWidth = 300, kSourceHeight = 200;

class SessionWindows : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("session-scene-{}", getpid());
    fs::create_directories(dir_);
    RgbImage picture(kSourceWidth, kSourceHeight);
    for (int y = 0; y < kSourceHeight; ++y)
      for (int x = 0; x < kSourceWidth; ++x) picture.set(x, y, window_pattern(x, y));
    write_png(dir_ / "pattern.png", picture);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::unique_ptr<Scene> session(const std::string& text) {
    const fs::path file = dir_ / "session.toml";
    std::ofstream(file) << text;
    SceneOptions options;
    options.session = file;
    return make_scene("session", options);
  }

  // What display `d` shows at canvas pixel (x, y), from a reassembly.
  static Rgb shown(const test::Reassembly& r, const Display& d, int x, int y) {
    return r.displays[static_cast<std::size_t>(d.id)].at(x - d.canvas_x, y - d.canvas_y);
  }

  fs::path dir_;
  const TileLayout layout_ = plan_layout(default_wall());
};

// The default wall's canvas is 1300x980: displays of 640x480, mullions of 20 at columns
// 640..659 and rows 480..499.
const char* kOverlapping = R"(
background = 0x203040

[[window]]
source = "mesh"
x = 100
y = 60
width = 700
height = 500

[[window]]
source = "strips"
x = 700
y = 300
width = 500
height = 400
z = 1

[[window]]
source = "picture"
content = "pattern.png"
fit = "1:1"
x = 560
y = 420
width = 260
height = 180
z = 2

[[window]]
source = "picture"
content = "pattern.png"
fit = "stretch"
x = 1100
y = 850
width = 400
height = 300
z = 3

[[window]]
source = "swap"
x = -50
y = 700
width = 300
height = 200
)";

TEST_F(SessionWindows, EveryDisplayEqualsItsReference) {
  auto scene = session(kOverlapping);
  for (const int frame : {0, 7}) {
    const test::WallCheck check = test::check_wall(layout_, *scene, frame);
    EXPECT_EQ(check.reassembly.errors.total(), 0u);
    for (std::size_t d = 0; d < check.diffs.size(); ++d)
      EXPECT_EQ(check.diffs[d].pixels_differing, 0) << "frame " << frame << " display " << d;
  }
}

TEST_F(SessionWindows, APictureAtOneToOneShowsItsPixelsInPlace) {
  auto scene = session(kOverlapping);
  const test::WallCheck check = test::check_wall(layout_, *scene, 0);
  // The 1:1 window (560, 420) is in front of the mesh and the strips; its picture is larger
  // than it, cut at the window's right and bottom. Every canvas pixel of it a display shows is
  // the picture's pixel at the same offset; those behind the mullions are on no display.
  long checked = 0, wrong = 0;
  for (const Display& d : layout_.wall.displays) {
    const Rect part = intersect(d.on_canvas(), Rect{560, 420, 260, 180});
    for (int y = part.y; y < part.bottom(); ++y)
      for (int x = part.x; x < part.right(); ++x) {
        ++checked;
        wrong += !(shown(check.reassembly, d, x, y) == window_pattern(x - 560, y - 420));
      }
  }
  EXPECT_EQ(wrong, 0);
  // 260x180 less the mullions' 20 columns and 20 rows that cross it.
  EXPECT_EQ(checked, 240L * 160);
  // Across the mullion: display 1's first column shows picture column 660 - 560, the 20
  // columns before it are hidden.
  const Display& right = layout_.wall.displays[1];
  EXPECT_EQ(shown(check.reassembly, right, 660, 430), window_pattern(100, 10));
  // The background shows where no window is; the wall's edge clips the stretched window.
  const Display& last = layout_.wall.displays[3];
  EXPECT_EQ(shown(check.reassembly, last, 1299, 520), (Rgb{0x20, 0x30, 0x40}));
  EXPECT_EQ(shown(check.reassembly, last, 1050, 979), (Rgb{0x20, 0x30, 0x40}));
  EXPECT_NE(shown(check.reassembly, last, 1299, 979), (Rgb{0x20, 0x30, 0x40}));
}

// Two windows over each other: the higher z shows where they overlap, whatever their order in
// the file; the lower one shows elsewhere.
TEST_F(SessionWindows, TheWindowInFrontShowsWhereTheyOverlap) {
  const std::string swap =
      "[[window]]\nsource = \"swap\"\nx = 100\ny = 100\nwidth = 200\n"
      "height = 200\nz = {}\n";
  const std::string picture =
      "[[window]]\nsource = \"picture\"\ncontent = \"pattern.png\"\n"
      "fit = \"1:1\"\nx = 200\ny = 150\nwidth = 200\nheight = 100\n";
  const Display& d0 = layout_.wall.displays[0];
  // The swap scene's colour of frame 0.
  const Rgb swap_colour{64, 128, 192};
  {
    auto scene = session(fmt::format(fmt::runtime(swap), 1) + picture);
    const test::WallCheck check = test::check_wall(layout_, *scene, 0);
    EXPECT_EQ(shown(check.reassembly, d0, 250, 200), swap_colour);  // both: swap in front
    EXPECT_EQ(shown(check.reassembly, d0, 350, 200), window_pattern(150, 50));  // the picture alone
  }
  {
    auto scene = session(fmt::format(fmt::runtime(swap), -1) + picture);
    const test::WallCheck check = test::check_wall(layout_, *scene, 0);
    EXPECT_EQ(shown(check.reassembly, d0, 250, 200),
              window_pattern(50, 50));                              // the picture in front
    EXPECT_EQ(shown(check.reassembly, d0, 150, 200), swap_colour);  // the swap alone
  }
}

TEST_F(SessionWindows, AMalformedSessionIsOneLineNamingFileAndLine) {
  try {
    session(
        "[[window]]\nsource = \"picture\"\ncontent = \"pattern.png\"\nx = 0\ny = 0\n"
        "width = 0\nheight = 10\n");
    FAIL();
  } catch (const std::exception& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir_ / "session.toml").string() + ":6: window[0].width: must be 1..16384, got 0");
  }
}

}  // namespace
}  // namespace l2
