// What a run clears from its --out before it starts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/png_io.hpp"
#include "l2wall/run_pictures.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

TEST(RemoveEarlierPictures, OnlyFoldersNamedAsARunNamesThem) {
  // A passing run into the --out of a failed one stood beside its fault/ folder.
  const fs::path out = fs::temp_directory_path() / "l2wall-earlier-pictures";
  fs::remove_all(out);
  for (const char* dir :
       {"fault", "frame-7", "mismatch-frame-3", "screenshots", "frame-best", "frames"}) {
    fs::create_directories(out / dir);
    std::ofstream(out / dir / "display-0.png") << "x";
  }
  std::ofstream(out / "frame-9") << "a file, not a run's folder";
  std::ofstream(out / "summary.txt") << "x";
  remove_earlier_pictures(out);
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(out)) left.push_back(e.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"frame-9", "frame-best", "frames", "screenshots",
                                            "summary.txt"}));
  fs::remove_all(out);
  remove_earlier_pictures(out);  // a folder that does not exist yet: nothing to do, no error
}

TEST(WriteDisplayPictures, AnEmptyPictureIsNotWrittenNorTheWall) {
  // Over MPI the displays of a column whose rank is gone come back empty after a fault.
  const fs::path dir = fs::temp_directory_path() / "l2wall-display-pictures";
  fs::remove_all(dir);
  Wall wall;
  wall.canvas_width = 8;
  wall.canvas_height = 2;
  wall.displays = {{0, 4, 2, 0, 0, 0, "", {}, {}, {}, {}, {}, {}, 1.0, {}},
                   {1, 4, 2, 4, 0, 0, "", {}, {}, {}, {}, {}, {}, 1.0, {}}};
  RgbImage shown(4, 2);
  shown.set(1, 1, Rgb{200, 10, 20});
  const RgbImage lost;
  const DisplayPictures pictures = [&](int id) -> const RgbImage& {
    return id == 0 ? shown : lost;
  };
  EXPECT_EQ(write_display_pictures(dir, wall, pictures), std::vector<int>{1});
  EXPECT_EQ(read_png(dir / "display-0.png").at(1, 1), (Rgb{200, 10, 20}));
  EXPECT_FALSE(fs::exists(dir / "display-1.png"));
  EXPECT_FALSE(fs::exists(dir / "wall.png"));  // not a wall with a hole in it
  fs::remove_all(dir);
  const DisplayPictures both = [&](int) -> const RgbImage& { return shown; };
  EXPECT_TRUE(write_display_pictures(dir, wall, both).empty());
  EXPECT_TRUE(fs::exists(dir / "wall.png"));
  fs::remove_all(dir);
}

// std::filesystem's "filesystem error: cannot remove all: Operation not permitted [...]" reached
// users. As root only an immutable folder cannot be removed (chattr; skipped where the file
// system or the user does not allow it).
TEST(RemoveEarlierPictures, AFolderThatCannotBeRemovedIsNamed) {
  const fs::path out = fs::temp_directory_path() / "l2wall-earlier-pictures-kept";
  fs::remove_all(out);
  fs::create_directories(out / "frame-1");
  std::ofstream(out / "frame-1" / "display-0.png") << "x";
  const std::string folder = (out / "frame-1").string();
  if (std::system(("chattr +i '" + folder + "' 2>/dev/null").c_str()) != 0) {
    fs::remove_all(out);
    GTEST_SKIP() << "chattr +i is not allowed here";
  }
  std::string error = "no error";
  try {
    remove_earlier_pictures(out);
  } catch (const std::runtime_error& e) {
    error = e.what();
  }
  std::system(("chattr -i '" + folder + "'").c_str());
  fs::remove_all(out);
  EXPECT_EQ(error,
            folder + ": cannot remove the pictures of an earlier run: Operation not permitted");
}

}  // namespace
}  // namespace l2
