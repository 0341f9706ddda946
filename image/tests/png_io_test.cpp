#include "image/png_io.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

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

}  // namespace
}  // namespace l2
