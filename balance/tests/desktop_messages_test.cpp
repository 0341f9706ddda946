#include "balance/desktop_messages.hpp"

#include <gtest/gtest.h>

namespace l2 {
namespace {

TEST(DesktopMessages, HeaderRoundTrip) {
  const DesktopMessage m{7, 1300, 980, {{0, 0, 256, 256}, {640, 480, 20, 30}}, 3};
  const std::string line = encode(m);
  EXPECT_EQ(line, "DESKTOP 7 1300 980 2 0 0 256 256 640 480 20 30 3");
  const DesktopMessage d = decode_desktop(line);
  EXPECT_EQ(d.frame, 7);
  EXPECT_EQ(d.width, 1300);
  EXPECT_EQ(d.height, 980);
  EXPECT_EQ(d.regions, m.regions);
  EXPECT_EQ(d.rects, 3);
  EXPECT_THROW(decode_desktop("DESKTOP 7 1300 980 1 0 0 0 5 0"), ControlError);  // no width
  EXPECT_THROW(decode_desktop("DESKTOP 7 1300 980 0 0 9"), ControlError);        // a word more
  EXPECT_THROW(decode_desktop("WINDOWS 7 0"), ControlError);
}

TEST(DesktopMessages, RectCarriesItsPixelsExactly) {
  // A 5x3 rectangle out of a 9-pixel-wide picture: every byte distinct, rows apart by stride.
  std::vector<std::uint8_t> picture(9 * 4 * 3);
  for (std::size_t i = 0; i < picture.size(); ++i) picture[i] = static_cast<std::uint8_t>(i * 7);
  const Rect r{2, 1, 5, 3};
  const std::string line = encode_desktop_rect(r, picture.data() + (1 * 9 + 2) * 3, 9 * 3);
  EXPECT_EQ(line.rfind("RECT 2 1 5 3 ", 0), 0u);
  const DesktopRect d = decode_desktop_rect(line);
  EXPECT_EQ(d.rect, r);
  ASSERT_EQ(d.rgb.size(), 5u * 3 * 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 15; ++x)
      EXPECT_EQ(d.rgb[y * 15 + x], picture[(1 + y) * 27 + 6 + x]) << y << "," << x;
}

TEST(DesktopMessages, DamagedRectRefused) {
  std::vector<std::uint8_t> px(4 * 4 * 3, 9);
  const std::string line = encode_desktop_rect({0, 0, 4, 4}, px.data(), 12);
  // The same pixels claimed for a larger rectangle, and pixels that are not base64.
  std::string larger = line;
  larger.replace(0, 12, "RECT 0 0 4 5");
  EXPECT_THROW(decode_desktop_rect(larger), ControlError);
  EXPECT_THROW(decode_desktop_rect("RECT 0 0 4 4 ab!d"), ControlError);
  EXPECT_THROW(decode_desktop_rect("RECT 0 0 4 4 abc"), ControlError);
}

TEST(DesktopMessages, BandsCoverTheRectInLinesThatFit) {
  const Rect r{10, 20, 4000, 1000};  // 12 MB of pixels
  const std::vector<Rect> bands = desktop_bands(r);
  int y = r.y;
  for (const Rect& b : bands) {
    EXPECT_EQ(b.x, r.x);
    EXPECT_EQ(b.w, r.w);
    EXPECT_EQ(b.y, y);
    EXPECT_LE(static_cast<std::size_t>(b.area()) * 3, kMaxDesktopRectBytes);
    y += b.h;
  }
  EXPECT_EQ(y, r.bottom());
  EXPECT_EQ(desktop_bands({0, 0, 8, 8}).size(), 1u);
}

}  // namespace
}  // namespace l2
