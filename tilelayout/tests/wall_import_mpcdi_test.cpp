// tilelayout import's MPCDI reader (import_mpcdi: mpcdi.xml and the archive's entry names in):
// regions become displays where their buffer puts them, the fileset's files are named by warp,
// alpha, alpha_gamma and beta and listed to extract, and the wall reads back with them; and
// every refusal is one line naming the file, mpcdi.xml's line and the field. Expected values
// are worked out by hand from the XML in the test.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "grey_png.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall_file.hpp"
#include "tilelayout/wall_import.hpp"

namespace l2::mpcdi_tests {
namespace {

namespace fs = std::filesystem;

// Two 64x48 projectors on a 120x48 buffer, overlapping by 8 columns: the right one at
// x = 56/120. `profile`, `version`, the right region's xResolution and its fileset can be
// changed by the tests.
struct Xml {
  std::string profile = "2d", version = "2.0", right_width = "64";
  std::string right_fileset = R"(
    <fileset region="r">
      <geometryWarpFile><path>r/warp.pfm</path><interpolation>linear</interpolation></geometryWarpFile>
      <alphaMap><path>r/alpha.png</path><componentDepth>1</componentDepth><bitDepth>8</bitDepth>
        <gammaEmbedded>1.0</gammaEmbedded></alphaMap>
      <betaMap><path>r/beta.png</path><componentDepth>1</componentDepth><bitDepth>8</bitDepth></betaMap>
    </fileset>)";

  std::string text() const {
    return R"(<?xml version="1.0"?>
<MPCDI profile=")" +
           profile + R"(" geometry="1" version=")" + version + R"(">
  <display>
    <buffer id="b" xResolution="120" yResolution="48">
      <region id="l" x="0" y="0" xsize="0.533333" ysize="1" xResolution="64" yResolution="48"/>
      <region id="r" x="0.466667" y="0" xsize="0.533333" ysize="1" xResolution=")" +
           right_width + R"(" yResolution="48"/>
    </buffer>
  </display>
  <files>
    <fileset region="l">
      <alphaMap><path>l/alpha.png</path><gammaEmbedded>2.2</gammaEmbedded></alphaMap>
    </fileset>)" +
           right_fileset + R"(
  </files>
</MPCDI>
)";
  }
};

const std::vector<std::string> kEntries = {"mpcdi.xml", "l/alpha.png", "r/warp.pfm", "r/alpha.png",
                                           "r/beta.png"};

ImportedWall imported(const std::string& xml, const std::vector<std::string>& entries = kEntries) {
  return import_mpcdi(xml, entries, "cal.mpcdi", {"wall.calibration", 2.2});
}

std::string error_of(const std::string& xml, const std::vector<std::string>& entries = kEntries) {
  try {
    imported(xml, entries);
  } catch (const LayoutError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << "imported: " << xml;
  return "";
}

// A 2x2-point PFM that puts every pixel on its own place: the identity warp.
std::string identity_pfm() {
  std::string out = "PF\n2 2\n-1\n";
  for (const float y : {1.0F, 0.0F}) {  // rows bottom to top
    for (const float x : {0.0F, 1.0F}) {
      for (const float v : {x, y, 0.0F}) out.append(reinterpret_cast<const char*>(&v), 4);
    }
  }
  return out;
}

TEST(WallImportMpcdi, RegionsBecomeDisplaysNamingTheirMaps) {
  const ImportedWall wall = imported(Xml().text());
  EXPECT_EQ(wall.format, ImportFormat::Mpcdi);
  ASSERT_EQ(wall.files.size(), 4u);
  EXPECT_EQ(wall.files[0].entry, "l/alpha.png");
  EXPECT_EQ(wall.files[0].path, "wall.calibration/d0-l-alpha.png");
  EXPECT_EQ(wall.files[1].entry, "r/warp.pfm");
  EXPECT_EQ(wall.files[1].path, "wall.calibration/d1-r-warp.pfm");
  // Maps carry their display's size (to be resampled to it when they differ); a warp none.
  EXPECT_EQ(wall.files[0].width, 64);
  EXPECT_EQ(wall.files[0].height, 48);
  EXPECT_EQ(wall.files[1].width, 0);
  EXPECT_EQ(wall.files[2].path, "wall.calibration/d1-r-alpha.png");
  EXPECT_EQ(wall.files[3].path, "wall.calibration/d1-r-beta.png");
  EXPECT_NE(wall.toml.find("alpha_gamma = 2.2  # display gamma 2.2 / gammaEmbedded 1\n"),
            std::string::npos)
      << wall.toml;

  // The files where the wall will find them: it reads back as every program reads it.
  const fs::path dir = fs::temp_directory_path() / ("mpcdi_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "wall.calibration");
  std::ofstream(dir / wall.files[1].path, std::ios::binary) << identity_pfm();
  for (const int f : {0, 2, 3}) {
    testing_support::write_grey_png(dir / wall.files[f].path, 64, 48,
                                    std::vector<std::uint8_t>(64 * 48, f == 3 ? 10 : 128));
  }
  const Wall w = parse_wall(wall.toml, dir / "wall.toml");
  fs::remove_all(dir);
  ASSERT_EQ(w.displays.size(), 2u);
  EXPECT_EQ(w.displays[0].canvas_x, 0);
  EXPECT_EQ(w.displays[1].canvas_x, 56);  // 0.466667 x 120, rounded
  EXPECT_EQ(w.displays[1].width, 64);
  EXPECT_EQ(w.displays[1].height, 48);
  EXPECT_EQ(w.displays[0].warp, "");
  EXPECT_EQ(w.displays[0].alpha, "wall.calibration/d0-l-alpha.png");
  EXPECT_EQ(w.displays[0].alpha_gamma, 1.0);  // gammaEmbedded 2.2 on projectors of gamma 2.2
  EXPECT_EQ(w.displays[1].warp, "wall.calibration/d1-r-warp.pfm");
  EXPECT_EQ(w.displays[1].alpha_gamma, 2.2);
  EXPECT_EQ(w.displays[1].beta, "wall.calibration/d1-r-beta.png");
  ASSERT_TRUE(w.displays[1].level_map);
}

TEST(WallImportMpcdi, Version1AndNotesForWhatTheWallDoesNotCarry) {
  Xml x;
  x.version = "1.0";
  x.right_fileset = R"(<fileset region="r"><alphaMap><path>./r/alpha.png</path>
      <bitDepth>16</bitDepth></alphaMap><distortionMap><path>d.pfm</path></distortionMap>
      </fileset>)";
  const ImportedWall wall = imported(x.text());
  ASSERT_EQ(wall.files.size(), 2u);
  EXPECT_EQ(wall.files[1].entry, "r/alpha.png");  // "./" dropped
  const std::vector<std::string> notes = {
      "MPCDI.files.fileset[0]: no geometryWarpFile: shown unwarped",
      "MPCDI.files.fileset[1]: no geometryWarpFile: shown unwarped",
      "MPCDI.files.fileset[1].alphaMap: a 16-bit map, read rounded to 8 bits (its finer steps "
      "are not kept)",
      "MPCDI.files.fileset[1].alphaMap: no gammaEmbedded: taken as the display's gamma 2.2 (the "
      "map used as it is)",
      "MPCDI.files.fileset[1].distortionMap: not carried (the wall file has no place for it)"};
  EXPECT_EQ(wall.notes, notes);
}

TEST(WallImportMpcdi, ARegionScaledInItsBufferIsNoted) {
  Xml x;
  x.right_width = "80";  // 0.533333 x 120 = 64 buffer pixels for an 80-pixel raster
  const ImportedWall wall = imported(x.text());
  ASSERT_EQ(wall.notes.size(), 2u);  // and fileset[0]: no geometryWarpFile
  EXPECT_EQ(
      wall.notes[0],
      "MPCDI.display.buffer[0].region[1]: covers 64x48 pixels of its buffer with a 80x48 raster: "
      "the wall shows it at its raster's size, one canvas pixel a projector pixel");
}

TEST(WallImportMpcdi, AnotherProfileIsOneLine) {
  Xml x;
  x.profile = "3d";
  EXPECT_EQ(error_of(x.text()),
            "cal.mpcdi: mpcdi.xml:2: MPCDI.profile: \"3d\" is the 3D media profile: tilelayout "
            "import takes the 2D media profile only (profile=\"2d\": regions of one flat "
            "picture), not a projection of a 3D scene");
  x.profile = "shader";
  EXPECT_EQ(error_of(x.text()).substr(0, 52),
            "cal.mpcdi: mpcdi.xml:2: MPCDI.profile: \"shader\": til");
  x.profile = "2d";
  x.version = "3.0";
  EXPECT_EQ(error_of(x.text()),
            "cal.mpcdi: mpcdi.xml:2: MPCDI.version: expected 1.0 or 2.0, got \"3.0\"");
}

TEST(WallImportMpcdi, MalformedXmlNamesItsLine) {
  std::string xml = Xml().text();
  xml.replace(xml.find("</buffer>"), 9, "</buffr>");  // tinyxml2 names the element's line
  EXPECT_EQ(error_of(xml), "cal.mpcdi: mpcdi.xml:4: not well-formed XML: mismatched element");
  EXPECT_EQ(error_of(""), "cal.mpcdi: mpcdi.xml:0: not well-formed XML: empty document");
  EXPECT_EQ(error_of("<mpcdi/>"),
            "cal.mpcdi: mpcdi.xml:1: MPCDI: the root element is \"mpcdi\": not an MPCDI "
            "document");
}

TEST(WallImportMpcdi, FilesAndFilesetsThatAreMissing) {
  Xml x;
  EXPECT_EQ(error_of(x.text(), {"mpcdi.xml", "l/alpha.png", "r/warp.pfm", "r/alpha.png"}),
            "cal.mpcdi: mpcdi.xml:17: MPCDI.files.fileset[1].betaMap.path: \"r/beta.png\" is not "
            "in the archive");
  x.right_fileset = "";
  EXPECT_EQ(
      error_of(x.text()),
      "cal.mpcdi: mpcdi.xml:6: MPCDI.display.buffer[0].region[1].id: \"r\": no fileset in files "
      "names this region");
  x.right_fileset = R"(<fileset region="q"/>)";
  EXPECT_EQ(error_of(x.text()),
            "cal.mpcdi: mpcdi.xml:12: MPCDI.files.fileset[1].region: \"q\": no region of display "
            "has this id");
}

TEST(WallImportMpcdi, AbsurdValues) {
  Xml x;
  x.right_width = "100000";
  EXPECT_EQ(
      error_of(x.text()),
      "cal.mpcdi: mpcdi.xml:6: MPCDI.display.buffer[0].region[1].xResolution: expected a whole "
      "number 1..4095, got \"100000\"");
  x.right_width = "0";
  EXPECT_EQ(
      error_of(x.text()),
      "cal.mpcdi: mpcdi.xml:6: MPCDI.display.buffer[0].region[1].xResolution: expected a whole "
      "number 1..4095, got \"0\"");
  x.right_width = "64";
  x.right_fileset = R"(<fileset region="r"><alphaMap><path>r/alpha.png</path>
      <componentDepth>3</componentDepth></alphaMap></fileset>)";
  EXPECT_EQ(error_of(x.text()),
            "cal.mpcdi: mpcdi.xml:13: MPCDI.files.fileset[1].alphaMap.componentDepth: 3 (a colour "
            "map): the wall's alpha and beta maps are grey (componentDepth 1)");
  x.right_fileset = R"(<fileset region="r"><alphaMap><path>r/alpha.png</path>
      <gammaEmbedded>3</gammaEmbedded></alphaMap></fileset>)";
  EXPECT_EQ(error_of(x.text()),
            "cal.mpcdi: mpcdi.xml:13: MPCDI.files.fileset[1].alphaMap.gammaEmbedded: 3 on "
            "projectors of gamma 2.2 makes alpha_gamma 0.733, outside the 1..4 a wall takes "
            "(--display-gamma sets the projectors' gamma)");
}

TEST(WallImportMpcdi, AZipGivenToTheJsonImporterSaysWhatItIs) {
  try {
    import_wall(std::string("PK\x03\x04\x14\x00", 6), "cal.mpcdi");
    ADD_FAILURE() << "imported a zip as JSON";
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(),
                 "cal.mpcdi: an MPCDI archive (a zip file): its mpcdi.xml is read by import_mpcdi");
  }
}

}  // namespace
}  // namespace l2::mpcdi_tests
