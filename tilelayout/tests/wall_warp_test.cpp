// Geometry warps in the wall file (`warp = "file.pfm"` of a [[display]]): the map a display
// gets from a PFM written here byte by byte, and every refusal's exact line, naming the wall
// file's line and field or the PFM file and its header field.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall_file.hpp"
#include "tilelayout/warp_file.hpp"
#include "wall_folder.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

// A PFM of `header` then the floats, rows as given (the file's order: bottom row first),
// little-endian.
std::string pfm_bytes(const std::string& header, const std::vector<float>& values) {
  std::string bytes = header;
  for (const float v : values) {
    const auto bits = std::bit_cast<std::uint32_t>(v);
    for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<char>(bits >> (8 * b) & 0xff));
  }
  return bytes;
}

// Pixel i's centre on a side of `size` pixels, normalised.
float centre(int i, int size) {
  return (static_cast<float>(i) + 0.5f) / static_cast<float>(size);
}

// The 4x2 display's positions, bottom row first, each pixel (x, y, 0): the top row mirrored,
// the bottom row as it is.
std::vector<float> mirrored_top() {
  std::vector<float> v;
  for (const int row : {1, 0}) {
    for (int x = 0; x < 4; ++x) {
      const int sx = row == 0 ? 3 - x : x;
      v.insert(v.end(), {centre(sx, 4), centre(row, 2), 0.0f});
    }
  }
  return v;
}

class WallWarp : public WallFolder {
 protected:
  WallWarp() : WallFolder("warp") {}
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
};

TEST_F(WallWarp, APfmBecomesTheDisplaysMapWithRowsBottomToTop) {
  write("calibration/w.pfm", pfm_bytes("PF\n4 2\n-1.0\n", mirrored_top()));
  const Wall wall = parse(one_display_wall("warp = \"calibration/w.pfm\""));
  const Display& d = wall.displays[0];
  EXPECT_EQ(d.warp, "calibration/w.pfm");
  ASSERT_TRUE(d.warp_map);
  // Map row 0 is the display's top row: mirrored, source x 3, 2, 1, 0 (in 1/256 pixel).
  const std::vector<std::int32_t> expected{3 * 256, 0,   2 * 256, 0,   256,     0,   0,       0,
                                           0,       256, 256,     256, 2 * 256, 256, 3 * 256, 256};
  EXPECT_EQ(d.warp_map->source, expected);
}

// A 2x2 mesh over the 4x2 display: its points on the corner pixels, the columns between
// interpolated. Mirrored: the left points name the right edge pixel's centre and the right
// points the left one's, so every pixel shows its mirror image.
TEST_F(WallWarp, ACoarseMeshIsInterpolatedOverTheDisplay) {
  std::vector<float> v;
  for (const int row : {1, 0})
    for (const int x : {3, 0}) v.insert(v.end(), {centre(x, 4), centre(row, 2), 0.0f});
  write("mesh.pfm", pfm_bytes("PF\n2 2\n-1\n", v));
  const Wall wall = parse(one_display_wall("warp = \"mesh.pfm\""));
  ASSERT_TRUE(wall.displays[0].warp_map);
  const std::vector<std::int32_t> expected{3 * 256, 0,   2 * 256, 0,   256, 0,   0, 0,
                                           3 * 256, 256, 2 * 256, 256, 256, 256, 0, 256};
  EXPECT_EQ(wall.displays[0].warp_map->source, expected);
}

TEST_F(WallWarp, BigEndianFloatsToo) {
  // A positive scale: the same positions with every float's bytes reversed.
  std::string bytes = pfm_bytes("PF\n4 2\n1\n", mirrored_top());
  for (std::size_t at = 9; at < bytes.size(); at += 4) {
    std::swap(bytes[at], bytes[at + 3]);
    std::swap(bytes[at + 1], bytes[at + 2]);
  }
  write("w.pfm", bytes);
  const Wall wall = parse(one_display_wall("warp = \"w.pfm\""));
  ASSERT_TRUE(wall.displays[0].warp_map);
  EXPECT_EQ(wall.displays[0].warp_map->source[0], 3 * 256);
}

TEST_F(WallWarp, AnIdentityWarpCostsNothing) {
  std::vector<float> v;
  for (const int row : {1, 0})
    for (int x = 0; x < 4; ++x) v.insert(v.end(), {centre(x, 4), centre(row, 2), 0.0f});
  write("id.pfm", pfm_bytes("PF\n4 2\n-1\n", v));
  const Wall wall = parse(one_display_wall("warp = \"id.pfm\""));
  EXPECT_EQ(wall.displays[0].warp, "id.pfm");
  EXPECT_FALSE(wall.displays[0].warp_map);
}

TEST_F(WallWarp, WallFileErrorsNameTheLineAndField) {
  const std::string f = wall_file();
  EXPECT_EQ(error_of(one_display_wall("warp = \"\"")),
            f + ":6: display[0].warp: must name a PFM warp file, got \"\"");
  EXPECT_EQ(error_of(one_display_wall("warp = 1")),
            f + ":6: display[0].warp: must be a string, got an integer");
  EXPECT_EQ(
      error_of(one_display_wall("warp = \"none.pfm\"")),
      f + ":6: display[0].warp: " + file("none.pfm") + ": cannot read: No such file or directory");
  EXPECT_EQ(error_of(one_display_wall("warp = \"/dev/zero\"")),
            f + ":6: display[0].warp: /dev/zero: not a regular file: a warp is a PFM file");
  // Larger than any 4x2 warp can be: refused before it is read to the end.
  write("big.pfm", std::string(max_warp_pfm_bytes(4, 2) + 1, ' '));
  EXPECT_EQ(error_of(one_display_wall("warp = \"big.pfm\"")),
            f + ":6: display[0].warp: " + file("big.pfm") + ": more than " +
                std::to_string(max_warp_pfm_bytes(4, 2)) +
                " bytes: not a PFM warp for this display");
}

TEST_F(WallWarp, PfmErrorsNameTheFileAndHeaderField) {
  const auto refused = [&](const std::string& bytes) {
    write("bad.pfm", bytes);
    return error_of(one_display_wall("warp = \"bad.pfm\""));
  };
  const std::string p = file("bad.pfm");
  const std::vector<float> v = mirrored_top();
  EXPECT_EQ(refused(pfm_bytes("P6\n4 2\n-1\n", v)),
            p + ": magic: must be \"PF\" (a 3-channel float PFM), got \"P6\"");
  EXPECT_EQ(refused(pfm_bytes("Pf\n4 2\n-1\n", v)),
            p + ": magic: must be \"PF\" (a 3-channel float PFM), got \"Pf\" (a 1-channel PFM)");
  EXPECT_EQ(refused(pfm_bytes("PF\n5 2\n-1\n", v)),
            p + ": width: must be 2..4 points (the display is 4 wide), got 5");
  EXPECT_EQ(refused(pfm_bytes("PF\n1 2\n-1\n", v)),
            p + ": width: must be 2..4 points (the display is 4 wide), got 1");
  EXPECT_EQ(refused(pfm_bytes("PF\n4 3\n-1\n", v)),
            p + ": height: must be 2..2 points (the display is 2 high), got 3");
  EXPECT_EQ(refused(pfm_bytes("PF\nx 2\n-1\n", v)),
            p + ": width: must be a positive integer, got \"x\"");
  EXPECT_EQ(refused(pfm_bytes("PF\n4 2\n0\n", v)),
            p + ": scale: must be a non-zero number, got \"0\"");
  EXPECT_EQ(refused(pfm_bytes("PF\n4 2\n-1\n", std::vector<float>(v.begin(), v.end() - 1))),
            p + ": data: 4x2 points of 3 floats are 96 bytes after the header, the file has 92");
  EXPECT_EQ(refused(pfm_bytes("PF\n2 2\n-1\n", v)),
            p + ": data: 2x2 points of 3 floats are 48 bytes after the header, the file has 96");
  EXPECT_EQ(refused("PF\n4 2"),
            p + ": height: the header ends before it (a PFM header is \"PF\", width, height and "
                "scale within 128 bytes)");
}

}  // namespace
}  // namespace l2
