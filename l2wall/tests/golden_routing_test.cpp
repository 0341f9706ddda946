// The displays a routing-only golden entry is produced from, in this process: the test pattern
// through the emulator and through the compositing server, and the GL version of rendered ones.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "golden/golden_routing.hpp"
#include "pipeserver/gl_context.hpp"
#include "strip_headers/strip_header.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/test_frame.hpp"
#include "tilelayout/test_pattern.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

TileLayout example(const char* wall) {
  return plan_layout(load_wall(std::filesystem::path(L2_SOURCE_DIR) / "walls" / wall));
}

// Every pixel decodes (test_pattern_position) to where it is on the canvas: routed to the right
// place, and the display where the wall file puts it.
void expect_every_pixel_in_place(const RgbImage& display, const Display& d) {
  int misplaced = 0;
  for (int y = 0; y < display.height(); ++y) {
    for (int x = 0; x < display.width(); ++x) {
      const auto at = test_pattern_position(d.id, display.at(x, y));
      if (!at || at->first != (d.canvas_x + x) % 4096 || at->second != (d.canvas_y + y) % 4096)
        ++misplaced;
    }
  }
  EXPECT_EQ(misplaced, 0) << "display " << d.id;
}

TEST(GoldenRouting, TestPatternArrivesInPlaceOnBothPaths) {
  const TileLayout layout = example("projectors-2x1.toml");  // overlapping displays
  const EntryDisplays shown = produce_test_pattern(layout, 1, true);
  ASSERT_EQ(shown.ids, (std::vector<int>{0, 1}));
  ASSERT_EQ(shown.emulator.size(), 2u);
  ASSERT_EQ(shown.vizserver.size(), 2u);
  EXPECT_EQ(shown.input_errors.total(), 0u);
  for (std::size_t i = 0; i < shown.ids.size(); ++i) {
    EXPECT_EQ(shown.emulator[i].width(), 1024);
    expect_every_pixel_in_place(shown.emulator[i], layout.wall.displays[i]);
    EXPECT_TRUE(shown.vizserver[i] == shown.emulator[i]) << "display " << i;
    EXPECT_TRUE(shown.reference[i] == shown.emulator[i]) << "display " << i;
  }
}

// A COPY header that says row y-1 instead of y: that row is overwritten with the wrong pixels
// and row y stays black, exactly the strip's width on each.
TEST(GoldenRouting, AWrongHeaderFieldMovesItsStrip) {
  const TileLayout layout = example("kd-2x2.toml");
  std::vector<RgbImage> frames;
  for (const PipeserverPlan& p : layout.pipeservers) frames.push_back(test_frame(p, true));
  const PackedTile& t = layout.pipeservers[1].tiles[0];
  const int r = 10;
  std::uint8_t* h = frames[1].row(t.fb_y + r).data() + (t.fb_x - 2) * 3;
  const Rect& d = t.tile.on_display;
  const std::uint64_t wrong =
      encode(StripHeader::copy(true, t.tile.display, d.x, d.y + r - 1, d.w));
  for (int i = 0; i < 6; ++i) h[i] = static_cast<std::uint8_t>(wrong >> (40 - 8 * i));
  StripErrorCounts errors;
  const std::vector<RgbImage> shown = emulate_displays(layout, frames, errors);
  EXPECT_EQ(errors.total(), 0u);
  const RgbImage& display = shown.at(t.tile.display);
  for (int x = d.x; x < d.right(); ++x) {
    EXPECT_EQ(display.at(x, d.y + r), (Rgb{0, 0, 0}));
    EXPECT_EQ(display.at(x, d.y + r - 1), test_pattern(t.tile.display, x, d.y + r));
  }
  EXPECT_EQ(display.at(d.x, d.y + r + 1), test_pattern(t.tile.display, d.x, d.y + r + 1));
}

// The pattern encodes canvas positions: wider mullions, which move displays 1 and 3 on the
// canvas but route every display pixel as before, change what those displays show.
TEST(GoldenRouting, AChangeOfGeometryChangesTheDisplays) {
  Wall wall = load_wall(std::filesystem::path(L2_SOURCE_DIR) / "walls/kd-2x2.toml");
  const EntryDisplays before = produce_test_pattern(plan_layout(wall), 1, false);
  for (Display& d : wall.displays) d.canvas_x += d.canvas_x > 0 ? 4 : 0;
  wall.canvas_width += 4;
  const EntryDisplays after = produce_test_pattern(plan_layout(wall), 1, false);
  EXPECT_TRUE(after.emulator[0] == before.emulator[0]);
  EXPECT_FALSE(after.emulator[1] == before.emulator[1]);
  EXPECT_TRUE(after.reference[1] == after.emulator[1]);
}

TEST(GoldenRouting, CapturedFramesNeedOneFilePerPipeserver) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("l2-golden-routing-empty-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  try {
    produce_from_captured(example("kd-2x2.toml"), dir);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / "scanout-0.png").string() +
                  ": missing: the wall has 4 pipeservers, give scanout-0.png .. scanout-3.png");
  }
  std::filesystem::remove_all(dir);
}

TEST(GlInfo, NamesTheMesaRelease) {
  const GlInfo gl = gl_info();
  EXPECT_NE(gl.version.find("Mesa "), std::string::npos) << gl.version;
  ASSERT_FALSE(gl.mesa_version().empty());
  EXPECT_TRUE(std::isdigit(static_cast<unsigned char>(gl.mesa_version()[0])));
  EXPECT_FALSE(gl.renderer.empty());
  EXPECT_EQ((GlInfo{"4.5 (Compatibility Profile) Mesa 22.3.6", ""}.mesa_version()), "22.3.6");
  EXPECT_EQ((GlInfo{"3.1 Mesa 23.0.0-devel (git-abc)", ""}.mesa_version()), "23.0.0-devel");
  EXPECT_EQ((GlInfo{"4.6 NVIDIA 535.1", ""}.mesa_version()), "");
}

}  // namespace
}  // namespace l2
