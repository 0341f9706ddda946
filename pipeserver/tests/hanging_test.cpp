// Displays as they hang (rotation and flip per display): a position picture at 1:1 on walls of
// turned and mirrored panels, rendered by the pipeservers and routed by their strip headers.
// Every display pixel must equal the canvas pixel the wall file's mapping names
// (docs/wall-file.md), computed here from each display's numbers as the wall file gives them,
// not by the code under test. (Both paths of a live run on these walls, byte for byte:
// l2wall/tests/hanging_run_test.cpp.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "image/png_io.hpp"
#include "pipeserver/pipeserver.hpp"
#include "pipeserver/scene.hpp"
#include "test_support.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

// What the wall file says of one display: native size, canvas corner, rotation, flip.
struct Hung {
  int x0, y0, w, h, rotation;
  char flip;  // 'n', 'h' or 'v'
};

// Canvas pixel (x, y) as a colour that names it: x and y low bytes, their high nibbles in blue.
Rgb position(int x, int y) {
  return {static_cast<std::uint8_t>(x & 255), static_cast<std::uint8_t>(y & 255),
          static_cast<std::uint8_t>((x >> 8 & 15) | (y >> 8 & 15) << 4)};
}

// The documented mapping, written out: flip in panel coordinates first, then the turn, clockwise
// seen from the front; at 90, pixel (x, y) shows (x0 + cw - 1 - y, y0 + x), cw the canvas width.
std::pair<int, int> canvas_of(const Hung& d, int x, int y) {
  if (d.flip == 'h') x = d.w - 1 - x;
  if (d.flip == 'v') y = d.h - 1 - y;
  const int cw = d.rotation % 180 ? d.h : d.w, ch = d.rotation % 180 ? d.w : d.h;
  switch (d.rotation) {
    case 90:
      return {d.x0 + cw - 1 - y, d.y0 + x};
    case 180:
      return {d.x0 + cw - 1 - x, d.y0 + ch - 1 - y};
    case 270:
      return {d.x0 + y, d.y0 + ch - 1 - x};
    default:
      return {d.x0 + x, d.y0 + y};
  }
}

class Hanging : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("l2-hanging-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The wall's displays with the position picture stretched over its canvas (1:1: the picture
  // is the canvas's size), on the DVI path and the vizserver path.
  void check(const Wall& wall, const std::vector<Hung>& expected) {
    ASSERT_EQ(wall.displays.size(), expected.size());
    RgbImage picture(wall.canvas_width, wall.canvas_height);
    for (int y = 0; y < picture.height(); ++y)
      for (int x = 0; x < picture.width(); ++x) picture.set(x, y, position(x, y));
    const fs::path file = dir_ / "positions.png";
    write_png(file, picture);
    const TileLayout layout = plan_layout(wall);
    std::vector<RgbImage> frames;
    for (const PipeserverPlan& plan : layout.pipeservers) {
      SceneOptions options;
      options.content = file;
      options.fit = "stretch";
      const auto scene = make_scene("picture", options);
      Pipeserver p(layout, plan.pipeserver);
      frames.push_back(p.render_frame(1, *scene));
    }
    const test::Reassembly routed = test::reassemble(wall, frames);
    EXPECT_EQ(routed.errors.total(), 0u);
    const std::vector<RgbImage>& dvi = routed.displays;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const Hung& d = expected[i];
      ASSERT_EQ(dvi[i].width(), d.w) << "display " << i;
      ASSERT_EQ(dvi[i].height(), d.h) << "display " << i;
      int wrong = 0;
      for (int y = 0; y < d.h; ++y) {
        for (int x = 0; x < d.w; ++x) {
          const auto [cx, cy] = canvas_of(d, x, y);
          if (dvi[i].at(x, y) != position(cx, cy) && wrong++ < 3) {
            const Rgb got = dvi[i].at(x, y);
            ADD_FAILURE() << "display " << i << " pixel " << x << "," << y << " should show canvas "
                          << cx << "," << cy << ", shows " << int(got.r) << "," << int(got.g) << ","
                          << int(got.b);
          }
        }
      }
      EXPECT_EQ(wrong, 0) << "display " << i << " (rotation " << d.rotation << ", flip " << d.flip
                          << ")";
    }
  }

  fs::path dir_;
};

Wall wall_file(const char* name) {
  return load_wall(fs::path(L2_SOURCE_DIR) / "walls" / name);
}

// Whole under ASan too, though it takes some 8 s there: most of it is the six pipeservers
// rendering at the panels' native size (about 1.2 s each), the code under test, and a smaller
// wall would no longer be this file's, whose 980x560 tiles turned into 1968-wide framebuffers
// are the point (EveryRotationAndFlip checks the mapping itself on small panels).
TEST_F(Hanging, PortraitWall) {
  // walls/portrait-3x2.toml: 1920x1080 panels at 90, 40-pixel bezels, so a pitch of 1120 across
  // and 1960 down.
  std::vector<Hung> expected;
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c) expected.push_back({c * 1120, r * 1960, 1920, 1080, 90, 'n'});
  check(wall_file("portrait-3x2.toml"), expected);
}

TEST_F(Hanging, MixedWall) {
  check(wall_file("mixed-hang.toml"),
        {{0, 0, 1280, 720, 0, 'n'}, {1320, 0, 1280, 720, 270, 'n'}, {0, 760, 1280, 720, 180, 'h'}});
}

TEST_F(Hanging, EveryRotationAndFlip) {
  // Twelve panels of 48x30 (odd and even, neither square), one for each rotation and flip, in
  // cells of 56x56; tiles of 20x20 cut every panel into pieces that start mid-panel.
  std::string toml = "name = \"every hang\"\n";
  std::vector<Hung> expected;
  const char* flips[] = {"none", "horizontal", "vertical"};
  for (int i = 0; i < 12; ++i) {
    const int rotation = 90 * (i % 4), f = i / 4;
    const int x0 = 56 * (i % 4) + 3, y0 = 56 * (i / 4) + 5;
    toml += fmt::format(
        "[[display]]\nwidth = 48\nheight = 30\nx = {}\ny = {}\nrotation = {}\nflip = \"{}\"\n", x0,
        y0, rotation, flips[f]);
    expected.push_back({x0, y0, 48, 30, rotation, "nhv"[f]});
  }
  toml +=
      "[tiling]\nkind = \"grid\"\ntile_width = 20\ntile_height = 20\n"
      "[pipeservers]\ncount = 3\nframebuffer_width = 256\nframebuffer_height = 256\n";
  check(parse_wall(toml, "every-hang.toml"), expected);
}

}  // namespace
}  // namespace l2
