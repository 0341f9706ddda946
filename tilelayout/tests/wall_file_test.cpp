#include "tilelayout/wall_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "tilelayout/planner.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

// Line numbers matter: errors below name them.
const std::string kBase =
    "name = \"t\"\n"               // 1
    "[display_grid]\n"             // 2
    "columns = 2\n"                // 3
    "rows = 1\n"                   // 4
    "width = 100\n"                // 5
    "height = 80\n"                // 6
    "mullion_x = 10\n"             // 7
    "[tiling]\n"                   // 8
    "kind = \"grid\"\n"            // 9
    "tile_width = 50\n"            // 10
    "tile_height = 40\n"           // 11
    "[pipeservers]\n"              // 12
    "count = 2\n"                  // 13
    "framebuffer_width = 300\n"    // 14
    "framebuffer_height = 200\n";  // 15

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string error_of(const std::string& text) {
  try {
    parse_wall(text, "walls/t.toml");
  } catch (const LayoutError& e) {
    return e.what();
  }
  return "no error";
}

TEST(WallFile, ReadsAGridWall) {
  const Wall w = parse_wall(kBase, "walls/t.toml");
  EXPECT_EQ(w.name, "t");
  EXPECT_EQ(w.source, "walls/t.toml");
  ASSERT_EQ(w.displays.size(), 2u);
  EXPECT_EQ(w.displays[1].id, 1);
  EXPECT_EQ(w.displays[1].on_canvas(), (Rect{110, 0, 100, 80}));
  EXPECT_EQ(w.canvas_width, 210);
  EXPECT_EQ(w.canvas_height, 80);
  EXPECT_EQ(w.tiling.kind, TilingKind::Grid);
  EXPECT_EQ(w.tiling.tile_width, 50);
  EXPECT_EQ(w.pipeserver_count, 2);
  EXPECT_EQ(w.framebuffer_width, 300);
  EXPECT_EQ(w.framebuffer_height, 200);
  EXPECT_EQ(w.framebuffer_line, 15);
  EXPECT_EQ(w.assignment, AssignmentPolicy::RoundRobin);
  EXPECT_EQ(w.board_max_width, 1280);
  EXPECT_EQ(w.board_max_height, 1024);
  EXPECT_EQ(w.refresh_hz, 60);
}

TEST(WallFile, GridWithOverlapSwapGroupsAndMesh) {
  const Wall w = parse_wall(
      replace(kBase, "mullion_x = 10\n",
              "mullion_x = -20\nmullion_y = 5\nswap_groups = [1, 2]\nmonitors = [\"a\", \"b\"]\n") +
          "assignment = \"area-balanced\"\n[mesh]\nboard_max_width = 640\nboard_max_height = "
          "480\nrefresh_hz = 30\n",
      "w.toml");
  EXPECT_EQ(w.displays[1].canvas_x, 80);
  EXPECT_EQ(w.displays[1].swap_group, 2);
  EXPECT_EQ(w.displays[0].monitor, "a");
  EXPECT_EQ(w.canvas_width, 180);
  EXPECT_EQ(w.assignment, AssignmentPolicy::AreaBalanced);
  EXPECT_EQ(w.board_max_width, 640);
  EXPECT_EQ(w.refresh_hz, 30);
}

TEST(WallFile, ExplicitDisplaysInAnyIdOrder) {
  const std::string text =
      "[[display]]\nid = 1\nwidth = 50\nheight = 40\nx = 60\ny = 0\nswap_group = 3\n"
      "[[display]]\nid = 0\nwidth = 50\nheight = 40\nx = 0\ny = 10\n"
      "[canvas]\nwidth = 200\nheight = 100\n"
      "[tiling]\nkind = \"list\"\ntiles = [[0, 0, 100, 50], [100, 0, 100, 50]]\n"
      "[pipeservers]\ncount = 1\n";
  const Wall w = parse_wall(text, "e.toml");
  ASSERT_EQ(w.displays.size(), 2u);
  EXPECT_EQ(w.displays[0].on_canvas(), (Rect{0, 10, 50, 40}));
  EXPECT_EQ(w.displays[1].swap_group, 3);
  EXPECT_EQ(w.canvas_width, 200);
  EXPECT_EQ(w.tiling.rects, (std::vector<Rect>{{0, 0, 100, 50}, {100, 0, 100, 50}}));
}

TEST(WallFile, KdAndStripsTilings) {
  Wall w = parse_wall(replace(kBase, "kind = \"grid\"\ntile_width = 50\ntile_height = 40\n",
                              "kind = \"kd\"\ntile_count = 7\ncost = [[1, 2.5], [0, 1]]\n"),
                      "k.toml");
  EXPECT_EQ(w.tiling.kind, TilingKind::KdSplit);
  EXPECT_EQ(w.tiling.tile_count, 7);
  EXPECT_EQ(w.tiling.cost, (std::vector<std::vector<double>>{{1, 2.5}, {0, 1}}));
  w = parse_wall(replace(kBase, "kind = \"grid\"\ntile_width = 50\ntile_height = 40\n",
                         "kind = \"strips\"\nstrips = 3\nsubstrips = 4\n"),
                 "s.toml");
  EXPECT_EQ(w.tiling.strip_count, 3);
  EXPECT_EQ(w.tiling.substrip_count, 4);
}

TEST(WallFile, MalformedTomlNamesTheLine) {
  const std::string e = error_of(replace(kBase, "[tiling]", "[tiling"));
  EXPECT_EQ(e.rfind("walls/t.toml:8: malformed TOML: ", 0), 0u) << e;
}

std::string repeated(const std::string& part, int times) {
  std::string out;
  for (int i = 0; i < times; ++i) out += part;
  return out;
}

// toml++ recurses once per nested table: deep keys overflowed the stack of every program that
// reads walls. They are refused before parsing, at the line that goes too deep.
TEST(WallFile, DeepNestingIsRefusedBeforeParsing) {
  const std::string deep = "walls/t.toml:16: nested more than 16 levels deep: not a wall file";
  EXPECT_EQ(error_of(kBase + "a" + repeated(".a", 50000) + " = 1\n"), deep);
  EXPECT_EQ(error_of(kBase + "[a" + repeated(".a", 50000) + "]\n"), deep);
  EXPECT_EQ(error_of(kBase + "[[a" + repeated(".a", 15) + "]]\n"), deep);
  EXPECT_EQ(error_of(kBase + "x = " + repeated("{a = ", 16) + "1" + repeated("}", 16) + "\n"),
            deep);
  EXPECT_EQ(error_of(kBase + "x = " + repeated("[", 16) + repeated("]", 16) + "\n"), deep);
  // Levels add up: a table's keys, dotted keys in inline tables, arrays of inline tables.
  EXPECT_EQ(error_of(kBase + "[a.a.a.a.a.a.a.a]\nb.b.b.b.b.b.b.b.b = 1\n"),
            "walls/t.toml:17: nested more than 16 levels deep: not a wall file");
  EXPECT_EQ(error_of(kBase + "x = {a.a.a.a.a.a.a = {b.b.b.b.b.b.b.b = 1}}\n"), deep);
  EXPECT_EQ(error_of(kBase + "x = [[{a = [[{b.b.b.b.b.b.b.b.b.b = 1}]]}]]\n"), deep);
  // The line is the one that goes too deep: after a multi-line string and a multi-line array.
  EXPECT_EQ(
      error_of(kBase + "s = \"\"\"\n[[[\n\"\"\"\nv = [\n1,\n]\n" + repeated("a.", 16) + "a = 1\n"),
      "walls/t.toml:22: nested more than 16 levels deep: not a wall file");
}

TEST(WallFile, LongKeysAreRefusedBeforeParsing) {
  EXPECT_EQ(error_of(kBase + "\"" + std::string(300, 'k') + "\" = 1\n"),
            "walls/t.toml:16: a key longer than 256 characters: not a wall file");
  EXPECT_EQ(error_of(kBase + "[" + std::string(100000, 'k') + "]\n"),
            "walls/t.toml:16: a key longer than 256 characters: not a wall file");
}

// What only looks deep is not: brackets and dots in strings and comments, floats, a table 15
// levels down. These reach the parser, which names the unknown key.
TEST(WallFile, NestingInStringsAndCommentsDoesNotCount) {
  const std::string text = replace(
      kBase, "name = \"t\"",
      "name = \"[[[[[[[[[[[[[[[[[[{{{{{{{{{{{{{{{{{ a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a\\\"\" "
      "# [[[[[[[[[[[[[[[[[[[[[[[ ''' \"\"\"");
  EXPECT_EQ(error_of(text + "x = [1.5, 2.5, 3.5, 4.5, 5.5, 6.5, 7.5, 8.5, 9.5, 0.5, 1.5, 2.5, "
                            "3.5, 4.5, 5.5, 6.5, 7.5]\n"),
            "walls/t.toml:16: pipeservers.x: unknown key (valid here: count, framebuffer_width, "
            "framebuffer_height, assignment)");
  EXPECT_EQ(error_of(text + "[a" + repeated(".a", 14) + "]\nb = 1\n"),
            "walls/t.toml:16: a: unknown key (valid here: name, canvas, display_grid, display, "
            "displays, tiling, pipeservers, mesh, depth, overlay, balance, blend, stereo)");
  EXPECT_EQ(error_of(text + "x = '[[[[[[[[[[[[[[[[[[[[' # ]\n"),
            "walls/t.toml:16: pipeservers.x: unknown key (valid here: count, framebuffer_width, "
            "framebuffer_height, assignment)");
}

TEST(WallFile, MalformedTomlQuotingTheFileIsOneEscapedLine) {
  // The TOML parser quotes what it saw: a line break or an escape sequence of the file went
  // into the message raw (found by fuzz/fuzz_wall_file).
  EXPECT_EQ(error_of("name = f\n"),
            "walls/t.toml:1: malformed TOML: Error while parsing boolean: expected 'false', saw "
            "'f\\n'");
  EXPECT_EQ(error_of("name = t\x1b[2J"),
            "walls/t.toml:1: malformed TOML: Error while parsing boolean: expected 'true', saw "
            "'t\\x1b'");
}

TEST(WallFile, UnknownKeysAreErrors) {
  EXPECT_EQ(error_of(replace(kBase, "tile_height = 40\n", "tile_height = 40\ntile_widht = 5\n")),
            "walls/t.toml:12: tiling.tile_widht: unknown key: did you mean tile_width? (valid "
            "here: kind, tile_width, tile_height, tiles, tile_count, cost, strips, substrips)");
  EXPECT_EQ(error_of("colour = 1\n" + kBase),
            "walls/t.toml:1: colour: unknown key (valid here: name, canvas, display_grid, display, "
            "displays, tiling, pipeservers, mesh, depth, overlay, balance, blend, stereo)");
  EXPECT_EQ(error_of(replace(kBase, "count = 2\n", "count = 2\nfb_width = 3\n")),
            "walls/t.toml:14: pipeservers.fb_width: unknown key (valid here: count, "
            "framebuffer_width, framebuffer_height, assignment)");
  EXPECT_EQ(error_of(replace(kBase, "tile_height = 40\n", "tile_height = 40\ntile_count = 5\n")),
            "walls/t.toml:12: tiling.tile_count: belongs to kind \"kd\", not \"grid\"");
}

TEST(WallFile, FieldRangesAndTypes) {
  EXPECT_EQ(error_of(replace(kBase, "tile_width = 50", "tile_width = 0")),
            "walls/t.toml:10: tiling.tile_width: must be 1..4095, got 0");
  // 300 pipeservers planned here, and every run refused them: the mesh has 256 inputs at most.
  EXPECT_EQ(error_of(replace(kBase, "count = 2\n", "count = 300\n")),
            "walls/t.toml:13: pipeservers.count: 300 is more than the 256 inputs of a mesh");
  EXPECT_EQ(error_of(replace(kBase, "width = 100", "width = 4096")),
            "walls/t.toml:5: display_grid.width: must be 1..4095, got 4096");
  EXPECT_EQ(error_of(replace(kBase, "tile_width = 50", "tile_width = \"50\"")),
            "walls/t.toml:10: tiling.tile_width: must be an integer, got a string");
  EXPECT_EQ(error_of(replace(kBase, "mullion_x = 10", "mullion_x = -100")),
            "walls/t.toml:7: display_grid.mullion_x: must be -99..4095, got -100");
  EXPECT_EQ(error_of(replace(kBase, "kind = \"grid\"", "kind = \"hex\"")),
            "walls/t.toml:9: tiling.kind: must be one of grid, list, kd, strips, got \"hex\"");
  EXPECT_EQ(error_of(replace(kBase, "tile_height = 40\n", "")),
            "walls/t.toml:8: tiling.tile_height: missing (required)");
  EXPECT_EQ(error_of(replace(kBase, "count = 2\n", "count = 2\nassignment = \"random\"\n")),
            "walls/t.toml:14: pipeservers.assignment: must be one of round-robin, zig-zag, "
            "spiral, blocks, area-balanced, got \"random\"");
}

// Ids beyond 63 are the displays of further meshes (several_meshes_test.cpp), up to the wall's
// limit.
TEST(WallFile, DisplayIdsBeyondTheWallsLimit) {
  EXPECT_EQ(
      error_of(replace(replace(kBase, "columns = 2", "columns = 33"), "rows = 1", "rows = 32")),
      "walls/t.toml:4: display_grid.rows: 33x32 displays are more than the 1024 of 16 "
      "meshes");
  const std::string list =
      "[[display]]\nid = 1024\nwidth = 50\nheight = 40\nx = 0\ny = 0\n"
      "[tiling]\nkind = \"grid\"\ntile_width = 10\ntile_height = 10\n[pipeservers]\ncount = 1\n";
  EXPECT_EQ(error_of(list), "walls/t.toml:2: display[0].id: must be 0..1023, got 1024");
  EXPECT_EQ(error_of(replace(list, "id = 1024", "id = 1")),
            "walls/t.toml:1: display: ids must run 0..0 without gaps; id 0 is missing");
}

TEST(WallFile, ListTilesOutsideTheCanvasOrOverlapping) {
  const std::string list = replace(kBase, "kind = \"grid\"\ntile_width = 50\ntile_height = 40\n",
                                   "kind = \"list\"\ntiles = [\n  [0, 0, 100, 80],\n  TILE,\n]\n");
  EXPECT_EQ(error_of(replace(list, "TILE", "[150, 0, 100, 10]")),
            "walls/t.toml:12: tiling.tiles[1]: tile 100x10 at 150,0 lies outside the 210x80 "
            "canvas");
  EXPECT_EQ(error_of(replace(list, "TILE", "[90, 70, 20, 20]")),
            "walls/t.toml:12: tiling.tiles[1]: tile 20x20 at 90,70 lies outside the 210x80 "
            "canvas");
  EXPECT_EQ(error_of(replace(list, "TILE", "[90, 60, 20, 20]")),
            "walls/t.toml:12: tiling.tiles[1]: tile 20x20 at 90,60 overlaps tiles[0] (100x80 at "
            "0,0) in 10x20 at 90,60");
  EXPECT_EQ(error_of(replace(list, "TILE", "[90, 60, 0, 20]")),
            "walls/t.toml:12: tiling.tiles[1].width: must be 1..4095, got 0");
  EXPECT_EQ(error_of(replace(list, "TILE", "[90, 60, 20]")),
            "walls/t.toml:12: tiling.tiles[1]: must be [x, y, width, height]");
}

TEST(WallFile, FramebufferAboveTheBoardLimit) {
  EXPECT_EQ(error_of(replace(kBase, "framebuffer_width = 300", "framebuffer_width = 2048")),
            "walls/t.toml:14: pipeservers.framebuffer_width: 2048 is more than the board input "
            "limit 1280 (raise mesh.board_max_width)");
  EXPECT_EQ(error_of(kBase + "[mesh]\nboard_max_height = 100\n"),
            "walls/t.toml:15: pipeservers.framebuffer_height: 200 is more than the board input "
            "limit 100 (raise mesh.board_max_height)");
}

TEST(WallFile, MissingSectionsAndOtherShapes) {
  EXPECT_EQ(error_of("[tiling]\nkind = \"grid\"\n"),
            "walls/t.toml: display_grid: the wall has no displays ([display_grid] or [[display]])");
  EXPECT_EQ(error_of("[display]\nwidth = 5\n"),
            "walls/t.toml:1: display: must be [[display]] entries (an array of tables), got a "
            "table");
  EXPECT_EQ(error_of(kBase.substr(0, kBase.find("[tiling]"))),
            "walls/t.toml: tiling: missing (required)");
  EXPECT_EQ(
      error_of(replace(kBase, "[tiling]\n", "[canvas]\nwidth = 200\nheight = 80\n[tiling]\n")),
      "walls/t.toml:9: canvas.width: display 1 (100x80 at 110,0) extends past the 200x80 "
      "canvas");
  const std::string kd = replace(kBase, "kind = \"grid\"\ntile_width = 50\ntile_height = 40\n",
                                 "kind = \"kd\"\ntile_count = 4\ncost = [[1, 2], [3]]\n");
  EXPECT_EQ(error_of(kd),
            "walls/t.toml:11: tiling.cost[1]: has 1 numbers, but tiling.cost[0] has 2");
  EXPECT_EQ(error_of(replace(kd, "[[1, 2], [3]]", "[[0, 0]]")),
            "walls/t.toml:11: tiling.cost: needs at least one cell above 0");
}

// Canvas (2 x 4095 + 10) x 4095 in 1x1 tiles: 8200 x 4095 = 33579000.
TEST(WallFile, TooManyTiles) {
  const std::string big =
      replace(replace(kBase, "width = 100", "width = 4095"), "height = 80", "height = 4095");
  EXPECT_EQ(error_of(replace(replace(big, "tile_width = 50", "tile_width = 1"), "tile_height = 40",
                             "tile_height = 1")),
            "walls/t.toml:10: tiling.tile_width: makes 33579000 tiles, more than 65536");
}

// Whatever the bytes, loading and planning end in a Wall or a one-line LayoutError: no other
// exception, no crash (the ASan run watches for out-of-bounds access).
TEST(WallFile, MutatedFilesFailCleanly) {
  std::mt19937 rng(12345);
  const std::string alphabet = "0123456789-=[]\",.\n #abkxyz";
  int errors = 0;
  for (int i = 0; i < 3000; ++i) {
    std::string text = kBase;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 3) {
        case 0:
          text[at] = alphabet[rng() % alphabet.size()];
          break;
        case 1:
          text.erase(at, 1 + rng() % 3);
          break;
        default:
          text.insert(at, 1, alphabet[rng() % alphabet.size()]);
          break;
      }
    }
    try {
      plan_layout(parse_wall(text, "m.toml"));
    } catch (const LayoutError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("m.toml", 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      ++errors;
    }
  }
  EXPECT_GT(errors, 1000);  // most mutations break the file
}

TEST(WallFile, LoadWallNamesAFileItCannotRead) {
  try {
    load_wall("/nonexistent/wall.toml");
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_EQ(std::string(e.what()),
              "/nonexistent/wall.toml: cannot read: No such file or directory");
  }
}

// A directory opens as a stream on Linux and reads as nothing: it was reported as a wall without
// displays.
TEST(WallFile, LoadWallNamesADirectory) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "l2_wall_dir.toml";
  std::filesystem::create_directories(dir);
  try {
    load_wall(dir);
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_EQ(std::string(e.what()), dir.string() + ": cannot read: Is a directory");
  }
  std::filesystem::remove(dir);
}

TEST(WallFile, LoadWallStopsReadingAtSixteenMegabytes) {
  // `tilelayout /dev/zero` read until it held 3.7 GB, and on.
  try {
    load_wall("/dev/zero");
    FAIL();
  } catch (const LayoutError& e) {
    EXPECT_EQ(std::string(e.what()), "/dev/zero: more than 16 MiB: not a wall file");
  }
}

TEST(WallFile, DefaultWallIsTheFileInWalls) {
  std::ifstream in(std::string(L2_WALLS_DIR) + "/kd-2x2.toml");
  std::ostringstream text;
  text << in.rdbuf();
  ASSERT_FALSE(text.str().empty());
  EXPECT_EQ(default_wall_toml(), text.str());
  const Wall w = default_wall();
  EXPECT_EQ(w.displays.size(), 4u);
  EXPECT_EQ(w.tiling.kind, TilingKind::KdSplit);
  EXPECT_EQ(w.pipeserver_count, 4);
}

}  // namespace
}  // namespace l2

namespace l2 {
namespace {

TEST(WallFile, BalanceSection) {
  EXPECT_EQ(parse_wall(kBase, "t.toml").balance.mode, BalanceMode::Static);
  const Wall w = parse_wall(
      kBase + "[balance]\nmode = \"strips\"\nassignment = \"heaviest-first\"\n", "t.toml");
  EXPECT_EQ(w.balance.mode, BalanceMode::Strips);
  EXPECT_TRUE(w.balance.heaviest_first);
  EXPECT_EQ(w.balance.line, 16);
  EXPECT_EQ(parse_wall(kBase + "[balance]\nmode = \"kd\"\n", "t.toml").balance.mode,
            BalanceMode::Kd);
  EXPECT_FALSE(parse_wall(kBase + "[balance]\nmode = \"kd\"\n", "t.toml").balance.heaviest_first);
  EXPECT_FALSE(w.balance.survive_host_loss);
  EXPECT_TRUE(parse_wall(kBase + "[balance]\nmode = \"kd\"\nsurvive_host_loss = true\n", "t.toml")
                  .balance.survive_host_loss);
  EXPECT_EQ(w.balance.resistance, 0);
  EXPECT_EQ(w.balance.tile_cost, 0);
  const Wall r = parse_wall(
      kBase + "[balance]\nmode = \"strips\"\nresistance = 0.1\ntile_cost = 0.15\n", "t.toml");
  EXPECT_DOUBLE_EQ(r.balance.resistance, 0.1);
  EXPECT_DOUBLE_EQ(r.balance.tile_cost, 0.15);
  EXPECT_EQ(
      parse_wall(kBase + "[balance]\nmode = \"kd\"\nresistance = 0\n", "t.toml").balance.resistance,
      0);
}

TEST(WallFile, BalanceErrorsNameTheLineAndField) {
  EXPECT_EQ(error_of(kBase + "[balance]\nmode = \"dynamic\"\n"),
            "walls/t.toml:17: balance.mode: must be one of static, strips, kd, got \"dynamic\"");
  EXPECT_EQ(error_of(kBase + "[balance]\nmode = 1\n"),
            "walls/t.toml:17: balance.mode: must be a string, got an integer");
  EXPECT_EQ(error_of(kBase + "[balance]\nassignment = \"fastest\"\n"),
            "walls/t.toml:17: balance.assignment: must be one of policy, heaviest-first, got "
            "\"fastest\"");
  EXPECT_EQ(error_of(kBase + "[balance]\nmode = \"kd\"\nsurvive_host_loss = \"yes\"\n"),
            "walls/t.toml:18: balance.survive_host_loss: must be true or false, got a string");
  EXPECT_EQ(error_of(kBase + "[balance]\nsurvive_host_loss = true\n"),
            "walls/t.toml:17: balance.survive_host_loss: needs balancing: mode = \"strips\" or "
            "\"kd\", or assignment = \"heaviest-first\"");
  EXPECT_EQ(error_of(kBase + "[balance]\nmode = \"kd\"\nresistance = 1\n"),
            "walls/t.toml:18: balance.resistance: must be a number from 0 up to below 1, got 1");
  EXPECT_EQ(error_of(kBase + "[balance]\nmode = \"kd\"\nresistance = -0.5\n"),
            "walls/t.toml:18: balance.resistance: must be a number from 0 up to below 1, got "
            "-0.5");
  EXPECT_EQ(error_of(kBase + "[balance]\nmode = \"kd\"\nresistance = \"10%\"\n"),
            "walls/t.toml:18: balance.resistance: must be a number, got a string");
  EXPECT_EQ(error_of(kBase + "[balance]\nmode = \"kd\"\ntile_cost = 1.5\n"),
            "walls/t.toml:18: balance.tile_cost: must be a number from 0 up to below 1, got 1.5");
  EXPECT_EQ(error_of(kBase + "[balance]\nmodes = \"kd\"\n"),
            "walls/t.toml:17: balance.modes: unknown key: did you mean mode? (valid here: mode, "
            "assignment, survive_host_loss, resistance, tile_cost)");
  EXPECT_EQ(error_of(kBase + "[depth]\nlayers = 2\n[balance]\nmode = \"strips\"\n"),
            "walls/t.toml:19: balance.mode: cannot balance a wall with [depth]: its tiles are "
            "shared by layer, not by render time");
}

}  // namespace
}  // namespace l2
