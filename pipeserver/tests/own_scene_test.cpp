// A program's own drawing (renderer.hpp) on a small wall: every display reassembles to its
// reference render, also when the drawing leaves the matrices changed (each tile starts as the
// first did), and the drawing is given the frame and each tile's rectangle.
#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

#include "pipeserver/pipeserver.hpp"
#include "pipeserver/renderer.hpp"
#include "test_support.hpp"

namespace l2 {
namespace {

// A large orange triangle turned by the frame number, the modelview left turned on return.
void careless_triangle(const TileView& view) {
  gl().Rotatef(20.0f * static_cast<float>(view.frame) + 10.0f, 0, 0, 1);
  gl().Begin(GL_TRIANGLES);
  gl().Color3f(1.0f, 0.5f, 0.0f);
  gl().Vertex3f(-0.9f, -0.7f, 0.0f);
  gl().Vertex3f(0.9f, -0.7f, 0.0f);
  gl().Vertex3f(0.0f, 0.9f, 0.0f);
  gl().End();
}

TEST(OwnScene, ReassemblesToTheReferenceWhateverTheDrawingLeavesBehind) {
  const TileLayout layout = test::small_layout(3, 40, 20, 120, 120);
  auto scene = make_own_scene(careless_triangle);
  for (const int frame : {0, 3}) {
    const auto check = test::check_wall(layout, *scene, frame);
    EXPECT_EQ(check.reassembly.errors.total(), 0u);
    long orange = 0;
    for (std::size_t d = 0; d < check.diffs.size(); ++d) {
      // Tiles are drawn as the reference draws their display (README: Reassembly is exact).
      EXPECT_EQ(check.diffs[d].pixels_differing, 0) << "frame " << frame << " display " << d;
      EXPECT_EQ(check.diffs[d].pixels_beyond_one, 0) << "frame " << frame << " display " << d;
      const RgbImage& shown = check.reassembly.displays[d];
      for (int y = 0; y < shown.height(); ++y)
        for (int x = 0; x < shown.width(); ++x) orange += shown.at(x, y) == Rgb{255, 128, 0};
    }
    EXPECT_GT(orange, 1000) << "frame " << frame;  // of 2 x 64 x 48 display pixels
  }
}

TEST(OwnScene, TheDrawingIsGivenTheFrameAndEachTile) {
  const TileLayout layout = test::small_layout(1, 40, 20, 200, 200);
  std::vector<Rect> tiles;
  std::vector<int> frames;
  auto scene = make_own_scene([&](const TileView& view) {
    tiles.push_back(view.on_canvas);
    frames.push_back(view.frame);
    EXPECT_EQ(view.canvas.width, layout.wall.canvas_width);
  });
  Pipeserver(layout, 0).render_frame(7, *scene);
  // Every tile once, in the order of its display's window (not the plan's order).
  std::vector<Rect> planned;
  for (const auto& t : layout.pipeservers[0].tiles) planned.push_back(t.tile.on_canvas);
  const auto by_place = [](const Rect& a, const Rect& b) {
    return std::tie(a.y, a.x, a.w, a.h) < std::tie(b.y, b.x, b.w, b.h);
  };
  std::sort(tiles.begin(), tiles.end(), by_place);
  std::sort(planned.begin(), planned.end(), by_place);
  EXPECT_EQ(tiles, planned);
  EXPECT_EQ(frames, std::vector<int>(planned.size(), 7));
}

}  // namespace
}  // namespace l2
