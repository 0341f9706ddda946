// tilelayout import's refusals: one line naming the file and the JSON path of the field, for
// malformed JSON, wrong types, missing fields, absurd sizes and more displays than a wall holds.
#include <gtest/gtest.h>

#include <string>

#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall_import.hpp"

namespace l2::import_error_tests {
namespace {

std::string error_of(const std::string& text, const std::string& file = "config.json") {
  try {
    import_wall(text, file);
  } catch (const LayoutError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << "imported: " << text;
  return "";
}

// A Tide configuration with `surface` as its surfaces[0] and one process on host "h".
std::string tide(const std::string& surface, const std::string& screen = "{}") {
  return R"({"surfaces": [)" + surface + R"(], "processes": [{"host": "h", "screens": [)" + screen +
         "]}]}";
}

TEST(WallImportErrors, WrongTypeNamesTheFieldAndWhatIsThere) {
  EXPECT_EQ(error_of(tide(R"({"screenCountX": "two", "displayWidth": 100, "displayHeight": 80})")),
            "config.json: surfaces[0].screenCountX: expected a positive integer, got \"two\"");
  EXPECT_EQ(error_of(tide(R"({"displayWidth": 100.5, "displayHeight": 80})")),
            "config.json: surfaces[0].displayWidth: expected a positive integer, got 100.5");
  EXPECT_EQ(error_of(R"({"surfaces": [{"displayWidth": 100, "displayHeight": 80}],
                         "processes": [{"host": 5, "screens": []}]})"),
            "config.json: processes[0].host: expected a string, got 5");
  EXPECT_EQ(error_of(tide(R"({"displayWidth": 100, "displayHeight": 80})", R"({"i": 2})")),
            "config.json: processes[0].screens[0].i: expected an integer 0..0, got 2");
  EXPECT_EQ(error_of(R"({"surfaces": {}})"),
            "config.json: surfaces: expected an array, got an object");
}

TEST(WallImportErrors, MissingFields) {
  EXPECT_EQ(error_of(tide(R"({"displayWidth": 100})")),
            "config.json: surfaces[0].displayHeight: expected a positive integer, got nothing "
            "(the field is missing)");
  EXPECT_EQ(error_of(R"({"layout": {"rows": 1, "columns": 1}, "resolution": {"height": 10},
                         "displays": [{"row": 0, "column": 0}]})",
                     "wall-cfg.json"),
            "wall-cfg.json: resolution.width: expected a positive integer, got nothing (the "
            "field is missing)");
  EXPECT_EQ(error_of(R"({"nDisplay": {"cluster": {"nodes": {"n": {"host": "h",
                         "viewports": {}}}}}})",
                     "x.ndisplay"),
            "x.ndisplay: nDisplay.cluster.nodes.n.window: expected an object, got nothing (the "
            "field is missing)");
}

TEST(WallImportErrors, MalformedJsonSaysWhere) {
  EXPECT_EQ(error_of("{\n  \"surfaces\": [1,,2]\n}"),
            "config.json: not valid JSON: parse error at line 2, column 18: syntax error while "
            "parsing value - unexpected ','; expected '[', '{', or a literal");
  // A number no double holds is not JSON a wall can use (found by fuzz_wall_import).
  EXPECT_EQ(error_of(R"({"surfaces": [{"displayWidth": 1e999}]})"),
            "config.json: not valid JSON: number overflow parsing '1e999'");
  EXPECT_EQ(error_of("[1, 2]"), "config.json: expected a JSON object at the top, got an array");
  EXPECT_EQ(error_of(R"({"name": "x"})"),
            "config.json: not a configuration tilelayout import knows: no \"surfaces\" (Tide), "
            "\"layout\" (SAGE2) or \"nDisplay\" at the top; --format names the format");
}

TEST(WallImportErrors, AbsurdSizesAreRefusedBeforeAnythingIsMade) {
  EXPECT_EQ(error_of(tide(R"({"screenCountX": 1000000000, "displayWidth": 100,
                              "displayHeight": 80})")),
            "config.json: surfaces[0].screenCountX: expected a positive integer up to 64, got "
            "1000000000");
  EXPECT_EQ(error_of(tide(R"({"displayWidth": 100000, "displayHeight": 80})")),
            "config.json: surfaces[0].displayWidth: expected a positive integer up to 4095, got "
            "100000");
  // A bezel overlapping a whole display would leave it no pixel of its own.
  EXPECT_EQ(error_of(tide(R"({"displayWidth": 100, "displayHeight": 80, "bezelWidth": -100})")),
            "config.json: surfaces[0].bezelWidth: expected an integer -99..4095, got -100");
  EXPECT_EQ(error_of(R"({"layout": {"rows": 1, "columns": 1}, "resolution": {"width": 100,
      "height": 80}, "dimensions": {"tile_width": 0.001, "tile_height": 1,
      "tile_borders": [1, 1, 0, 0]}, "displays": [{"row": 0, "column": 0}]})"),
            "config.json: dimensions.tile_borders: tile borders of 2 m are 200000 pixels at the "
            "tiles' pitch, more than 4095");
}

TEST(WallImportErrors, MoreThanSixtyFourDisplaysNamesTheCount) {
  EXPECT_EQ(error_of(tide(R"({"screenCountX": 9, "screenCountY": 8, "displayWidth": 100,
                              "displayHeight": 80})")),
            "config.json: surfaces[0]: 72 displays, more than the 64 one mesh addresses, which is "
            "all an import makes (a wall of more is served by several meshes: docs/wall-file.md)");
  std::string viewports;
  for (int i = 0; i < 65; ++i) {
    viewports += (i ? "," : "") + std::string("\"v") + std::to_string(i) +
                 R"(": {"region": {"x": 0, "y": 0, "w": 10, "h": 10}})";
  }
  EXPECT_EQ(error_of(R"({"nDisplay": {"cluster": {"nodes": {"n": {"host": "h", "window": {"x": 0,
                         "y": 0, "w": 10, "h": 10}, "viewports": {)" +
                         viewports + "}}}}}}",
                     "big.ndisplay"),
            "big.ndisplay: nDisplay.cluster.nodes: 65 displays, more than the 64 one mesh "
            "addresses, which is all an import makes (a wall of more is served by several "
            "meshes: docs/wall-file.md)");
}

TEST(WallImportErrors, NDisplayAngleOffTheQuarterTurns) {
  EXPECT_EQ(error_of(R"({"nDisplay": {"cluster": {"nodes": {"n": {"host": "h", "window": {"x": 0,
      "y": 0, "w": 10, "h": 10}, "viewports": {"v": {"region": {"x": 0, "y": 0, "w": 10, "h": 10},
      "viewportRemap": {"bEnable": true, "baseRemap": {"angle": 45}}}}}}}}})",
                     "a.ndisplay"),
            "a.ndisplay: nDisplay.cluster.nodes.n.viewports.v.viewportRemap.baseRemap.angle: "
            "expected 0, 90, 180 or 270 (a display hangs turned by quarter turns), got 45");
}

TEST(WallImportErrors, Sage2TwoDisplaysOnOneTile) {
  EXPECT_EQ(error_of(R"({"layout": {"rows": 1, "columns": 2}, "resolution": {"width": 100,
      "height": 80}, "displays": [{"row": 0, "column": 0, "width": 2}, {"row": 0, "column": 1}]})"),
            "config.json: displays[1]: covers row 0, column 1, which displays[0] covers already");
}

}  // namespace
}  // namespace l2::import_error_tests
