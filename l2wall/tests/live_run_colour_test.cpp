// Colour matching end to end: a live run's saved displays on a wall with a gain/offset display
// and a table-file display are the same wall's uncorrected displays with each table applied,
// the tables worked out here from their formulas, on both paths.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <string>

#include "image/png_io.hpp"
#include "wall_run.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace testing_support;

// The documented gain/offset rule (docs/wall-file.md, "Colour matching"): the gain to 1/2^32,
// in * gain rounded half up, plus the offset, clamped to a byte.
int by_gain(int in, double gain, int offset) {
  const long long g = std::llround(std::ldexp(gain, 32));
  return std::clamp(static_cast<int>((in * g + (1LL << 31)) >> 32) + offset, 0, 255);
}
// The test's own table file: an inverted red, halved green, blue as it is.
int by_table(int in, int channel) {
  return channel == 0 ? 255 - in : channel == 1 ? in / 2 : in;
}

// The example wall's text, its colour list either as written with the test's table file in
// place of the example's, or left out.
std::string wall_text(bool colour, const fs::path& table) {
  std::ifstream in(fs::path(L2_SOURCE_DIR) / "walls" / "colour-matched-2x2.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto begin = text.find("colour = [");
  const auto end = text.find("]\n", text.find("{},\n]", begin)) + 2;
  EXPECT_NE(begin, std::string::npos);
  if (!colour) return text.erase(begin, end - begin);
  const std::string example = "lut = \"calibration/panel-2.txt\"";
  return text.replace(text.find(example), example.size(),
                      fmt::format("lut = \"{}\"", table.string()));
}

RgbImage frame_of(const WallRun& run, int display, const std::string& suffix = "") {
  return read_png(run.out() / "frame-9" / fmt::format("display-{}{}.png", display, suffix));
}

TEST(LiveRunColour, ShownDisplaysAreTheUncorrectedOnesThroughTheirTables) {
  const ScratchDir dir("colour-walls");
  std::string table = "# R G B for inputs 0..255\n";
  for (int i = 0; i < 256; ++i)
    table += fmt::format("{} {} {}\n", by_table(i, 0), by_table(i, 1), by_table(i, 2));
  std::ofstream(dir / "table.txt") << table;
  std::ofstream(dir / "colour.toml") << wall_text(true, dir / "table.txt");
  std::ofstream(dir / "plain.toml") << wall_text(false, {});

  const std::vector<std::string> args = {"--frames", "10",   "--refresh", "0",
                                         "--path",   "both", "--compare"};
  std::vector<std::string> colour_args = {"--wall", (dir / "colour.toml").string()};
  std::vector<std::string> plain_args = {"--wall", (dir / "plain.toml").string()};
  colour_args.insert(colour_args.end(), args.begin(), args.end());
  plain_args.insert(plain_args.end(), args.begin(), args.end());
  WallRun colour("colour-on", colour_args);
  ASSERT_TRUE(colour.wait(60s).ok()) << colour.output();
  WallRun plain("colour-off", plain_args);
  ASSERT_TRUE(plain.wait(60s).ok()) << plain.output();
  EXPECT_NE(colour.output().find("compare: 40 display pictures identical byte for byte"),
            std::string::npos)
      << colour.output();

  const double gain[3] = {1.0, 0.96, 0.92};
  const int offset[3] = {0, 0, 4};
  for (int d = 0; d < 4; ++d) {
    const RgbImage raw = frame_of(plain, d);
    const RgbImage shown = frame_of(colour, d);
    ASSERT_EQ(shown.width(), raw.width());
    ASSERT_EQ(shown.height(), raw.height());
    std::size_t wrong = 0, changed = 0;
    const std::size_t bytes = raw.stride() * static_cast<std::size_t>(raw.height());
    for (std::size_t i = 0; i < bytes; ++i) {
      const int in = raw.data()[i], channel = static_cast<int>(i % 3);
      const int expected = d == 0   ? by_gain(in, gain[channel], offset[channel])
                           : d == 2 ? by_table(in, channel)
                                    : in;
      wrong += shown.data()[i] != expected;
      changed += shown.data()[i] != in;
    }
    EXPECT_EQ(wrong, 0u) << "display " << d;
    // The bunny's frame is not all black: the tables did change pixels where they should.
    if (d == 0 || d == 2) {
      EXPECT_GT(changed, bytes / 4) << "display " << d;
    }
    // The vizserver path kept the same matched bytes.
    EXPECT_EQ(frame_of(colour, d, "-vizserver"), shown) << "display " << d;
  }
  expect_clean(colour);
  expect_clean(plain);
}

}  // namespace
}  // namespace l2
