// `l2wall plot`: a report.csv written by hand, drawn by gnuplot; the picture holds a curve in
// each curve's colour, and what cannot be plotted is one line naming the file.
#include "report_plot.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "image/png_io.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

class ReportPlot : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("l2-plot-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

Rgb rgb_of(const char* hex) {
  const unsigned long v = std::strtoul(hex + 1, nullptr, 16);
  return Rgb{static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 8),
             static_cast<std::uint8_t>(v)};
}

long pixels_of(const RgbImage& image, Rgb colour) {
  long n = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) n += image.at(x, y) == colour;
  }
  return n;
}

TEST_F(ReportPlot, DrawsRouteSwapAndEveryHostsRenderTime) {
  std::ofstream(dir_ / "report.csv")
      << "frame,in_refresh,swap_refresh,latency_frames,route_ms,swap_ms,render_ms_0,"
         "ready_wait_ms_0,sync_retries_0,render_ms_1,ready_wait_ms_1,sync_retries_1\n"
         "0,1,2,1,1.000,16.000,10.000,3.000,0,22.000,1.000,0\n"
         "1,2,3,1,2.000,17.000,11.000,3.000,0,25.000,1.000,0\n"
         "2,3,4,1,1.500,16.500,12.000,3.000,0,21.000,1.000,0\n";
  std::ofstream(dir_ / "summary.txt") << "limited by pipeserver 1's render time: median 22.0 ms\n";
  const fs::path png = plot_report(dir_);
  EXPECT_EQ(png, dir_ / "report.png");
  const RgbImage picture = read_png(png);
  EXPECT_EQ(picture.width(), 1000);
  EXPECT_EQ(picture.height(), 600);
  // route, swap, pipeserver 0, pipeserver 1: each drawn (line and key sample) in its colour.
  for (int curve = 0; curve < 4; ++curve) {
    EXPECT_GT(pixels_of(picture, rgb_of(kPlotColours[curve])), 100) << kPlotColours[curve];
  }
  EXPECT_EQ(pixels_of(picture, rgb_of(kPlotColours[4])), 0);  // no third pipeserver
  std::ifstream commands(dir_ / "report.gnuplot");
  const std::string text((std::istreambuf_iterator<char>(commands)), {});
  EXPECT_NE(text.find("set title 'l2wall run, 2 pipeservers: time per frame - limited by "
                      "pipeserver 1''s render time: median 22.0 ms'"),
            std::string::npos)
      << text;
}

// The vizserver path has no emulator: its route and swap columns are empty, and not drawn.
TEST_F(ReportPlot, WithoutAnEmulatorOnlyTheRenderTimes) {
  std::ofstream(dir_ / "report.csv")
      << "frame,in_refresh,swap_refresh,latency_frames,route_ms,swap_ms,render_ms_0,"
         "ready_wait_ms_0,sync_retries_0\n"
         "0,,,n/a,,,10.000,3.000,0\n"
         "1,,,n/a,,,12.000,3.000,0\n";
  const RgbImage picture = read_png(plot_report(dir_));
  EXPECT_EQ(pixels_of(picture, rgb_of(kPlotColours[0])), 0);
  EXPECT_EQ(pixels_of(picture, rgb_of(kPlotColours[1])), 0);
  EXPECT_GT(pixels_of(picture, rgb_of(kPlotColours[2])), 100);
}

TEST_F(ReportPlot, WhatCannotBePlottedIsOneLine) {
  try {
    plot_report(dir_);
    FAIL() << "plotted a folder without report.csv";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), (dir_ / "report.csv").string() + ": cannot read, or empty");
  }
  std::ofstream(dir_ / "report.csv") << "a,b,c\n1,2,3\n";
  try {
    plot_report(dir_);
    FAIL() << "plotted a CSV that is not a report";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), (dir_ / "report.csv").string() +
                                         ":1: not the header of an l2wall run's report: a,b,c");
  }
}

}  // namespace
}  // namespace l2
