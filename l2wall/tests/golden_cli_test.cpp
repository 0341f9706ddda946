// `l2wall golden check|update` as users run them, on temporary copies of the repository's
// golden folder: a changed golden pixel and a changed header field in a captured frame each
// fail with a summary line and a diff picture that shows them, OpenImageIO's idiff agrees with
// every verdict, and update refuses to change a routing-only golden without being told to.
#include <fstream>
#include <sstream>

#include "display_compare.hpp"
#include "golden_cli.hpp"
#include "image/png_io.hpp"
#include "strip_headers/strip_header.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/test_frame.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

using namespace l2::test;

// The pristine copy passes, and idiff agrees on the displays it wrote.
TEST_F(GoldenCli, APristineCopyPassesAndIdiffAgrees) {
  const Result r = l2wall("check " + common() + " --entry " + kPattern + " --write-actual");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("[1/1] " + kPattern), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("ok ("), std::string::npos) << r.output;
  for (const int d : {0, 3}) {
    const fs::path actual = out() / kPattern / ("display-" + std::to_string(d) + "-actual.png");
    EXPECT_EQ(idiff(golden(kPattern, d), actual), 0) << actual;
  }
}

TEST_F(GoldenCli, OnePixelChangedInAGoldenImageFailsWithADiffPicture) {
  const RgbImage original = read_png(golden(kPattern, 2));
  RgbImage changed = original;
  const Rgb was = original.at(100, 50);
  changed.set(100, 50, Rgb{static_cast<std::uint8_t>(was.r ^ 0xFF), was.g, was.b});
  write_png(golden(kPattern, 2), changed);

  const Result r = l2wall("check " + common() + " --entry " + kPattern);
  EXPECT_EQ(r.code, 1) << r.output;
  const fs::path actual = out() / kPattern / "display-2-actual.png";
  const fs::path diff = out() / kPattern / "display-2-diff.png";
  const std::string line = kPattern + " display 2: emulator vs golden image: 1 pixel differs (1 " +
                           "by more than one level), largest difference " +
                           std::to_string(std::abs(int{was.r} - (was.r ^ 0xFF))) +
                           " at (100, 50); wrote " + actual.string() + ", " + diff.string();
  EXPECT_NE(r.output.find(line), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("FAILED"), std::string::npos);
  EXPECT_NE(r.output.find("golden check: if the change is intended, make them the golden images: "
                          "`l2wall golden update --goldens " +
                          goldens().string() + " --root " + kSource.string() + " --entry " +
                          kPattern + " --allow-routing-change`\n"),
            std::string::npos)
      << r.output;
  // Only that display, only against the golden: both paths and the test pattern agree.
  EXPECT_EQ(r.output.find("display 0:"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("vizserver vs"), std::string::npos) << r.output;

  EXPECT_TRUE(read_png(actual) == original);  // what the emulator showed: the true pattern
  const RgbImage picture = read_png(diff);
  EXPECT_EQ(picture.at(100, 50), kDiffPixel);
  EXPECT_EQ(picture.at(106, 50), kDiffMarker);
  const Rgb elsewhere = original.at(300, 300);
  EXPECT_EQ(picture.at(300, 300), (Rgb{static_cast<std::uint8_t>(elsewhere.r / 4),
                                       static_cast<std::uint8_t>(elsewhere.g / 4),
                                       static_cast<std::uint8_t>(elsewhere.b / 4)}));
  EXPECT_NE(idiff(golden(kPattern, 2), actual), 0);  // idiff: different too
  EXPECT_EQ(idiff(golden(kPattern, 3), golden(kPattern, 3)), 0);
}

// A captured frame with the y field of one COPY header changed (check bits recomputed, so it
// decodes): its strip lands one row up, the row it belonged to stays black.
TEST_F(GoldenCli, OneHeaderFieldChangedInAnInputFrameFailsWithADiffPicture) {
  const fs::path inputs = dir_ / "captured";
  const Result scanout =
      run(std::string(TILELAYOUT_PATH) + " --wall " + quote(kSource / "walls/kd-2x2.toml") +
          " --parity 1 --canvas-pattern --scanout " + quote(inputs));
  ASSERT_EQ(scanout.code, 0) << scanout.output;
  const std::string check =
      "check " + common() + " --entry " + kPattern + " --inputs " + quote(inputs);
  const Result clean = l2wall(check);
  ASSERT_EQ(clean.code, 0) << clean.output;
  EXPECT_NE(clean.output.find("DVI path only"), std::string::npos) << clean.output;

  const TileLayout layout = plan_layout(load_wall(kSource / "walls/kd-2x2.toml"));
  const PackedTile& t = layout.pipeservers[1].tiles[0];
  const Rect& d = t.tile.on_display;
  const int r = 10;
  RgbImage frame = read_png(inputs / "scanout-1.png");
  std::uint8_t* h = frame.row(t.fb_y + r).data() + (t.fb_x - 2) * 3;
  const std::uint64_t wrong =
      encode(StripHeader::copy(true, t.tile.display, d.x, d.y + r - 1, d.w));
  for (int i = 0; i < 6; ++i) h[i] = static_cast<std::uint8_t>(wrong >> (40 - 8 * i));
  write_png(inputs / "scanout-1.png", frame);

  const Result broken = l2wall(check);
  EXPECT_EQ(broken.code, 1) << broken.output;
  const std::string id = std::to_string(t.tile.display);
  const std::string line = kPattern + " display " + id +
                           ": emulator vs golden image: " + std::to_string(2 * d.w) +
                           " pixels differ";
  EXPECT_NE(broken.output.find(line), std::string::npos) << broken.output;
  const fs::path actual = out() / kPattern / ("display-" + id + "-actual.png");
  const RgbImage picture = read_png(out() / kPattern / ("display-" + id + "-diff.png"));
  for (const int x : {d.x, d.x + d.w / 2, d.right() - 1}) {
    EXPECT_EQ(picture.at(x, d.y + r), kDiffPixel) << x;
    EXPECT_EQ(picture.at(x, d.y + r - 1), kDiffPixel) << x;
    EXPECT_NE(picture.at(x, d.y + r + 1), kDiffPixel) << x;
  }
  EXPECT_EQ(read_png(actual).at(d.x, d.y + r), (Rgb{0, 0, 0}));
  EXPECT_NE(idiff(golden(kPattern, t.tile.display), actual), 0);

  // A captured frame missing is a check that could not be made, exit 2: it was reported as a
  // mismatch (exit 1) "with actual images and diff pictures" that were never written.
  fs::remove(inputs / "scanout-3.png");
  const Result missing = l2wall(check);
  EXPECT_EQ(missing.code, 2) << missing.output;
  EXPECT_NE(missing.output.find(kPattern + ": could not be checked: "), std::string::npos)
      << missing.output;
  EXPECT_NE(missing.output.find("scanout-3.png"), std::string::npos) << missing.output;
  EXPECT_NE(missing.output.find("golden check: 1 of 1 entries could not be checked"),
            std::string::npos)
      << missing.output;
  EXPECT_EQ(missing.output.find("diff pictures"), std::string::npos) << missing.output;
}

TEST_F(GoldenCli, UpdateRefusesToChangeARoutingOnlyGoldenUnlessAllowed) {
  const RgbImage original = read_png(golden(kPattern, 1));
  RgbImage changed = original;
  changed.set(5, 6, Rgb{1, 2, 3});
  write_png(golden(kPattern, 1), changed);
  const std::string update =
      "update --goldens " + quote(goldens()) + " --out " + quote(out()) + " --entry " + kPattern;

  const Result refused = l2wall(update);
  EXPECT_EQ(refused.code, 1) << refused.output;
  EXPECT_NE(refused.output.find(kPattern + " display 1: routing-only golden would change: 1 pixel "
                                           "differs"),
            std::string::npos)
      << refused.output;
  // The command to run, with the folders and options of this one.
  EXPECT_NE(refused.output.find("run `l2wall golden update --goldens " + goldens().string() +
                                " --root " + kSource.string() + " --entry " + kPattern + " --out " +
                                out().string() + " --allow-routing-change`\n"),
            std::string::npos)
      << refused.output;
  EXPECT_TRUE(read_png(golden(kPattern, 1)) == changed);  // nothing written
  EXPECT_EQ(read_png(out() / kPattern / "display-1-diff.png").at(5, 6), kDiffPixel);

  const Result allowed = l2wall(update + " --allow-routing-change");
  EXPECT_EQ(allowed.code, 0) << allowed.output;
  EXPECT_NE(allowed.output.find("1 image written"), std::string::npos) << allowed.output;
  EXPECT_TRUE(read_png(golden(kPattern, 1)) == original);
}

// A golden image missing: the command that makes it, with the folders this check used.
TEST_F(GoldenCli, AMissingGoldenImageNamesTheCommandThatMakesIt) {
  fs::remove(golden(kPattern, 2));
  const Result r = l2wall("check " + common() + " --entry " + kPattern);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("golden image " + golden(kPattern, 2).string() +
                          " is missing (make it with `l2wall golden update --goldens " +
                          goldens().string() + " --root " + kSource.string() + " --entry " +
                          kPattern + "`)"),
            std::string::npos)
      << r.output;
}

// Wider mullions move displays on the canvas but route every display pixel as before: the
// routing-only entry sees it, as its pattern encodes canvas positions, and its hint names the
// flag the update then needs.
TEST_F(GoldenCli, AWallWithWiderMullionsFailsTheRoutingEntry) {
  const fs::path root = dir_ / "root";
  fs::create_directories(root / "walls");
  std::ostringstream text;
  text << std::ifstream(kSource / "walls/kd-2x2.toml").rdbuf();
  std::string wall = text.str();
  const std::string was = "mullion_x = 20 ";
  ASSERT_NE(wall.find(was), std::string::npos);
  wall.replace(wall.find(was), was.size(), "mullion_x = 24 ");
  std::ofstream(root / "walls/kd-2x2.toml") << wall;
  const Result r = l2wall("check " + common() + " --root " + quote(root) + " --entry " + kPattern);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find(kPattern + " display 1: emulator vs golden image: "), std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find(kPattern + " display 0: emulator vs golden image: "), std::string::npos)
      << r.output;  // display 0 stays where it was
  EXPECT_NE(r.output.find("golden check: if the change is intended, make them the golden images: "
                          "`l2wall golden update --goldens " +
                          goldens().string() + " --root " + root.string() + " --entry " + kPattern +
                          " --allow-routing-change`\n"),
            std::string::npos)
      << r.output;
}

// Without --goldens an update would write into the project's own golden folder: it refuses,
// before running anything, and says which folder that was.
TEST_F(GoldenCli, UpdateWritesOnlyIntoAFolderItIsGiven) {
  const fs::path manifest = kSource / "tests/golden_images/manifest.toml";
  const auto before = fs::last_write_time(manifest);
  const Result r = l2wall("update --out " + quote(out()) + " --entry " + kPattern);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("l2wall golden update: give --goldens DIR, the golden folder to write; "
                          "the default, "),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("tests/golden_images, is the project's own (to regenerate it, name "
                          "it)\n"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("[1/1]"), std::string::npos) << r.output;  // nothing was run
  EXPECT_EQ(fs::last_write_time(manifest), before);
}

TEST_F(GoldenCli, UsageErrorsAreOneLine) {
  Result r = l2wall("check " + common() + " --entry rabbit");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(
      r.output.find("l2wall golden: --entry rabbit: no such entry; the manifest has " + kPattern),
      std::string::npos)
      << r.output;
  r = l2wall("check " + common() + " --entry kd-2x2-bunny --inputs " + quote(dir_));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("--inputs: kd-2x2-bunny is a rendered entry"), std::string::npos)
      << r.output;
  r = l2wall("check --goldens " + quote(dir_) + " --out " + quote(out()));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find((dir_ / "manifest.toml").string() + ": cannot read"), std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace l2
