#include "tilelayout/several_meshes.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

// A grid of `columns` x `rows` displays of 40x30, one tile each, `pipeservers` of them.
std::string grid_wall(int columns, int rows, int pipeservers, const std::string& extra = "") {
  return "[display_grid]\ncolumns = " + std::to_string(columns) +
         "\nrows = " + std::to_string(rows) + "\nwidth = 40\nheight = 30\n" + extra +
         "[tiling]\nkind = \"grid\"\ntile_width = 40\ntile_height = 30\n"
         "[pipeservers]\ncount = " +
         std::to_string(pipeservers) + "\nframebuffer_width = 48\nframebuffer_height = 30\n";
}

std::string error_of(const std::string& text) {
  try {
    parse_wall(text, "walls/m.toml");
  } catch (const LayoutError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SeveralMeshes, SixtyFourDisplaysAreOneMeshAndSixtyFiveTwo) {
  EXPECT_EQ(parse_wall(grid_wall(8, 8, 64), "w.toml").mesh_count, 1);
  const Wall w = parse_wall(grid_wall(13, 5, 65), "w.toml");
  ASSERT_EQ(w.mesh_count, 2);
  // Half would cut the 7th column; the nearest cut between columns is after it: the first 7
  // columns (35 displays) and the other 6 (30).
  for (const Display& d : w.displays) EXPECT_EQ(d.mesh, d.id % 13 < 7 ? 0 : 1) << d.id;
}

TEST(SeveralMeshes, StallionIsItsLeftAndRightHalves) {
  const Wall w = load_wall(L2_WALLS_DIR "/stallion-16x5.toml");
  ASSERT_EQ(w.displays.size(), 80u);
  ASSERT_EQ(w.mesh_count, 2);
  for (const Display& d : w.displays) EXPECT_EQ(d.mesh, d.id % 16 < 8 ? 0 : 1) << d.id;
  EXPECT_EQ(w.mesh_pipeservers, (std::vector<int>{80, 80}));
}

TEST(SeveralMeshes, RealityDeckIsSevenMeshesOfWholeColumns) {
  const Wall w = load_wall(L2_WALLS_DIR "/reality-deck.toml");
  ASSERT_EQ(w.displays.size(), 416u);
  ASSERT_EQ(w.mesh_count, 7);
  std::vector<int> count(7, 0);
  for (const Display& d : w.displays) {
    ++count[static_cast<std::size_t>(d.mesh)];
    // Every display of a column in the same mesh, and meshes in column order.
    EXPECT_EQ(d.mesh, w.displays[static_cast<std::size_t>(d.id % 52)].mesh) << d.id;
    if (d.id % 52 > 0) {
      EXPECT_GE(d.mesh, w.displays[static_cast<std::size_t>(d.id - 1)].mesh);
    }
  }
  EXPECT_EQ(count, (std::vector<int>{56, 56, 64, 56, 64, 56, 64}));
  // Two pipeservers a panel: each mesh's share is twice its displays.
  EXPECT_EQ(w.mesh_pipeservers, (std::vector<int>{112, 112, 128, 112, 128, 112, 128}));
}

TEST(SeveralMeshes, MeshesGivenPerDisplay) {
  std::string meshes = "meshes = [";
  for (int i = 0; i < 8; ++i) meshes += i < 5 ? "1, " : "0, ";
  const Wall w = parse_wall(grid_wall(4, 2, 4, meshes + "]\n"), "w.toml");
  ASSERT_EQ(w.mesh_count, 2);
  EXPECT_EQ(w.displays[0].mesh, 1);
  EXPECT_EQ(w.displays[7].mesh, 0);
  const std::vector<MeshPart> parts = mesh_parts(w);
  EXPECT_EQ(parts[0].displays, (std::vector<int>{5, 6, 7}));
  EXPECT_EQ(parts[1].displays, (std::vector<int>{0, 1, 2, 3, 4}));
  // 4 pipeservers for 3 and 5 displays' pixels: 1 + 0.75 -> 2 and 1 + 1.25 -> 2.
  EXPECT_EQ(parts[0].first_pipeserver, 0);
  EXPECT_EQ(parts[0].pipeserver_count, 2);
  EXPECT_EQ(parts[1].first_pipeserver, 2);
  EXPECT_EQ(parts[1].pipeserver_count, 2);
}

TEST(SeveralMeshes, GivenMeshesAreCheckedInOneLine) {
  EXPECT_EQ(error_of(grid_wall(2, 1, 2, "meshes = [0, 2]\n")),
            "walls/m.toml:6: display_grid.meshes: display 1: 2, but no display has mesh 1: "
            "meshes are numbered 0.. without gaps");
  std::string all_zero = "meshes = [";
  for (int i = 0; i < 65; ++i) all_zero += "0, ";
  EXPECT_EQ(error_of(grid_wall(65, 1, 65, all_zero + "]\n")),
            "walls/m.toml:6: display_grid.meshes: display 0: mesh 0 has 65 displays, more "
            "than the 64 a strip header addresses");
  const std::string list =
      "[[display]]\nwidth = 40\nheight = 30\nx = 0\ny = 0\nmesh = 0\n"
      "[[display]]\nwidth = 40\nheight = 30\nx = 40\ny = 0\n"
      "[tiling]\nkind = \"grid\"\ntile_width = 40\ntile_height = 30\n[pipeservers]\ncount = 2\n";
  EXPECT_EQ(error_of(list),
            "walls/m.toml:7: display[1].mesh: missing, but display 0 has one: give every display "
            "a mesh or none (then the planner chooses)");
}

TEST(SeveralMeshes, EveryMeshNeedsAPipeserverAndAtMostAMeshsInputs) {
  EXPECT_EQ(error_of(grid_wall(13, 5, 1)),
            "walls/m.toml:11: pipeservers.count: 1 pipeservers cannot feed 2 meshes: each "
            "pipeserver feeds one mesh (its headers cannot say which) and each mesh needs one");
  EXPECT_EQ(error_of(grid_wall(13, 5, 600)),
            "walls/m.toml:11: pipeservers.count: mesh 0 would take 323 of the 600 pipeservers, "
            "more than the 256 inputs of a mesh");
}

TEST(SeveralMeshes, WhatOnlyOneMeshDoesYetIsRefused) {
  EXPECT_EQ(error_of(grid_wall(13, 5, 66, "mullion_x = -4\n") + "[blend]\ngamma = 2.2\n"),
            "walls/m.toml:15: blend: blending is for a wall of one mesh; this wall's 65 displays "
            "need 2 meshes");
  EXPECT_EQ(error_of(grid_wall(13, 5, 66) + "[depth]\nlayers = 2\n"),
            "walls/m.toml:15: depth: depth compositing is for a wall of one mesh; this wall's "
            "65 displays need 2 meshes");
}

TEST(SeveralMeshes, SharesFollowThePixels) {
  EXPECT_EQ(share_pipeservers(10, {100, 300}), (std::vector<int>{3, 7}));
  EXPECT_EQ(share_pipeservers(3, {1, 1, 1}), (std::vector<int>{1, 1, 1}));
  // 2 spare for 3 equal meshes: the lower meshes first.
  EXPECT_EQ(share_pipeservers(5, {7, 7, 7}), (std::vector<int>{2, 2, 1}));
}

// What a live run drives: every mesh's plan put together in the wall's numbers, the headers
// keeping each mesh's display ids.
TEST(SeveralMeshes, TheWallsPlanIsEveryMeshsInTheWallsNumbers) {
  const TileLayout layout = plan_layout(load_wall(L2_WALLS_DIR "/stallion-16x5.toml"));
  ASSERT_EQ(layout.meshes.size(), 2u);
  ASSERT_EQ(layout.pipeservers.size(), 160u);
  EXPECT_EQ(layout.tiles.size(), 160u);
  // Pipeserver 80 is mesh 1's first input: half of the wall's display 8, its mesh's display 0.
  const PipeserverPlan& p = layout.pipeservers[80];
  EXPECT_EQ(p.pipeserver, 80);
  EXPECT_EQ(p.mesh, 1);
  ASSERT_EQ(p.tiles.size(), 1u);
  EXPECT_EQ(p.tiles[0].tile.display, 8);
  EXPECT_EQ(header_id(p.tiles[0].tile), 0);
  EXPECT_EQ(p.tiles[0].tile.on_canvas, (Rect{8 * 2560, 0, 1280, 1600}));
  // Mesh 0 numbers its 8 columns' displays row by row: the wall's display (row r, column c) is
  // its r * 8 + c.
  for (int s = 0; s < 80; ++s) {
    const DisplayTile& t = layout.pipeservers[static_cast<std::size_t>(s)].tiles.at(0).tile;
    EXPECT_EQ(header_id(t), t.display / 16 * 8 + t.display % 16) << s;
  }
  for (std::size_t i = 0; i < layout.tiles.size(); ++i) {
    EXPECT_EQ(layout.wall.displays[static_cast<std::size_t>(layout.tiles[i].display)].mesh,
              layout.pipeservers[static_cast<std::size_t>(layout.tile_pipeserver[i])].mesh)
        << i;
  }
}

TEST(SeveralMeshes, EachMeshIsPlannedInItsOwnNumbers) {
  const Wall w = load_wall(L2_WALLS_DIR "/stallion-16x5.toml");
  const std::vector<MeshPart> parts = mesh_parts(w);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[1].first_pipeserver, 80);
  EXPECT_EQ(number_runs(parts[1].displays), "8-15, 24-31, 40-47, 56-63, 72-79");
  const MeshPlan m = plan_mesh(w, parts[1]);
  const Wall& mw = m.layout.wall;
  ASSERT_EQ(mw.displays.size(), 40u);
  EXPECT_EQ(mw.pipeserver_count, 80);
  // Its display 0 is the wall's display 8: the 9th column's top panel.
  EXPECT_EQ(mw.displays[0].on_canvas(), (Rect{8 * 2560, 0, 2560, 1600}));
  EXPECT_EQ(mw.displays[39].on_canvas(), (Rect{15 * 2560, 4 * 1600, 2560, 1600}));
  // Every pipeserver one half-panel tile, every tile on one of its displays.
  ASSERT_EQ(m.layout.pipeservers.size(), 80u);
  std::set<std::pair<int, int>> halves;
  for (const PipeserverPlan& s : m.layout.pipeservers) {
    ASSERT_EQ(s.tiles.size(), 1u) << s.pipeserver;
    const DisplayTile& t = s.tiles[0].tile;
    EXPECT_EQ(t.on_display.w, 1280);
    EXPECT_EQ(t.on_display.h, 1600);
    halves.insert({t.display, t.on_display.x});
  }
  EXPECT_EQ(halves.size(), 80u);  // each half of each of its 40 displays once
  EXPECT_EQ(mesh_heading(parts[1], 20, 5),
            "mesh 1: 40 displays (wall displays 8-15, 24-31, 40-47, 56-63, 72-79 as its "
            "displays 0-39), 80 pipeservers (80-159 as its inputs 0-79), 20 x 5 boards");
}

}  // namespace
}  // namespace l2
