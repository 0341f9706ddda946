// The real tilelayout executable, run as a child process: exit status, the one-line errors for
// broken walls, and the files --png and --scanout write.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_run.hpp"
#include "image/png_io.hpp"
#include "routing_check.hpp"
#include "tilelayout/pictures.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using cli_testing::ChildRun;
using cli_testing::Cli;
using cli_testing::slurp;

const std::string kGood =
    "[display_grid]\ncolumns = 2\nrows = 1\nwidth = 100\nheight = 80\nmullion_x = 10\n"
    "[tiling]\nkind = \"grid\"\ntile_width = 50\ntile_height = 40\n"
    "[pipeservers]\ncount = 2\nframebuffer_width = 300\nframebuffer_height = 200\n";

std::string replaced(const std::string& from, const std::string& to) {
  std::string t = kGood;
  t.replace(t.find(from), from.size(), to);
  return t;
}

TEST_F(Cli, PrintsThePlan) {
  const ChildRun r = run("--wall '" + write("good.toml", kGood).string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("pipeserver 0: 5 tiles in 1 row, 40 of 200 rows used, framebuffer use "
                       "13.3%"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("display 1: 100x80 at canvas 110,0, swap group 0: 100.0% covered "
                       "(8000 of 8000 pixels)"),
            std::string::npos)
      << r.out;
}

TEST_F(Cli, ReportsThePixelClockOfEachPipeserversDviLink) {
  const ChildRun r = run(std::string("--wall '") + L2_WALLS_DIR + "/monitors-4x3.toml'");
  EXPECT_EQ(r.status, 0) << r.err;
  // 1328x1560 at 60 Hz with CVT reduced blanking: 1328 + 160 pixels a line; 460 us are 45 lines
  // of 10.39 us; 60 x 1605 x 1488 = 143.29 MHz, rounded down to a multiple of 0.25 MHz.
  const std::string link =
      "rows used, framebuffer use 94.8%\n"
      "  DVI link: 1328x1560 at 60 Hz needs a 143.25 MHz pixel clock (CVT reduced blanking, "
      "1488x1605 with blanking): single link\n";
  EXPECT_NE(r.out.find("pipeserver 3: 6 tiles in 3 rows, 1556 of 1560 " + link), std::string::npos)
      << r.out;
  int links = 0;  // one per pipeserver
  for (auto at = r.out.find("  DVI link: "); at != std::string::npos;
       at = r.out.find("  DVI link: ", at + 1)) {
    ++links;
  }
  EXPECT_EQ(links, 8) << r.out;
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;
}

// A wall of nine 160x120 displays tiled 80x60 (four tiles each, a 2-column header gap before
// every strip), two 480x360 pipeservers, two board columns (displays 0-7 and 8).
TEST_F(Cli, ReportsTheNetworkEachBoardColumnNeeds) {
  const fs::path wall = write("two-columns.toml", R"(name = "3x3"
[display_grid]
columns = 3
rows = 3
width = 160
height = 120
[tiling]
kind = "grid"
tile_width = 80
tile_height = 60
[pipeservers]
count = 2
framebuffer_width = 480
framebuffer_height = 360
)");
  const ChildRun r = run("--wall '" + wall.string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  // Both inputs feed both columns: 2 x 480 x 360 x 3 = 1.04 MB, x 8 bits x 60 Hz = 0.50 Gbit/s.
  // Own strips: 4 tiles a display of (2 + 80) x 60 x 3 = 14760 bytes; column 0 has 8 displays
  // (0.47 MB, 0.23 Gbit/s), column 1 one (0.06 MB, 0.03 Gbit/s).
  EXPECT_NE(r.out.find("\n  board column 0 (displays 0,1,2,3,4,5,6,7): 2 inputs, 1.04 MB a frame "
                       "as scanned out (0.50 Gbit/s); its own strips 0.47 MB (0.23 Gbit/s), the "
                       "most that changes\n"
                       "  board column 1 (displays 8): 2 inputs, 1.04 MB a frame as scanned out "
                       "(0.50 Gbit/s); its own strips 0.06 MB (0.03 Gbit/s), the most that "
                       "changes\n"),
            std::string::npos)
      << r.out;
}

TEST_F(Cli, WarnsWhenAFramebufferNeedsMoreThanASingleDviLink) {
  const auto wall = [&](const std::string& name, int width, int height) {
    return write(name, replaced("framebuffer_width = 300\nframebuffer_height = 200",
                                fmt::format("framebuffer_width = {}\nframebuffer_height = {}",
                                            width, height)) +
                           "[mesh]\nboard_max_width = 4096\nboard_max_height = 4096\n");
  };
  // 2048x1536 at 60 Hz: 2208 pixels a line, 1536 + 44 lines, 209.32 MHz rounded down.
  const auto big = wall("big.toml", 2048, 1536);
  ChildRun r = run("--wall '" + big.string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("  DVI link: 2048x1536 at 60 Hz needs a 209.25 MHz pixel clock (CVT "
                       "reduced blanking, 2208x1580 with blanking): dual link\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find(big.string() +
                       ":14: warning: framebuffers of 2048x1536 at 60 Hz need a 209.25 MHz pixel "
                       "clock (CVT reduced blanking), more than single-link DVI carries (165 "
                       "MHz): a dual link carries it (330 MHz)\n"),
            std::string::npos)
      << r.out;
  // 3200x2400: 3360 pixels a line, 2400 + 69 lines, 497.75 MHz.
  const auto huge = wall("huge.toml", 3200, 2400);
  r = run("--wall '" + huge.string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find(huge.string() +
                       ":14: warning: framebuffers of 3200x2400 at 60 Hz need a 497.75 MHz pixel "
                       "clock (CVT reduced blanking), more than single-link DVI carries (165 "
                       "MHz): more than a dual link too (330 MHz)\n"),
            std::string::npos)
      << r.out;
}

// A wall's name and keys are the file's text: control characters in them (escape sequences
// that clear the screen or retitle the terminal) reached the terminal as they were.
TEST_F(Cli, ControlCharactersFromTheWallFileArePrintedAsEscapes) {
  ChildRun r = run(
      "--wall '" +
      write("named.toml", "name = \"\\u001b[2J\\u001b]0;owned\\u0007 wall\"\n" + kGood).string() +
      "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("wall \"\\x1b[2J\\x1b]0;owned\\x07 wall\" (", 0), 0u) << r.out;
  EXPECT_EQ(r.out.find('\x1b'), std::string::npos);
  const fs::path keyed = write("keyed.toml", "\"\\u001b[31mred\" = 1\n" + kGood);
  r = run("--wall '" + keyed.string() + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err,
            "tilelayout: " + keyed.string() +
                ":1: \\x1b[31mred: unknown key (valid here: name, canvas, display_grid, "
                "display, displays, tiling, pipeservers, mesh, depth, overlay, balance, blend, "
                "stereo)\n");
}

TEST_F(Cli, BrokenWallsGiveOneLineAndExitOne) {
  struct Case {
    std::string text, error;
  };
  const std::vector<Case> cases = {
      {replaced("[tiling]", "[tiling"), ":7: malformed TOML: "},
      {replaced("tile_height = 40\n", "tile_height = 40\ntile_hieght = 4\n"),
       ":11: tiling.tile_hieght: unknown key: did you mean tile_height?"},
      {replaced("columns = 2", "columns = 1025"),
       ":2: display_grid.columns: must be 1..1024, got 1025"},
      {replaced("width = 100", "width = 5000"),
       ":4: display_grid.width: must be 1..4095, got 5000"},
      {replaced("kind = \"grid\"\ntile_width = 50\ntile_height = 40",
                "kind = \"list\"\ntiles = [[0, 0, 100, 80], [200, 0, 20, 80]]"),
       ":9: tiling.tiles[1]: tile 20x80 at 200,0 lies outside the 210x80 canvas"},
      {replaced("kind = \"grid\"\ntile_width = 50\ntile_height = 40",
                "kind = \"list\"\ntiles = [[0, 0, 100, 80], [50, 0, 100, 80]]"),
       ":9: tiling.tiles[1]: tile 100x80 at 50,0 overlaps tiles[0] (100x80 at 0,0) in 50x80 "
       "at 50,0"},
      // Tiles 0, 2, 4 fill row 0 (52 + 42 + 12 columns); tile 6, fourth in the list, opens a
      // second row that ends at 80.
      {replaced("framebuffer_width = 300\nframebuffer_height = 200",
                "framebuffer_width = 150\nframebuffer_height = 60"),
       ":14: pipeserver 0: tile 3 (display 0, 50x40 at 50,40) does not fit the 150x60 "
       "framebuffer: needs 80 rows, 20 too many"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const fs::path wall = write("bad" + std::to_string(i) + ".toml", cases[i].text);
    const ChildRun r = run("--wall '" + wall.string() + "'");
    EXPECT_EQ(r.status, 1) << i;
    EXPECT_EQ(r.out, "") << i;
    const std::string prefix = "tilelayout: " + wall.string() + cases[i].error;
    EXPECT_EQ(r.err.rfind(prefix, 0), 0u) << i << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << i << ": " << r.err;
  }
}

// The issue's reproducer, python3 -c 'print("a"+".a"*50000+" = 1")': the stack overflow inside
// the TOML parser ended the program with SIGSEGV and no message.
TEST_F(Cli, DeeplyNestedKeysAreAOneLineError) {
  std::string text = "a";
  for (int i = 0; i < 50000; ++i) text += ".a";
  const fs::path wall = write("deep.toml", text + " = 1\n");
  const ChildRun r = run("--wall '" + wall.string() + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "tilelayout: " + wall.string() +
                       ":1: nested more than 16 levels deep: not a wall file\n");
}

TEST_F(Cli, UncoveredCanvasIsAWarningNotAnError) {
  const fs::path wall = write(
      "holes.toml", replaced("kind = \"grid\"\ntile_width = 50\ntile_height = 40",
                             "kind = \"list\"\ntiles = [[0, 0, 100, 80], [110, 0, 100, 40]]"));
  const ChildRun r = run("--wall '" + wall.string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find(wall.string() + ": warning: canvas area 100x40 at 110,40 (display 1: "
                                       "4000 pixels) is not covered by any tile"),
            std::string::npos)
      << r.out;
}

TEST_F(Cli, MissingFileAndBadOptions) {
  ChildRun r = run("--wall '" + (dir_ / "none.toml").string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "tilelayout: --wall: File does not exist: " + (dir_ / "none.toml").string() +
                       "\nRun with --help for more information.\n");
  r = run("--parity 2");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--parity"), std::string::npos) << r.err;
  r = run("a.toml b.toml");
  EXPECT_EQ(r.status, 2);
}

TEST_F(Cli, HelpAndDefault) {
  ChildRun r = run("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--scanout"), std::string::npos);
  r = run("--print-default");
  EXPECT_EQ(r.out, std::string(default_wall_toml()));
  r = run("");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out.rfind("wall \"2x2 k-d wall\"", 0), 0u) << r.out;
}

TEST_F(Cli, PlanEndsWithTheLossesTheWallSurvives) {
  // Survival.DefaultWall (survival_test.cpp) has the numbers from the planner's packing.
  ChildRun r = run("");
  EXPECT_EQ(r.status, 0) << r.err;
  const std::string last =
      "survives the loss of no pipeserver (framebuffers 800x600); 1: needs "
      "framebuffer_height >= 910\n";
  ASSERT_GE(r.out.size(), last.size());
  EXPECT_EQ(r.out.substr(r.out.size() - last.size()), last) << r.out;
  // The suggested height, written into the wall, survives the loss and names the next.
  const fs::path wall = write("roomier.toml", std::string(default_wall_toml()));
  std::string text = slurp(wall);
  text.replace(text.find("framebuffer_height = 600"), 24, "framebuffer_height = 910");
  write("roomier.toml", text);
  r = run("--wall '" + wall.string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\nsurvives the loss of 1 pipeserver (framebuffers 800x910); 2: needs "
                       "framebuffer_height >= 1440 with [mesh] board_max_height = 1440\n"),
            std::string::npos)
      << r.out;
  r = run("--suggest");
  EXPECT_NE(r.out.find("\nframebuffer_height = 910 (at framebuffer_width = 800): survives the "
                       "loss of 1 pipeserver\nframebuffer_height = 1440 (at framebuffer_width = "
                       "800, and [mesh] board_max_height = 1440): survives the loss of 2 "
                       "pipeservers\nframebuffer_width = 1280, framebuffer_height = 769: survives "
                       "the loss of 2 pipeservers within the boards' 1280x1024\n"),
            std::string::npos)
      << r.out;
}

std::vector<fs::path> example_walls() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(L2_WALLS_DIR)) {
    if (e.path().extension() != ".toml") continue;
    // Walls of several meshes have tests of their own (several_meshes_test.cpp).
    if (load_wall(e.path()).mesh_count == 1) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// `page` begins with `picture`: its top-left corner holds it pixel for pixel (the legend is
// below, and may make the page wider).
void expect_on_top(const RgbImage& page, const RgbImage& picture, const std::string& what) {
  ASSERT_GE(page.width(), picture.width()) << what;
  ASSERT_GE(page.height(), picture.height()) << what;
  for (int y = 0; y < picture.height(); ++y) {
    ASSERT_TRUE(std::equal(picture.row(y).begin(), picture.row(y).end(), page.row(y).begin()))
        << what << ": row " << y;
  }
}

// One test per example wall, so CTest can run them side by side.
class CliWall : public Cli, public ::testing::WithParamInterface<fs::path> {};

// The --scanout frames of the wall, read back from the PNG files the executable wrote, route
// every visible display pixel exactly once. --png writes its pictures too.
TEST_P(CliWall, ScanoutFramesRouteEveryDisplayPixelOnce) {
  const fs::path& path = GetParam();
  const ChildRun r = run("--wall '" + path.string() + "' --parity 1 --scanout '" +
                         (dir_ / "scan").string() + "' --png '" + (dir_ / "png").string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const Wall wall = load_wall(path);
  const TileLayout layout = plan_layout(wall);
  std::vector<RgbImage> frames;
  for (int s = 0; s < wall.pipeserver_count; ++s) {
    frames.push_back(read_png(dir_ / "scan" / ("scanout-" + std::to_string(s) + ".png")));
    EXPECT_EQ(frames.back().width(), wall.framebuffer_width);
    EXPECT_EQ(frames.back().height(), wall.framebuffer_height);
    const RgbImage pic = read_png(dir_ / "png" / ("pipeserver-" + std::to_string(s) + ".png"));
    EXPECT_GE(pic.width(), wall.framebuffer_width);
    EXPECT_GT(pic.height(), wall.framebuffer_height);  // the legend below
    expect_on_top(pic, framebuffer_picture(layout.pipeservers[s]),
                  "pipeserver " + std::to_string(s));
  }
  const RgbImage wall_png = read_png(dir_ / "png" / "wall.png");
  // Canvases longer than 4096 pixels are drawn shrunk by a whole factor.
  const int scale = (std::max(wall.canvas_width, wall.canvas_height) + 4095) / 4096;
  const RgbImage wall_pic = wall_picture(layout);
  EXPECT_EQ(wall_pic.width(), (wall.canvas_width + scale - 1) / scale);
  EXPECT_EQ(wall_pic.height(), (wall.canvas_height + scale - 1) / scale);
  EXPECT_GT(wall_png.height(), wall_pic.height());  // the legend below
  expect_on_top(wall_png, wall_pic, "wall.png");
  const RoutingCheck c = check_routing(wall, frames, true);
  EXPECT_EQ(c.errors.total(), 0u);
  EXPECT_EQ(c.wrong_parity, 0);
  if (wall.depth_layers != 0 || wall.overlay) {
    // A picture per depth layer; the composite itself is the verifier's to check (it
    // composites, this copy does not): verify_tests route every example wall and check it.
    for (int layer = 0; layer < wall_layers(layout); ++layer) {
      const std::string name = "wall-layer-" + std::to_string(layer) + ".png";
      expect_on_top(read_png(dir_ / "png" / name), wall_picture(layout, layer), name);
    }
    return;
  }
  long long visible = 0;
  for (const Display& d : wall.displays) visible += 1LL * d.width * d.height;
  EXPECT_EQ(c.copied, visible);
  EXPECT_EQ(c.wrong_colour + c.wrong_parity + c.outside, 0);
  EXPECT_EQ(c.uncovered, 0);
  EXPECT_EQ(c.covered_twice, 0);
}

INSTANTIATE_TEST_SUITE_P(ExampleWalls, CliWall, ::testing::ValuesIn(example_walls()),
                         [](const auto& wall_info) {
                           std::string name = wall_info.param.stem().string();
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace l2

namespace l2 {
namespace {

// The wall of Planner.TilesThatDoNotFitSayWhatWould (planner_test.cpp, where the values are
// worked out): --suggest prints them, the plain run names them after its error.
constexpr const char* kTightWallFile = R"([display_grid]
columns = 1
rows = 1
width = 600
height = 100
[tiling]
kind = "list"
tiles = [[0, 0, 200, 100], [200, 0, 100, 100], [300, 0, 200, 100], [500, 0, 100, 100]]
[pipeservers]
count = 2
framebuffer_width = 310
framebuffer_height = 100
)";

TEST_F(Cli, SuggestPrintsWhatFits) {
  const fs::path wall = write("tight.toml", kTightWallFile);
  ChildRun r = run("--suggest --wall '" + wall.string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out,
            "as written (310x100, 2 pipeservers, round-robin): does not fit\n"
            "framebuffer_height = 200 (at framebuffer_width = 310)\n"
            "framebuffer_width = 404 (at framebuffer_height = 100)\n"
            "framebuffer_width = 202, framebuffer_height = 200: the smallest framebuffer\n"
            "assignment = \"blocks\" (at 310x100, 2 pipeservers)\n"
            "assignment = \"area-balanced\" (at 310x100, 2 pipeservers)\n"
            "pipeservers.count = 3 (at 310x100, round-robin): the fewest that fit\n"
            "framebuffer_height = 200 (at framebuffer_width = 310): survives the loss of 1 "
            "pipeserver\n");
  r = run("--wall '" + wall.string() + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "tilelayout: " + wall.string() +
                       ":12: pipeserver 0: tile 1 (display 0, 200x100 at 300,0) does not fit the "
                       "310x100 framebuffer: needs 200 rows, 100 too many; what would fit, each "
                       "alone: assignment = \"blocks\" or \"area-balanced\"; framebuffer_width = "
                       "404; pipeservers.count = 3; framebuffer_height = 200\n");
  // A suggested value, written into the wall, plans.
  const fs::path fixed =
      write("fixed.toml", std::string(kTightWallFile) + "assignment = \"blocks\"\n");
  EXPECT_EQ(run("--wall '" + fixed.string() + "'").status, 0);
}

TEST_F(Cli, SuggestOnAWallThatFitsPrintsTheSmallestFramebuffer) {
  // One 100x50 tile on one 200x60 framebuffer: 102 columns and 50 rows would do.
  const fs::path wall = write("roomy.toml",
                              "[display_grid]\ncolumns = 1\nrows = 1\nwidth = 100\nheight = 50\n"
                              "[tiling]\nkind = \"grid\"\ntile_width = 100\ntile_height = 50\n"
                              "[pipeservers]\ncount = 1\nframebuffer_width = 200\n"
                              "framebuffer_height = 60\n");
  const ChildRun r = run("--suggest --wall '" + wall.string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out,
            "as written (200x60, 1 pipeserver, round-robin): fits\n"
            "framebuffer_height = 50 (at framebuffer_width = 200)\n"
            "framebuffer_width = 102 (at framebuffer_height = 60)\n"
            "framebuffer_width = 102, framebuffer_height = 50: the smallest framebuffer\n"
            "assignment = \"zig-zag\" (at 200x60, 1 pipeserver)\n"
            "assignment = \"spiral\" (at 200x60, 1 pipeserver)\n"
            "assignment = \"blocks\" (at 200x60, 1 pipeserver)\n"
            "assignment = \"area-balanced\" (at 200x60, 1 pipeserver)\n"
            "pipeservers.count = 1 (at 200x60, round-robin): the fewest that fit\n"
            "survives the loss of no pipeserver: its one pipeserver has nobody to take its "
            "tiles\n");
}

}  // namespace
}  // namespace l2

namespace l2 {
namespace {

// tilelayout import: the wall file it writes is one tilelayout --wall plans, the hostfile has the
// hosts the configuration names, a bad configuration is one line and exit 1.
TEST_F(Cli, ImportWritesAWallFileThatPlansAndAHostfile) {
  const std::string input = std::string(L2_IMPORTED_DIR) + "/tide-bbp-4x3.json";
  const fs::path wall = dir_ / "imported.toml", hosts = dir_ / "hosts";
  ChildRun r = run("import '" + input + "' --write '" + wall.string() + "' --hostfile '" +
                   hosts.string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out,
            "wrote " + wall.string() + "\nwrote " + hosts.string() + " (mpirun --hostfile)\n");
  const std::string hostfile = slurp(hosts);
  EXPECT_EQ(hostfile.substr(hostfile.rfind(".\n") + 2),
            "bbplxviz03i slots=4\nbbplxviz04i slots=5\n");
  r = run("--wall '" + wall.string() + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("wall \"TestWall\"", 0), 0u) << r.out;
}

TEST_F(Cli, ImportPrintsTheWallAndItsNotesApart) {
  const std::string input = std::string(L2_IMPORTED_DIR) + "/ndisplay-3-nodes.ndisplay";
  const ChildRun r = run("import '" + input + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(parse_wall(r.out, "stdout.toml").displays.size(), 3u);
  // Four notes (remap, rotation, projection policy, camera) on stderr, one line each.
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 4) << r.err;
  EXPECT_EQ(r.err.rfind("note: node node_center: output remap from file", 0), 0u) << r.err;
}

TEST_F(Cli, ImportRefusals) {
  const fs::path bad = write("config.json", R"({"surfaces": [{"screenCountX": "two"}]})");
  ChildRun r = run("import '" + bad.string() + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "tilelayout import: " + bad.string() +
                       ": surfaces[0].screenCountX: expected a positive integer, got \"two\"\n");
  EXPECT_EQ(r.out, "");
  // SAGE2 files name no render hosts: no hostfile to write.
  const std::string sage2 = std::string(L2_IMPORTED_DIR) + "/sage2-3x2-cfg.json";
  r = run("import '" + sage2 + "' --hostfile '" + (dir_ / "h").string() + "'");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err,
            "tilelayout import: " + sage2 + ": names no hosts, so there is no hostfile to write\n");
  EXPECT_FALSE(fs::exists(dir_ / "h"));
  // Usage errors: a format it does not know, tilelayout's own options with import.
  EXPECT_EQ(run("import '" + sage2 + "' --format xml").status, 2);
  r = run("--png '" + dir_.string() + "' import '" + sage2 + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("import does not take --png"), std::string::npos) << r.err;
  // An output that cannot be written: exit 3, the path and the system's reason.
  const fs::path plain = write("plain", "x");
  r = run("import '" + sage2 + "' --write '" + (plain / "w.toml").string() + "'");
  EXPECT_EQ(r.status, 3);
  EXPECT_EQ(r.err, "tilelayout import: cannot write " + (plain / "w.toml").string() +
                       ": Not a directory\n");
  r = run("import --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--hostfile"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace l2
