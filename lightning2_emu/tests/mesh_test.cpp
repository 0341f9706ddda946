#include "lightning2_emu/mesh.hpp"

#include <gtest/gtest.h>

#include "lightning2_emu/swap_group.hpp"

namespace l2 {
namespace {

TEST(Mesh, CountsInputsAndDisplaysFromBoards) {
  const Mesh mesh(3, 2);
  EXPECT_EQ(mesh.input_count(), 12);
  EXPECT_EQ(mesh.display_count(), 16);
  EXPECT_EQ(mesh.limit().width, 1280);
  EXPECT_EQ(mesh.limit().height, 1024);
}

TEST(Mesh, PlacesInputsOnRowsAndDisplaysOnColumnsAndPorts) {
  EXPECT_EQ(Mesh::board_row_of_input(0), 0);
  EXPECT_EQ(Mesh::board_row_of_input(3), 0);
  EXPECT_EQ(Mesh::board_row_of_input(4), 1);
  EXPECT_EQ(Mesh::board_row_of_input(11), 2);
  EXPECT_EQ(Mesh::column_of_display(7), 0);
  EXPECT_EQ(Mesh::column_of_display(8), 1);
  EXPECT_EQ(Mesh::port_of_display(13), 5);
  const Board b = Mesh(3, 2).board(2, 1);
  EXPECT_EQ(b.first_input(), 8);
  EXPECT_EQ(b.first_display(), 8);
  EXPECT_THROW(Mesh(3, 2).board(3, 0), MeshError);
}

TEST(Mesh, FitsTheSmallestMesh) {
  const Mesh m = Mesh::fit(12, 1);
  EXPECT_EQ(m.rows(), 3);
  EXPECT_EQ(m.columns(), 1);
  const Mesh n = Mesh::fit(5, 9);
  EXPECT_EQ(n.rows(), 2);
  EXPECT_EQ(n.columns(), 2);
  EXPECT_EQ(Mesh::fit(0, 0).input_count(), 4);
  EXPECT_THROW(Mesh::fit(1, 65), MeshError);
}

TEST(Mesh, RefusesInputsBeyondTheMeshOrTheBoardLimit) {
  const Mesh mesh(1, 1, {640, 480});
  EXPECT_NO_THROW(mesh.check_input(3, 640, 480, "a.png"));
  try {
    mesh.check_input(4, 10, 10, "e.png");
    FAIL();
  } catch (const MeshError& e) {
    EXPECT_STREQ(e.what(),
                 "e.png: input 4 is beyond the mesh (1x1 boards: 4 inputs, 8 displays, inputs "
                 "up to 640x480 has inputs 0..3)");
  }
  try {
    mesh.check_input(0, 641, 480, "big.png");
    FAIL();
  } catch (const MeshError& e) {
    EXPECT_STREQ(e.what(), "big.png: input 0 is 641x480, larger than the board limit 640x480");
  }
}

TEST(Mesh, BoardLimitIsTwoByOneToAWallFilesLargest) {
  // --board-max 100000x100000 was taken, where a wall file's board_max allows 4096.
  try {
    Mesh(1, 1, {5000, 480});
    FAIL();
  } catch (const MeshError& e) {
    EXPECT_STREQ(e.what(), "board input limit must be 2x1..4096x4096, got 5000x480");
  }
  EXPECT_THROW(Mesh(1, 1, {640, 4097}), MeshError);
  EXPECT_THROW(Mesh(1, 1, {1, 480}), MeshError);
  EXPECT_NO_THROW(Mesh(1, 1, {4096, 4096}));
}

TEST(Mesh, RefusesDisplaysBeyondTheMeshOrTheHeaderRange) {
  const Mesh mesh(1, 2);
  EXPECT_NO_THROW(mesh.check_display(15, 4096, 4096));
  EXPECT_THROW(mesh.check_display(16, 100, 100), MeshError);
  EXPECT_THROW(mesh.check_display(0, 4097, 100), MeshError);
  EXPECT_THROW(mesh.check_display(0, 0, 100), MeshError);
  EXPECT_THROW(Mesh(1, 9), MeshError);
  EXPECT_THROW(Mesh(0, 1), MeshError);
}

TEST(SwapGroups, GroupDisplaysByTheirConfiguredNumber) {
  const std::vector<DisplaySpec> displays = {
      {0, 10, 10, 5}, {1, 10, 10, 2}, {2, 10, 10, 5}, {3, 10, 10, 2}, {4, 10, 10, 9}};
  const auto groups = make_swap_groups(displays);
  ASSERT_EQ(groups.size(), 3u);
  EXPECT_EQ(groups[0].id, 2);
  EXPECT_EQ(groups[0].displays, (std::vector<int>{1, 3}));
  EXPECT_EQ(groups[1].id, 5);
  EXPECT_EQ(groups[1].displays, (std::vector<int>{0, 2}));
  EXPECT_EQ(groups[2].displays, (std::vector<int>{4}));
}

}  // namespace
}  // namespace l2
