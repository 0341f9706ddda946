// `l2wall golden` on a rendered entry, with real pipeserver processes: update makes a new
// entry's images and records this Mesa; images recorded as made by another Mesa are compared
// within the tolerance, and the output says so; with this Mesa the same pixel fails. A small
// wall of its own (two pipeservers, one 320x240 display, DVI path only) keeps the three live
// runs short; the repository's rendered entries, on both paths, run in the CTest
// l2wall_golden_check.
#include <fstream>

#include "golden/golden_manifest.hpp"
#include "golden_cli.hpp"
#include "image/png_io.hpp"
#include "pipeserver/gl_context.hpp"

namespace l2 {
namespace {

using namespace l2::test;

const char* kSmallWall = R"toml(name = "one small display, two pipeservers"
[[display]]
id = 0
width = 320
height = 240
x = 0
y = 0
[tiling]
kind = "grid"
tile_width = 160
tile_height = 120
[pipeservers]
count = 2
framebuffer_width = 324
framebuffer_height = 240
)toml";

const char* kSmallEntry = R"toml([[entry]]
name = "small-bunny"
kind = "rendered"
wall = "walls/small.toml"
scene = "mesh"
frame = 1
paths = ["dvi"]
tolerance = { differing_percent = 0.01, beyond_one_percent = 0.003 }
)toml";

// The small wall under `root` and a manifest of its one rendered entry, no images yet; returns
// the options that point `l2wall golden` at them.
std::string small_entry(const fs::path& root, const fs::path& goldens, const fs::path& out) {
  fs::create_directories(root / "walls");
  std::ofstream(root / "walls/small.toml") << kSmallWall;
  fs::remove_all(goldens);
  fs::create_directories(goldens);
  std::ofstream(goldens / "manifest.toml") << kSmallEntry;
  return "--goldens " + quote(goldens) + " --root " + quote(root) + " --out " + quote(out) + " ";
}

TEST_F(GoldenCli, UpdateRecordsThisMesaAndAnotherMesaIsComparedWithinTheTolerance) {
  const fs::path root = dir_ / "root";
  const std::string where = small_entry(root, goldens(), out());

  // A new entry: update makes its image and records the GL that made it.
  const Result made = l2wall("update " + where);
  ASSERT_EQ(made.code, 0) << made.output;
  EXPECT_NE(made.output.find("1 image written, manifest rewritten"), std::string::npos)
      << made.output;
  const GlInfo gl = gl_info();
  GoldenManifest manifest = load_manifest(goldens() / "manifest.toml");
  ASSERT_EQ(manifest.entries.size(), 1u);
  EXPECT_EQ(manifest.entries[0].gl_version, gl.version);
  EXPECT_EQ(manifest.entries[0].gl_renderer, gl.renderer);
  EXPECT_EQ(manifest.entries[0].mesa, gl.mesa_version());
  const RgbImage made_image = read_png(golden("small-bunny", 0));
  EXPECT_EQ(made_image.width(), 320);

  // One golden pixel changed, and the images said to come from another Mesa: within tolerance.
  RgbImage changed = made_image;
  changed.set(20, 10, Rgb{255, 255, 254});
  write_png(golden("small-bunny", 0), changed);
  manifest.entries[0].mesa = "0.1.0";
  manifest.entries[0].gl_version = "4.5 (Compatibility Profile) Mesa 0.1.0";
  std::ofstream(goldens() / "manifest.toml") << format_manifest(manifest);
  const Result other = l2wall("check " + where);
  EXPECT_EQ(other.code, 0) << other.output;
  EXPECT_NE(other.output.find("small-bunny: golden images made with Mesa 0.1.0 (" + gl.renderer +
                              "), this is Mesa " + gl.mesa_version() + " (" + gl.renderer +
                              "): compared within the tolerance"),
            std::string::npos)
      << other.output;
  EXPECT_NE(other.output.find("small-bunny: emulator vs golden image: 1 of 76800 pixels differ"),
            std::string::npos)
      << other.output;

  // The same pixel with the images recorded as this Mesa's: exact, so it fails.
  manifest.entries[0].mesa = gl.mesa_version();
  manifest.entries[0].gl_version = gl.version;
  std::ofstream(goldens() / "manifest.toml") << format_manifest(manifest);
  const Result same = l2wall("check " + where);
  EXPECT_EQ(same.code, 1) << same.output;
  EXPECT_NE(same.output.find("small-bunny display 0: emulator vs golden image: 1 pixel differs "
                             "(1 by more than one level)"),
            std::string::npos)
      << same.output;
  EXPECT_EQ(same.output.find("compared within the tolerance"), std::string::npos);
  EXPECT_TRUE(read_png(out() / "small-bunny/display-0-actual.png") == made_image);
}

// The same wall re-tiled (80-pixel-wide tiles): the picture is the same, but pipeserver 1's
// frame stamp moved from (160,0) to (80,0). Those two pixels are said to be stamps and left
// out; any other pixel still fails.
TEST_F(GoldenCli, StampsMovedByAReTilingAreLeftOutAndSaidSo) {
  const fs::path root = dir_ / "root";
  const std::string where = small_entry(root, goldens(), out());
  const Result made = l2wall("update " + where);
  ASSERT_EQ(made.code, 0) << made.output;

  std::string retiled = kSmallWall;
  retiled.replace(retiled.find("tile_width = 160"), 16, "tile_width = 80");
  std::ofstream(root / "walls/small.toml") << retiled;
  const Result check = l2wall("check " + where);
  EXPECT_EQ(check.code, 0) << check.output;
  EXPECT_NE(check.output.find("small-bunny: 2 pixels differ from the golden images only by frame "
                              "1's stamp (the first pixel of each pipeserver's first tile, moved "
                              "by another tiling): left out of the comparison"),
            std::string::npos)
      << check.output;

  // A real difference besides: still a failure.
  RgbImage changed = read_png(golden("small-bunny", 0));
  changed.set(20, 10, Rgb{255, 255, 254});
  write_png(golden("small-bunny", 0), changed);
  const Result failed = l2wall("check " + where);
  EXPECT_EQ(failed.code, 1) << failed.output;
  EXPECT_NE(failed.output.find("small-bunny display 0: emulator vs golden image: 1 pixel differs"),
            std::string::npos)
      << failed.output;
}

}  // namespace
}  // namespace l2
