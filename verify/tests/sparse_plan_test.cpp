// Sparse DEPTH rows (tilelayout/sparse_depth.hpp) against the plan: the test-pattern frames of
// the compositing walls, their DEPTH rows made sparse as a pipeserver makes them, still verify
// clean, pixels and plan; a sparse row whose strips leave their tile's row is not as planned.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "strip_headers/strip_header.hpp"
#include "tilelayout/sparse_depth.hpp"
#include "verify/check_report.hpp"
#include "verify/routing_check.hpp"
#include "verify/verify_run.hpp"
#include "verify_test_wall.hpp"

namespace l2 {
namespace {

// Every DEPTH row of `frames` sent sparse, leaving out the far plane; returns the rows made
// sparser than dense.
int make_sparse(const TileLayout& layout, std::vector<RgbImage>& frames) {
  int sparser = 0;
  SparseScratch scratch;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    for (const PackedTile& p : layout.pipeservers[i].tiles) {
      if (p.tile.compositing != Compositing::Depth) continue;
      const int w = p.tile.on_display.w;
      for (int r = 0; r < p.tile.on_display.h; ++r) {
        std::uint8_t* gap = frames[i].row(p.fb_y + r).data() + (p.fb_x - 4) * 3;
        const std::optional<StripHeader> dense = decode(header_value(gap, gap + 3));
        if (!dense) return -1;  // not the EXT header the plan puts there
        find_depth_spans(gap + 12, gap + 12 + 3 * w, w, {}, scratch.spans);
        if (!(scratch.spans.size() == 1 && scratch.spans[0] == DepthSpan{0, w})) ++sparser;
        pack_sparse_row(gap, *dense, scratch.spans, scratch.row);
      }
    }
  }
  return sparser;
}

TEST(SparsePlan, SparseTestPatternFramesOfTheCompositingWallsVerifyClean) {
  for (const char* name : {"sort-last-512x384.toml", "hybrid-2x1.toml"}) {
    const TileLayout layout = plan_layout(load_wall(std::filesystem::path(L2_WALLS_DIR) / name));
    std::vector<RgbImage> frames = verify_test::scanned_out(layout);
    const int sparser = make_sparse(layout, frames);
    // The pattern sends losing layers at the far plane (test_pattern.hpp): some of their rows
    // change.
    EXPECT_GT(sparser, 10) << name;
    const RoutingCheck alone = check_routing(layout, frames);
    EXPECT_TRUE(alone.clean()) << name << ": " << check_report(alone).back();
    const std::vector<RgbImage> shown = route_on_wall(layout.wall, frames, 2);
    std::vector<const RgbImage*> routed;
    for (const RgbImage& s : shown) routed.push_back(&s);
    const RoutingCheck check = check_routing(layout, frames, routed);
    EXPECT_TRUE(check.clean()) << name << ": " << check_report(check).back();
    for (const InputCheck& i : check.inputs) EXPECT_EQ(i.not_as_planned, 0) << name;
  }
}

TEST(SparsePlan, AStripOutsideItsTilesRowIsNotAsPlanned) {
  const TileLayout layout =
      plan_layout(load_wall(std::filesystem::path(L2_WALLS_DIR) / "sort-last-512x384.toml"));
  std::vector<RgbImage> frames = verify_test::scanned_out(layout);
  ASSERT_GT(make_sparse(layout, frames), 0);
  // Row 10 of pipeserver 1: its first DEPTH strip sent to display row 11 instead of 10.
  const PackedTile& p = layout.pipeservers[1].tiles[0];
  std::uint8_t* gap = frames[1].row(p.fb_y + 10).data() + (p.fb_x - 4) * 3;
  StripHeader h = *decode(header_value(gap, gap + 3));
  ASSERT_EQ(h.op, StripOp::Ext);
  h.y = static_cast<std::uint16_t>(h.y + 1);
  write_header_pixels(encode(h), gap, 3);
  const RoutingCheck check = check_routing(layout, frames);
  EXPECT_FALSE(check.clean());
  EXPECT_EQ(check.inputs[0].not_as_planned, 0);
  EXPECT_GE(check.inputs[1].not_as_planned, 1);
}

}  // namespace
}  // namespace l2
