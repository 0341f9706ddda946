// Output folders: made when missing, refused in one line naming the path and why.
#include "image/folders.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "image/png_io.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir() {
  const fs::path dir =
      fs::temp_directory_path() /
      ("l2_folders_" +
       std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(Folders, MakesMissingParentsAndAcceptsAnExistingFolder) {
  const fs::path dir = fresh_dir();
  make_folders(dir / "a/b/c");
  EXPECT_TRUE(fs::is_directory(dir / "a/b/c"));
  make_folders(dir / "a/b/c", "--out");
  make_folders(dir / "a/b/");
  fs::remove_all(dir);
}

// std::filesystem said "filesystem error: cannot create directories: Not a directory [...]".
TEST(Folders, AFileInTheWayIsNamed) {
  const fs::path dir = fresh_dir();
  std::ofstream(dir / "file") << "x";
  EXPECT_EQ(error_of([&] { make_folders(dir / "file/a/b", "--out"); }),
            "--out " + (dir / "file/a/b").string() + ": cannot make the folder: " +
                (dir / "file").string() + " is a file, not a folder");
  EXPECT_EQ(error_of([&] { make_folders(dir / "file"); }),
            (dir / "file").string() + ": a file, not a folder");
  EXPECT_EQ(error_of([&] { make_folders(dir / "file/"); }),
            (dir / "file/").string() + ": a file, not a folder");
  EXPECT_EQ(error_of([&] { write_png(dir / "file/display-0.png", RgbImage(2, 2)); }),
            dir.string() + "/file: a file, not a folder");
  fs::remove_all(dir);
}

// OpenImageIO said only "Could not open file".
TEST(Folders, AFolderWhereAPictureGoesIsNamed) {
  const fs::path dir = fresh_dir();
  fs::create_directories(dir / "display-2.png");
  EXPECT_EQ(error_of([&] { write_png(dir / "display-2.png", RgbImage(2, 2)); }),
            (dir / "display-2.png").string() + ": cannot write: a folder, not a file");
  fs::remove_all(dir);
}

// OpenImageIO's "could not find a format writer for ... Is it a file format that OpenImageIO
// doesn't know about?", and an empty file left behind by the check that the file can be opened.
TEST(Folders, AnUnknownPictureFormatIsNamedAndNoFileIsLeft) {
  const fs::path dir = fresh_dir();
  EXPECT_EQ(error_of([&] { write_png(dir / "frame.foo", RgbImage(2, 2)); }),
            (dir / "frame.foo").string() +
                ": cannot write: no picture format is known for '.foo' (give .png)");
  EXPECT_FALSE(fs::exists(dir / "frame.foo"));
  fs::remove_all(dir);
}

TEST(Folders, NumberedNamesArePrefixDigitsSuffixAndNothingElse) {
  EXPECT_TRUE(numbered_name("frame-12", "frame-"));
  EXPECT_TRUE(numbered_name("frame-0003.png", "frame-", ".png", 4));
  EXPECT_FALSE(numbered_name("frame-003.png", "frame-", ".png", 4));  // fewer digits than asked
  EXPECT_FALSE(numbered_name("frame-", "frame-"));                    // no digit at all
  EXPECT_FALSE(numbered_name("frame-.png", "frame-", ".png"));
  EXPECT_FALSE(numbered_name("frame-1a", "frame-"));
  EXPECT_FALSE(numbered_name("frame-12.png", "frame-"));  // a suffix not asked for
  EXPECT_FALSE(numbered_name("frame-12", "frame-", ".png"));
  EXPECT_FALSE(numbered_name("myframe-12", "frame-"));
  EXPECT_FALSE(numbered_name("frame--12", "frame-"));
}

TEST(Folders, RemoveEarlierTakesWhatItIsToldAndNothingElse) {
  const fs::path dir = fresh_dir();
  fs::create_directories(dir / "frame-1" / "inner");
  std::ofstream(dir / "frame-1" / "inner" / "a.png") << "x";
  std::ofstream(dir / "frame-2") << "a file with a run's folder name";
  std::ofstream(dir / "notes.txt") << "mine";
  remove_earlier(
      dir,
      [](const fs::directory_entry& e) {
        return e.is_directory() && numbered_name(e.path().filename().string(), "frame-");
      },
      "the pictures of an earlier run");
  EXPECT_FALSE(fs::exists(dir / "frame-1"));
  EXPECT_TRUE(fs::exists(dir / "frame-2"));
  EXPECT_TRUE(fs::exists(dir / "notes.txt"));
  // A folder that does not exist yet: nothing to do, no error.
  EXPECT_EQ(error_of([&] {
              remove_earlier(
                  dir / "missing", [](const auto&) { return true; }, "x");
            }),
            "no error");
}

}  // namespace
}  // namespace l2
