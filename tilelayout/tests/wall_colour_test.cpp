// Colour matching in the wall file and colour table files: the tables a display gets (entries
// worked out by hand from the documented formula), and every refusal's exact line.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tilelayout/colour_lut.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall_file.hpp"
#include "wall_folder.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

// Line numbers matter: errors below name them. Two [[display]] entries.
const std::string kList =
    "[[display]]\n"               // 1
    "width = 4\n"                 // 2
    "height = 2\n"                // 3
    "x = 0\n"                     // 4
    "y = 0\n"                     // 5
    "[[display]]\n"               // 6
    "width = 4\n"                 // 7
    "height = 2\n"                // 8
    "x = 4\n"                     // 9
    "y = 0\n"                     // 10
    "COLOUR\n"                    // 11
    "[tiling]\n"                  // 12
    "kind = \"grid\"\n"           // 13
    "tile_width = 4\n"            // 14
    "tile_height = 2\n"           // 15
    "[pipeservers]\n"             // 16
    "count = 1\n"                 // 17
    "framebuffer_width = 20\n"    // 18
    "framebuffer_height = 10\n";  // 19

std::string with(const std::string& colour) {
  std::string text = kList;
  text.replace(text.find("COLOUR"), 6, colour);
  return text;
}

class WallColour : public WallFolder {
 protected:
  WallColour() : WallFolder("colour") {}
};

// 256 lines "R G B": R = i, G = 255 - i, B = i / 2, with comments and blank lines between.
std::string table_text() {
  std::string text = "# a measured panel\n\n";
  for (int i = 0; i < 256; ++i) {
    text += std::to_string(i) + " " + std::to_string(255 - i) + "\t" + std::to_string(i / 2);
    text += i == 7 ? "   # a comment after an entry\n" : "\n";
  }
  return text;
}

TEST_F(WallColour, ADisplayWithoutColourAppliesNothing) {
  const Wall w = parse(with(""));
  EXPECT_EQ(w.displays[0].colour.kind, ColourMatch::Kind::None);
  EXPECT_FALSE(w.displays[0].colour.applies());
  EXPECT_TRUE(w.displays[0].colour.table.is_identity());
}

TEST_F(WallColour, GainAndOffsetBecomeOneTable) {
  const Wall w = parse(with("gain = [1, 0.96, 0.92]\noffset = [0, 0, 4]"));
  const ColourMatch& c = w.displays[1].colour;
  EXPECT_EQ(c.kind, ColourMatch::Kind::Gain);
  EXPECT_TRUE(c.applies());
  EXPECT_EQ(c.gain, (std::array<double, 3>{1.0, 0.96, 0.92}));
  EXPECT_EQ(c.offset, (std::array<int, 3>{0, 0, 4}));
  EXPECT_EQ(c.table.channel[0][77], 77);
  EXPECT_EQ(c.table.channel[1][255], 245);  // 244.8
  EXPECT_EQ(c.table.channel[2][0], 4);      // 0 + 4
  EXPECT_EQ(c.table.channel[2][255], 239);  // 234.6 -> 235, + 4
  EXPECT_FALSE(w.displays[0].colour.applies());
  // Only an offset: the gain stays 1.
  const Wall o = parse(with("offset = [-3, 0, 0]"));
  EXPECT_EQ(o.displays[1].colour.table.channel[0][2], 0);
  EXPECT_EQ(o.displays[1].colour.table.channel[0][200], 197);
  EXPECT_EQ(o.displays[1].colour.table.channel[1][200], 200);
}

TEST_F(WallColour, ATableFileRelativeToTheWallFile) {
  write("calibration/panel.txt", table_text());
  const Wall w = parse(with("lut = \"calibration/panel.txt\""));
  const ColourMatch& c = w.displays[1].colour;
  EXPECT_EQ(c.kind, ColourMatch::Kind::Lut);
  EXPECT_EQ(c.lut, "calibration/panel.txt");
  for (const int i : {0, 7, 8, 128, 255}) {
    EXPECT_EQ(c.table.channel[0][i], i);
    EXPECT_EQ(c.table.channel[1][i], 255 - i);
    EXPECT_EQ(c.table.channel[2][i], i / 2);
  }
}

TEST_F(WallColour, AGridGivesEachDisplayItsOwn) {
  write("p1.txt", table_text());
  const std::string grid =
      "[display_grid]\n"
      "columns = 3\n"
      "rows = 1\n"
      "width = 4\n"
      "height = 2\n"
      "colour = [{gain = [2, 1, 1]}, {}, {lut = \"p1.txt\"}]\n"
      "[tiling]\n"
      "kind = \"grid\"\n"
      "tile_width = 4\n"
      "tile_height = 2\n"
      "[pipeservers]\n"
      "count = 1\n"
      "framebuffer_width = 20\n"
      "framebuffer_height = 10\n";
  const Wall w = parse(grid);
  EXPECT_EQ(w.displays[0].colour.kind, ColourMatch::Kind::Gain);
  EXPECT_EQ(w.displays[0].colour.table.channel[0][100], 200);
  EXPECT_EQ(w.displays[1].colour.kind, ColourMatch::Kind::None);
  EXPECT_EQ(w.displays[2].colour.kind, ColourMatch::Kind::Lut);
  EXPECT_EQ(w.displays[2].colour.table.channel[1][0], 255);
  std::string two = grid;
  two.replace(two.find("{gain = [2, 1, 1]}, "), 20, "");
  EXPECT_EQ(error_of(two), wall_file() +
                               ":6: display_grid.colour: needs 3 entries (one per display, {} for "
                               "none), got 2");
  std::string bad = grid;
  bad.replace(bad.find("{}"), 2, "{gain = [1, 1]}");
  EXPECT_EQ(error_of(bad),
            wall_file() + ":6: display_grid.colour[1].gain: needs 3 numbers 0..4, got 2");
  bad = grid;
  bad.replace(bad.find("{}"), 2, "3");
  EXPECT_EQ(error_of(bad), wall_file() +
                               ":6: display_grid.colour[1]: must be a table ({gain = [...]}, {lut "
                               "= \"...\"} or {}), got an integer");
}

TEST_F(WallColour, BadValuesAreOneLineNamingFileLineAndField) {
  const std::string f = wall_file();
  EXPECT_EQ(error_of(with("gain = [1, 0.9]")),
            f + ":11: display[1].gain: needs 3 numbers 0..4, got 2");
  EXPECT_EQ(error_of(with("gain = 1.0")),
            f + ":11: display[1].gain: needs 3 numbers 0..4, got a number");
  EXPECT_EQ(error_of(with("gain = [1, 4.5, 1]")),
            f + ":11: display[1].gain[1]: must be a number 0..4, got 4.5");
  EXPECT_EQ(error_of(with("gain = [1, -0.5, 1]")),
            f + ":11: display[1].gain[1]: must be a number 0..4, got -0.5");
  EXPECT_EQ(error_of(with("gain = [1, 1, \"x\"]")),
            f + ":11: display[1].gain[2]: must be a number 0..4, got a string");
  EXPECT_EQ(error_of(with("offset = [0, 0, 300]")),
            f + ":11: display[1].offset[2]: must be -255..255, got 300");
  EXPECT_EQ(error_of(with("offset = [0, 0.5, 0]")),
            f + ":11: display[1].offset[1]: must be an integer, got a number");
  EXPECT_EQ(error_of(with("offset = [0, 0, 0, 0]")),
            f + ":11: display[1].offset: needs 3 integers -255..255, got 4");
  EXPECT_EQ(error_of(with("lut = \"p.txt\"\ngain = [1, 1, 1]")),
            f + ":11: display[1].lut: use either lut or gain/offset, not both");
  EXPECT_EQ(error_of(with("lut = \"\"")),
            f + ":11: display[1].lut: must name a colour table file, got \"\"");
  EXPECT_EQ(error_of(with("lut = 3")), f + ":11: display[1].lut: must be a string, got an integer");
  EXPECT_EQ(error_of(with("lut = \"none.txt\"")),
            f + ":11: display[1].lut: " + (dir_ / "none.txt").string() +
                ": cannot read: No such file or directory");
  EXPECT_EQ(
      error_of(with("lut = \"/dev/null\"")),
      f + ":11: display[1].lut: /dev/null: not a regular file: a colour table is a text file");
  EXPECT_EQ(error_of(with("colour = [{}]")),
            f + ":11: display[1].colour: unknown key (valid here: id, mesh, width, height, x, "
                "y, swap_group, monitor, rotation, flip, gain, offset, lut, warp, alpha, beta, "
                "alpha_gamma, eye)");
}

TEST_F(WallColour, ABadTableNamesItsOwnFileAndLine) {
  std::string text = table_text();
  // The 17th line of the file: two header lines, then entry 14 ("14 241 7").
  text.replace(text.find("14 241\t7"), 8, "12 300 4");
  write("bad.txt", text);
  EXPECT_EQ(error_of(with("lut = \"bad.txt\"")),
            (dir_ / "bad.txt").string() + ":17: expected 3 integers 0..255, got \"12 300 4\"");
}

// The table text alone: what parse_colour_lut refuses, word for word.
std::string lut_error(const std::string& text) {
  try {
    parse_colour_lut(text, "calibration/panel-3.txt");
  } catch (const LayoutError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ColourLut, RefusesEveryMalformedEntry) {
  const std::string name = "calibration/panel-3.txt";
  EXPECT_EQ(lut_error("1 2\n"), name + ":1: expected 3 integers 0..255, got \"1 2\"");
  EXPECT_EQ(lut_error("# x\n1 2 3 4\n"), name + ":2: expected 3 integers 0..255, got \"1 2 3 4\"");
  EXPECT_EQ(lut_error("1 -2 3\n"), name + ":1: expected 3 integers 0..255, got \"1 -2 3\"");
  EXPECT_EQ(lut_error("1 2.5 3\n"), name + ":1: expected 3 integers 0..255, got \"1 2.5 3\"");
  EXPECT_EQ(lut_error("1 2 0x3\n"), name + ":1: expected 3 integers 0..255, got \"1 2 0x3\"");
  EXPECT_EQ(lut_error("1 2 99999999999999999999\n"),
            name + ":1: expected 3 integers 0..255, got \"1 2 99999999999999999999\"");
  // Control characters are escaped and a long line is cut: the error stays one short line.
  EXPECT_EQ(lut_error("1\x1b[2J 2 3\n"),
            name + ":1: expected 3 integers 0..255, got \"1\\x1b[2J 2 3\"");
  EXPECT_EQ(lut_error(std::string(100, 'x')),
            name + ":1: expected 3 integers 0..255, got \"" + std::string(40, 'x') + "...\"");
}

TEST(ColourLut, NeedsExactly256Entries) {
  std::string text;
  for (int i = 0; i < 255; ++i) text += "0 0 0\n";
  EXPECT_EQ(lut_error(text),
            "calibration/panel-3.txt: 255 entries, a table needs exactly 256: one for each input "
            "byte 0..255");
  text += "1 1 1\r\n";  // a file written on Windows is fine
  EXPECT_EQ(parse_colour_lut(text, "x").channel[2][255], 1);
  text += "\n# end\n2 2 2\n";  // line 259
  EXPECT_EQ(lut_error(text),
            "calibration/panel-3.txt:259: more than 256 entries: a table has one for each input "
            "byte 0..255");
  EXPECT_EQ(lut_error(""),
            "calibration/panel-3.txt: 0 entries, a table needs exactly 256: one for each input "
            "byte 0..255");
  EXPECT_EQ(lut_error(std::string(kMaxColourLutBytes + 1, '#')),
            "calibration/panel-3.txt: more than 64 KiB: not a colour table (256 lines of R G B)");
}

}  // namespace
}  // namespace l2
