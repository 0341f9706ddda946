#include "image/png_io.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace l2 {
namespace {

std::filesystem::path temp_dir() {
  auto dir = std::filesystem::temp_directory_path() /
             ("l2_png_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
              ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(PngIo, RoundTripIsExact) {
  RgbImage img(17, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 17; ++x)
      img.set(x, y, {static_cast<std::uint8_t>(x * 15), static_cast<std::uint8_t>(y * 50), 77});
  const auto path = temp_dir() / "sub" / "round.png";
  write_png(path, img);
  EXPECT_EQ(read_png(path), img);
}

TEST(PngIo, MissingFileErrorNamesIt) {
  try {
    read_png("/nonexistent/frame-7.png");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/frame-7.png"), std::string::npos);
  }
}

TEST(PngIo, GarbageFileIsAnErrorNotACrash) {
  const auto path = temp_dir() / "garbage.png";
  std::ofstream(path) << "this is not a png";
  EXPECT_THROW(read_png(path), std::runtime_error);
}

// Whether a shared library whose file name contains `name` is mapped into this process.
bool mapped(const std::string& name) {
  std::ifstream maps("/proc/self/maps");
  for (std::string line; std::getline(maps, line);) {
    if (line.find(name) != std::string::npos) return true;
  }
  return false;
}

// OpenImageIO costs half a second of start-up; a process pays for it on its first picture only.
// A "threadsafe" death test runs its statement in a fresh process (this binary, executed again),
// where no picture has been read or written yet.
TEST(PngIoDeathTest, OpenImageIOIsLoadedOnTheFirstPictureOnly) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const auto path = temp_dir() / "first.png";
  EXPECT_EXIT(
      {
        if (mapped("libOpenImageIO")) {
          std::fputs("OpenImageIO was loaded before any picture\n", stderr);
          std::exit(1);
        }
        write_png(path, RgbImage(3, 2, {1, 2, 3}));
        if (!mapped("libOpenImageIO")) {
          std::fputs("OpenImageIO not loaded after writing a picture\n", stderr);
          std::exit(2);
        }
        std::exit(read_png(path) == RgbImage(3, 2, {1, 2, 3}) ? 0 : 3);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace l2
