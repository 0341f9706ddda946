// The order in which `sequence` plays a folder's frames.
#include "lightning2_emu/frame_files.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

namespace l2 {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> names_in_play_order(const std::vector<std::string>& files) {
  const fs::path dir =
      fs::temp_directory_path() /
      ("l2_frame_files_" +
       std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const std::string& f : files) std::ofstream(dir / f) << "x";
  std::vector<std::string> names;
  for (const fs::path& p : list_frames(dir)) names.push_back(p.filename().string());
  fs::remove_all(dir);
  return names;
}

TEST(FrameFiles, NumbersInNamesCountByValue) {
  // Plain name order played frame-10 right after frame-1, before frame-2.
  EXPECT_EQ(
      names_in_play_order({"frame-10.png", "frame-2.png", "frame-1.png", "frame-0.png"}),
      (std::vector<std::string>{"frame-0.png", "frame-1.png", "frame-2.png", "frame-10.png"}));
  EXPECT_EQ(names_in_play_order({"b-1.png", "a-20.png", "a-3.png", "notes.txt"}),
            (std::vector<std::string>{"a-3.png", "a-20.png", "b-1.png"}));
  // Zero-padded names keep their order; padded and unpadded equal numbers are both kept.
  EXPECT_EQ(names_in_play_order({"f010.png", "f002.png", "f2.png", "f9.png"}),
            (std::vector<std::string>{"f002.png", "f2.png", "f9.png", "f010.png"}));
}

}  // namespace
}  // namespace l2
