// tilelayout import's library on the example configurations (examples/walls/imported/, each
// following its format's published examples): the wall file it writes is read back with
// parse_wall and planned, and its displays are compared with the values worked out by hand from
// the input file.
#include "tilelayout/wall_import.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2::import_tests {
namespace {

std::string example(const std::string& name) {
  std::ifstream in(std::string(L2_IMPORTED_DIR) + "/" + name, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  EXPECT_FALSE(s.str().empty()) << name;
  return s.str();
}

struct Expected {
  int width, height, x, y, rotation = 0;
  Flip flip = Flip::None;
};

// The wall as every program reads it: parsed, and planned without an error.
Wall read_back(const ImportedWall& imported) {
  const Wall wall = parse_wall(imported.toml, "imported.toml");
  EXPECT_NO_THROW(plan_layout(wall)) << imported.toml;
  return wall;
}

void expect_displays(const Wall& wall, const std::vector<Expected>& expected) {
  ASSERT_EQ(wall.displays.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const Display& d = wall.displays[i];
    const Expected& e = expected[i];
    EXPECT_EQ(d.width, e.width) << "display " << i;
    EXPECT_EQ(d.height, e.height) << "display " << i;
    EXPECT_EQ(d.canvas_x, e.x) << "display " << i;
    EXPECT_EQ(d.canvas_y, e.y) << "display " << i;
    EXPECT_EQ(d.orientation.rotation, e.rotation) << "display " << i;
    EXPECT_EQ(d.orientation.flip, e.flip) << "display " << i;
  }
}

TEST(WallImport, TideGridOfTwoDisplayScreensWithBezels) {
  const ImportedWall imported = import_wall(example("tide-bbp-4x3.json"), "tide-bbp-4x3.json");
  EXPECT_EQ(imported.format, ImportFormat::Tide);
  const Wall wall = read_back(imported);
  EXPECT_EQ(wall.name, "TestWall");
  // 2x3 screens of 2x1 displays: 4 columns, 3 rows of 1920x1080, steps of 1920+14 and 1080+12.
  std::vector<Expected> expected;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) expected.push_back({1920, 1080, c * 1934, r * 1092});
  }
  expect_displays(wall, expected);
  EXPECT_EQ(wall.displays[11].canvas_x, 5802);
  EXPECT_EQ(wall.displays[11].canvas_y, 2184);
  EXPECT_EQ(wall.canvas_width, 7722);   // 4 x 1920 + 3 x 14
  EXPECT_EQ(wall.canvas_height, 3264);  // 3 x 1080 + 2 x 12
  // One pipeserver per process, in the order of the processes.
  EXPECT_EQ(wall.pipeserver_count, 6);
  EXPECT_EQ(imported.hosts,
            (std::vector<std::string>{"bbplxviz03i", "bbplxviz03i", "bbplxviz03i", "bbplxviz04i",
                                      "bbplxviz04i", "bbplxviz04i"}));
  // 1 coordinator + 6 pipeservers + 2 board columns (12 displays, 8 a column).
  EXPECT_EQ(mpi_hostfile(imported.hosts, imported.display_count),
            "# l2wall run --mpi: mpirun -np 9 --hostfile THIS --map-by slot "
            "(docs/mpi-design.md).\n"
            "# Rank 0 (the coordinator) on the first host, the 6 pipeservers on the hosts the "
            "configuration names, the 2 board column rank(s) on the last host.\n"
            "bbplxviz03i slots=4\nbbplxviz04i slots=5\n");
  EXPECT_TRUE(imported.notes.empty());
  // What came from where is in the file for a person to read.
  EXPECT_NE(imported.toml.find("#   display 5: screen i=0 j=1 of processes[1] on bbplxviz03i, "
                               "X display :0.0\n"),
            std::string::npos);
}

TEST(WallImport, TideStereoProjectorsOverlapAndAreImportedOnce) {
  const ImportedWall imported =
      import_wall(example("tide-stereo-2x1.json"), "tide-stereo-2x1.json");
  const Wall wall = read_back(imported);
  EXPECT_EQ(wall.name, "tide-stereo-2x1");
  // numScreensX 2 of 960x540, bezel -60: the second starts 60 pixels before the first ends.
  expect_displays(wall, {{960, 540, 0, 0}, {960, 540, 900, 0}});
  EXPECT_EQ(wall.pipeserver_count, 4);
  EXPECT_EQ(imported.display_count, 2);
  // 1 coordinator + 4 pipeservers + 1 board column, all on the one host.
  const std::string hostfile = mpi_hostfile(imported.hosts, imported.display_count);
  EXPECT_EQ(
      hostfile.substr(hostfile.rfind('#')),
      "# Rank 0 (the coordinator) on the first host, the 4 pipeservers on the hosts the "
      "configuration names, the 1 board column rank(s) on the last host.\nlocalhost slots=6\n");
  ASSERT_EQ(imported.notes.size(), 2u);
  EXPECT_EQ(imported.notes[0],
            "stereo: processes[0].screens[0].stereo = \"left\" and 3 more screens: not "
            "representable, each display is imported once, as one picture");
  EXPECT_EQ(imported.notes[1],
            "processes[1].screens[0] shows screen i=0 j=0 again (processes[0] does first) (and 1 "
            "more repeated screens): kept once");
  // The notes are in the wall file too.
  EXPECT_NE(imported.toml.find("#   - " + imported.notes[0] + "\n"), std::string::npos);
}

TEST(WallImport, Sage2BordersInMetresBecomeMullionsAtThePixelPitch) {
  const ImportedWall imported = import_wall(example("sage2-3x2-cfg.json"), "sage2-3x2-cfg.json");
  EXPECT_EQ(imported.format, ImportFormat::Sage2);
  const Wall wall = read_back(imported);
  EXPECT_EQ(wall.name, "Tiled lab wall");
  // 1920 px over 1.2 m and 1080 px over 0.675 m: 1600 px/m both ways. Borders 0.005 + 0.005 m
  // across: 16 px; 0.0025 + 0.0025 m down: 8 px.
  std::vector<Expected> expected;
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 3; ++c) expected.push_back({1920, 1080, c * 1936, r * 1088});
  }
  expect_displays(wall, expected);
  // No hosts in a SAGE2 file: one pipeserver per display.
  EXPECT_TRUE(imported.hosts.empty());
  EXPECT_EQ(wall.pipeserver_count, 6);
  EXPECT_TRUE(imported.notes.empty());
}

TEST(WallImport, Sage2DisplaysSpanningTilesAreListedDisplays) {
  const ImportedWall imported =
      import_wall(example("sage2-display-span-cfg.json"), "sage2-display-span-cfg.json");
  const Wall wall = read_back(imported);
  // 300x200 tiles, no dimensions (no mullions): 1x3, 2x2 and 2x1 tiles.
  expect_displays(wall, {{300, 600, 0, 0}, {600, 400, 300, 0}, {600, 200, 300, 400}});
  EXPECT_EQ(wall.canvas_width, 900);
  EXPECT_EQ(wall.canvas_height, 600);
  ASSERT_EQ(imported.notes.size(), 4u);
  EXPECT_EQ(imported.notes[0],
            "no dimensions (tile sizes and borders in metres): mullions taken as 0");
  EXPECT_EQ(imported.notes[2],
            "displays[1] spans 2x2 tiles: imported as one 600x400 display, the borders between "
            "its tiles inside it");
}

TEST(WallImport, NDisplayViewportsAtWindowPlusRegionTheRightOneTurned) {
  const ImportedWall imported =
      import_wall(example("ndisplay-3-nodes.ndisplay"), "ndisplay-3-nodes.ndisplay");
  EXPECT_EQ(imported.format, ImportFormat::NDisplay);
  const Wall wall = read_back(imported);
  // vp_right: region 1080x1920 (as seen) turned 90 degrees: a 1920x1080 panel hung in portrait.
  expect_displays(wall, {{1920, 1080, 0, 0}, {1920, 1080, 1920, 0}, {1920, 1080, 3840, 0, 90}});
  EXPECT_EQ(wall.displays[2].on_canvas(), (Rect{3840, 0, 1080, 1920}));
  EXPECT_EQ(wall.canvas_width, 4920);
  EXPECT_EQ(wall.canvas_height, 1920);
  EXPECT_EQ(imported.hosts,
            (std::vector<std::string>{"192.168.10.11", "192.168.10.12", "192.168.10.13"}));
  EXPECT_EQ(wall.pipeserver_count, 3);
  ASSERT_EQ(imported.notes.size(), 4u);
  EXPECT_EQ(imported.notes[0],
            "node node_center: output remap from file \"warp/center_blend.obj\": a warp of the "
            "node's whole output, not carried; its viewports are imported unwarped");
  EXPECT_EQ(imported.notes[2],
            "projection policy \"simple\" (node_left/vp_left, node_center/vp_center, "
            "node_right/vp_right): not carried; each display shows its canvas rectangle");
  EXPECT_EQ(imported.notes[3],
            "camera \"DefaultViewPoint\" (node_left/vp_left, node_center/vp_center, "
            "node_right/vp_right): not carried");
}

// One node, one viewport with `remap` as its viewportRemap, its window at (wx, 50).
std::string one_viewport(const std::string& remap, int wx = 100) {
  return R"({"nDisplay": {"version": "5.00", "cluster": {"nodes": {"n": {"host": "h",
      "window": {"x": )" +
         std::to_string(wx) + R"(, "y": 50, "w": 400, "h": 300},
      "viewports": {"v": {"region": {"x": 10, "y": 20, "w": 300, "h": 200},
      "viewportRemap": )" +
         remap + "}}}}}}}";
}

std::string remap(const std::string& angle, bool h, bool v) {
  return R"({"bEnable": true, "baseRemap": {"angle": )" + angle + R"(, "bFlipH": )" +
         (h ? "true" : "false") + R"(, "bFlipV": )" + (v ? "true" : "false") + "}}";
}

TEST(WallImport, NDisplayRemapAnglesAndFlips) {
  struct Case {
    std::string angle;
    bool h, v;
    Expected display;
  };
  // The canvas starts at the viewport: window (100, 50) + region (10, 20) moves to 0,0.
  const Case cases[] = {
      {"0", true, false, {300, 200, 0, 0, 0, Flip::Horizontal}},
      {"180", false, true, {300, 200, 0, 0, 180, Flip::Vertical}},
      {"270", false, false, {200, 300, 0, 0, 270}},
      {"-90", false, false, {200, 300, 0, 0, 270}},
      {"450.0", false, false, {200, 300, 0, 0, 90}},
      {"90", true, true, {200, 300, 0, 0, 270}},  // both flips: a half turn more
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.angle);
    const ImportedWall imported = import_wall(one_viewport(remap(c.angle, c.h, c.v)), "r.ndisplay");
    expect_displays(read_back(imported), {c.display});
  }
  // A remap that is not enabled turns nothing.
  const std::string off = R"({"bEnable": false, "baseRemap": {"angle": 90}})";
  expect_displays(read_back(import_wall(one_viewport(off), "r.ndisplay")), {{300, 200, 0, 0}});
}

TEST(WallImport, FormatIsToldFromContentOrGiven) {
  const std::string tide = example("tide-stereo-2x1.json");
  EXPECT_EQ(import_wall(tide, "a.json", ImportFormat::Tide).format, ImportFormat::Tide);
  try {
    import_wall(tide, "a.json", ImportFormat::Sage2);
    FAIL() << "a Tide file read as SAGE2";
  } catch (const LayoutError& e) {
    EXPECT_STREQ(e.what(),
                 "a.json: layout: expected an object, got nothing (the field is missing)");
  }
}

TEST(WallImport, HostfilePlacesCoordinatorPipeserversAndColumnsInRankOrder) {
  // Rank 0 and pipeservers 0, 1 on b; pipeserver 2 and the one column (3 displays) on a.
  const std::string text = mpi_hostfile({"b", "b", "a"}, 3);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "# l2wall run --mpi: mpirun -np 5 --hostfile THIS --map-by slot (docs/mpi-design.md).");
  EXPECT_EQ(text.substr(text.rfind(".\n") + 2), "b slots=3\na slots=2\n");
  // 17 displays: three columns.
  EXPECT_EQ(mpi_hostfile({"a"}, 17).substr(mpi_hostfile({"a"}, 17).rfind(".\n") + 2),
            "a slots=5\n");
  EXPECT_EQ(mpi_hostfile({}, 4), "");
}

}  // namespace
}  // namespace l2::import_tests
