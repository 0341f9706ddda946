// The rank roles of an MPI run, from rank order, on the walls the tests run over MPI.
#include "mpi_link/rank_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

TEST(RankMap, DefaultWallIsOneColumnOfFourInputs) {
  const RankMap map = make_rank_map(plan_layout(default_wall()));
  EXPECT_EQ(map.pipeservers, 4);
  EXPECT_EQ(map.columns, 1);
  EXPECT_EQ(map.size(), 6);
  EXPECT_EQ(map.role(0), "coordinator");
  EXPECT_EQ(map.role(1), "pipeserver 0");
  EXPECT_EQ(map.role(4), "pipeserver 3");
  EXPECT_EQ(map.role(5), "board column 0");
  EXPECT_EQ(map.column_rank(0), 5);
  EXPECT_EQ(map.pipeservers_of_column[0], (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(map.displays_of_column[0], (std::vector<int>{0, 1, 2, 3}));
  for (const auto& columns : map.columns_of_pipeserver) EXPECT_EQ(columns, std::vector<int>{0});
}

// 65 displays (13 x 5): two meshes, each with its own columns. Mesh 0 is the left 7 columns of
// displays (35: its columns 0-4) and pipeservers 0-1, mesh 1 the right 6 (30: columns 5-8)
// and pipeservers 2-3.
TEST(RankMap, EachMeshHasItsOwnColumns) {
  const RankMap map =
      make_rank_map(plan_layout(load_wall(L2_SOURCE_DIR "/l2wall/mpi/tests/two-meshes-13x5.toml")));
  EXPECT_EQ(map.pipeservers, 4);
  EXPECT_EQ(map.columns, 9);
  EXPECT_EQ(map.size(), 14);
  // Mesh 0 numbers its displays row by row over its 7 columns: wall display 15 (row 1, column
  // 2) is its 9, in its column 1; wall display 7 is mesh 1's 0, in the wall's column 5, and
  // wall display 64 (row 4, column 12) mesh 1's 29, in column 5 + 3.
  EXPECT_EQ(map.column_of_display[15], 1);
  EXPECT_EQ(map.column_of_display[7], 5);
  EXPECT_EQ(map.column_of_display[64], 8);
  EXPECT_EQ(map.displays_of_column[5], (std::vector<int>{7, 8, 9, 10, 11, 12, 20, 21}));
  for (int c = 0; c < 9; ++c) {
    const std::vector<int> mesh_pipeservers =
        c < 5 ? std::vector<int>{0, 1} : std::vector<int>{2, 3};
    for (const int s : map.pipeservers_of_column[static_cast<std::size_t>(c)]) {
      EXPECT_NE(std::find(mesh_pipeservers.begin(), mesh_pipeservers.end(), s),
                mesh_pipeservers.end())
          << "column " << c << " pipeserver " << s;
    }
    EXPECT_FALSE(map.pipeservers_of_column[static_cast<std::size_t>(c)].empty()) << c;
  }
}

TEST(RankMap, TwelveMonitorsAreTwoColumns) {
  const RankMap map =
      make_rank_map(plan_layout(load_wall(L2_SOURCE_DIR "/walls/monitors-4x3.toml")));
  EXPECT_EQ(map.pipeservers, 8);
  EXPECT_EQ(map.columns, 2);
  EXPECT_EQ(map.size(), 11);
  EXPECT_EQ(map.role(9), "board column 0");
  EXPECT_EQ(map.role(10), "board column 1");
  EXPECT_EQ(map.displays_of_column[0], (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(map.displays_of_column[1], (std::vector<int>{8, 9, 10, 11}));
  // Every input reaches some column, and a column takes in exactly the inputs that feed it.
  for (int s = 0; s < map.pipeservers; ++s) {
    ASSERT_FALSE(map.columns_of_pipeserver[s].empty());
    for (const int c : map.columns_of_pipeserver[s]) {
      const auto& fed = map.pipeservers_of_column[c];
      EXPECT_NE(std::find(fed.begin(), fed.end(), s), fed.end()) << "pipeserver " << s;
    }
  }
}

TEST(RankMap, WrongRankCountIsOneLineWithTheNumbers) {
  const RankMap map = make_rank_map(plan_layout(default_wall()));
  EXPECT_TRUE(rank_count_error(map, 6).ok());
  EXPECT_EQ(rank_count_error(map, 4).reason(),
            "--mpi: this wall needs mpirun -np 6 (1 coordinator + 4 pipeservers + 1 board "
            "column), got 4 ranks");
}

}  // namespace
}  // namespace l2
