// tilelayout import of an MPCDI calibration, the real executable: the example archive
// (examples/walls/imported/projectors-2x1-warped.mpcdi, made by make-mpcdi.py from
// walls/projectors-2x1-warped.toml's calibration) gives that wall's displays and warps, its maps
// extracted beside the wall file; archives that are broken or hostile are one line each.
#include <gtest/gtest.h>
#include <zip.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "image/level_map.hpp"
#include "image/png_io.hpp"
#include "tilelayout/blend_map.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using cli_testing::ChildRun;
using cli_testing::Cli;
using cli_testing::slurp;

const std::string kExample = std::string(L2_IMPORTED_DIR) + "/projectors-2x1-warped.mpcdi";

// A zip file of `entries` (name, bytes), written with libzip.
void write_zip(const fs::path& path,
               const std::vector<std::pair<std::string, std::string>>& entries) {
  int error = 0;
  zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  ASSERT_NE(z, nullptr);
  for (const auto& [name, bytes] : entries) {
    zip_source_t* s = zip_source_buffer(z, bytes.data(), bytes.size(), 0);
    ASSERT_GE(zip_file_add(z, name.c_str(), s, ZIP_FL_OVERWRITE), 0);
  }
  ASSERT_EQ(zip_close(z), 0);  // reads the buffers: they must live until here
}

const std::string kOneRegion = R"(<MPCDI profile="2d" version="2.0"><display>
<buffer id="b" xResolution="64" yResolution="48">
<region id="r" x="0" y="0" xsize="1" ysize="1" xResolution="64" yResolution="48"/></buffer>
</display><files><fileset region="r"><alphaMap><path>a.png</path></alphaMap></fileset></files>
</MPCDI>)";

TEST_F(Cli, MpcdiImportGivesTheWarpedProjectorsWithTheirMaps) {
  const fs::path wall = dir_ / "imported.toml";
  const ChildRun r = run("import '" + kExample + "' --write '" + wall.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "wrote " + wall.string() + "\nwrote 5 files of its maps into " +
                       (dir_ / "imported.calibration").string() + "\n");
  const Wall imported = load_wall(wall);
  const Wall original = load_wall(std::string(L2_WALLS_DIR) + "/projectors-2x1-warped.toml");
  ASSERT_EQ(imported.displays.size(), 2u);
  const int left_of[] = {0, 960};
  const char* names[] = {"d0-left", "d1-right"};
  for (int i = 0; i < 2; ++i) {
    const Display& d = imported.displays[i];
    EXPECT_EQ(d.width, 1024);
    EXPECT_EQ(d.height, 768);
    EXPECT_EQ(d.canvas_x, left_of[i]);
    EXPECT_EQ(d.canvas_y, 0);
    EXPECT_EQ(d.warp, std::string("imported.calibration/") + names[i] + "-warp.pfm");
    EXPECT_EQ(d.alpha, std::string("imported.calibration/") + names[i] + "-alpha.png");
    EXPECT_EQ(d.alpha_gamma, 2.2);  // linear maps (gammaEmbedded 1) on projectors of gamma 2.2
    // The same warp as the wall it was made from: the PFM extracted byte for byte.
    ASSERT_TRUE(d.warp_map && original.displays[i].warp_map);
    EXPECT_EQ(d.warp_map->source, original.displays[i].warp_map->source);
  }
  EXPECT_EQ(imported.displays[0].beta, "");
  EXPECT_EQ(imported.displays[1].beta, "imported.calibration/d1-right-beta.png");
  // The alpha maps as make-mpcdi.py wrote them: 255 outside the 64 overlap columns, falling
  // across them, round(w x 255) with w = (1024 - u - 0.5) / 64 (left) at canvas column u.
  const RgbImage left = read_png(dir_ / "imported.calibration/d0-left-alpha.png");
  const RgbImage right = read_png(dir_ / "imported.calibration/d1-right-alpha.png");
  EXPECT_EQ(left.at(0, 0).r, 255);
  EXPECT_EQ(left.at(959, 767).r, 255);
  EXPECT_EQ(left.at(960, 0).r, 253);  // w = 63.5 / 64
  EXPECT_EQ(left.at(1023, 0).r, 2);   // w = 0.5 / 64
  EXPECT_EQ(right.at(0, 0).r, 2);
  EXPECT_EQ(right.at(63, 0).r, 253);
  EXPECT_EQ(right.at(64, 0).r, 255);
  // The light the two walls send: the imported alpha maps (8 bits, alpha_gamma 2.2) against the
  // original's generated blend (weights in 1/4096 at gamma 2.2), every code value of every
  // column: the same outside the overlap, within one code value across it (an alpha byte is a
  // coarser step than a blend weight).
  for (int i = 0; i < 2; ++i) {
    const std::vector<std::uint16_t> weights = blend_weights(original, i);
    const LevelMap& level = *imported.displays[i].level_map;
    int worst = 0;
    for (int x = 0; x < 1024; ++x) {
      const ColourTable blend = blend_table(weights[static_cast<std::size_t>(x)], 2.2);
      for (int in = 0; in < 256; ++in) {
        const auto shown = static_cast<int>(
            (static_cast<std::uint64_t>(in) * level.gain[static_cast<std::size_t>(x)] +
             level.offset[static_cast<std::size_t>(x)] + kLevelOne / 2) /
            kLevelOne);
        const int diff = std::abs(shown - blend.channel[0][static_cast<std::size_t>(in)]);
        if (weights[static_cast<std::size_t>(x)] == kBlendOne) {
          EXPECT_EQ(diff, 0) << x << " " << in;
        }
        worst = std::max(worst, diff);
      }
    }
    EXPECT_LE(worst, 1) << "display " << i;
  }
  // tilelayout --wall plans it, and says what each display carries.
  const ChildRun planned = run("--wall '" + wall.string() + "'");
  EXPECT_EQ(planned.status, 0) << planned.err;
  EXPECT_NE(planned.out.find("warp imported.calibration/d1-right-warp.pfm; alpha "
                             "imported.calibration/d1-right-alpha.png at gamma 2.2; beta "
                             "imported.calibration/d1-right-beta.png"),
            std::string::npos)
      << planned.out;
}

TEST_F(Cli, MpcdiImportWithoutWritePrintsTheWallAndExtractsNothing) {
  const ChildRun r = run("import --format mpcdi '" + kExample + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("warp = \"projectors-2x1-warped.calibration/d0-left-warp.pfm\""),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.err,
            "note: the 5 files of its maps are not extracted without --write WALL, which puts "
            "them in WALL's folder, in WALL-STEM.calibration/\n");
  EXPECT_FALSE(fs::exists("projectors-2x1-warped.calibration"));
}

TEST_F(Cli, MpcdiImportResamplesACoarserMap) {
  // A 2x1 alpha map, 0 and 255, for a 64x48 projector: column x samples the map at
  // (x + 0.5) * 2 / 64 - 0.5, so 31 at 0.484375 (123.5 of 255, to 124) and 32 at 0.515625
  // (131.48, to 131); the edges keep the map's edge values.
  const fs::path cal = dir_ / "coarse.mpcdi";
  const std::vector<std::uint8_t> map = {0, 255};
  write_zip(cal, {{"mpcdi.xml", kOneRegion}, {"a.png", encode_grey_png(2, 1, map)}});
  const ChildRun r =
      run("import '" + cal.string() + "' --write '" + (dir_ / "w.toml").string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("note: a.png: 2x1, resampled (bilinear) to its display's 64x48 as "
                       "w.calibration/d0-r-alpha.png\n"),
            std::string::npos)
      << r.out;
  PictureSource source;
  const RgbImage alpha = read_png(dir_ / "w.calibration/d0-r-alpha.png", &source);
  EXPECT_EQ(source.colour_channels, 1);
  ASSERT_EQ(alpha.width(), 64);
  ASSERT_EQ(alpha.height(), 48);
  EXPECT_EQ(alpha.at(0, 0).r, 0);
  EXPECT_EQ(alpha.at(31, 0).r, 124);
  EXPECT_EQ(alpha.at(32, 47).r, 131);
  EXPECT_EQ(alpha.at(63, 47).r, 255);
  EXPECT_EQ(load_wall(dir_ / "w.toml").displays[0].alpha, "w.calibration/d0-r-alpha.png");
}

TEST_F(Cli, MpcdiImportRefusals) {
  const fs::path no_xml = dir_ / "no-xml.mpcdi";
  write_zip(no_xml, {{"a.png", "x"}});
  ChildRun r = run("import '" + no_xml.string() + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "tilelayout import: " + no_xml.string() +
                       ": mpcdi.xml: not in the archive (an MPCDI file describes its displays "
                       "there)\n");

  const fs::path not_zip = write("cal.mpcdi", "<MPCDI/>");
  r = run("import --format mpcdi '" + not_zip.string() + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "tilelayout import: " + not_zip.string() +
                       ": not a zip archive (an MPCDI file is one): Not a zip archive\n");

  // A map the wall cannot take (a colour PNG): refused as the wall reads it back, and nothing
  // left behind.
  RgbImage colour(64, 48);
  const fs::path coloured = dir_ / "colour.mpcdi";
  write_zip(coloured, {{"mpcdi.xml", kOneRegion}, {"a.png", encode_png(colour)}});
  r = run("import '" + coloured.string() + "' --write '" + (dir_ / "w.toml").string() + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err,
            "tilelayout import: " + coloured.string() +
                ": the imported wall does not load with its maps: " + (dir_ / "w.toml").string() +
                ":17: display[0].alpha: " + (dir_ / "w.calibration/d0-r-alpha.png").string() +
                ": must be a grey PNG, got colour png\n");
  EXPECT_FALSE(fs::exists(dir_ / "w.toml"));
  EXPECT_FALSE(fs::exists(dir_ / "w.calibration"));

  // A zip bomb: an entry that inflates to 257 MiB, refused from its declared size.
  const fs::path bomb = dir_ / "bomb.mpcdi";
  write_zip(bomb, {{"mpcdi.xml", kOneRegion}, {"a.png", std::string(257u << 20, '\0')}});
  EXPECT_LT(fs::file_size(bomb), 1u << 20);
  r = run("import '" + bomb.string() + "' --write '" + (dir_ / "w.toml").string() + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "tilelayout import: " + bomb.string() +
                       ": a.png: inflates to more than 268435456 bytes, more than any file of a "
                       "calibration: refused (a damaged or hostile archive)\n");
  EXPECT_FALSE(fs::exists(dir_ / "w.calibration"));

  r = run("import '" + std::string(L2_IMPORTED_DIR) + "/tide-bbp-4x3.json' --display-gamma 2");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--display-gamma is for MPCDI calibrations"), std::string::npos) << r.err;
  r = run("import --help");
  EXPECT_NE(r.out.find("--display-gamma"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mpcdi"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace l2
