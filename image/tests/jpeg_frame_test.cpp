// Shared screens' JPEG frames (jpeg_frame.hpp): real JPEGs made here with libjpeg's encoder are
// decoded to their colours; hostile bytes are refused in one line.
#include "image/jpeg_frame.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "test_jpeg.hpp"

namespace l2 {
namespace {

bool near(std::span<const std::uint8_t> row, int x, int r, int g, int b) {
  const auto at = [&](int c) { return static_cast<int>(row[static_cast<std::size_t>(x) * 3 + c]); };
  return std::abs(at(0) - r) < 12 && std::abs(at(1) - g) < 12 && std::abs(at(2) - b) < 12;
}

TEST(JpegFrame, DecodesTheColoursItWasMadeOf) {
  const Result<RgbImage> frame = decode_jpeg_frame(test::two_halves(64, 32));
  ASSERT_TRUE(frame.ok()) << frame.reason();
  EXPECT_EQ(frame->width(), 64);
  EXPECT_EQ(frame->height(), 32);
  EXPECT_TRUE(near(frame->row(10), 8, 255, 0, 0));
  EXPECT_TRUE(near(frame->row(10), 56, 0, 0, 255));
}

TEST(JpegFrame, RefusesWhatIsNotAJpeg) {
  EXPECT_EQ(decode_jpeg_frame("\x89PNG\r\n").reason(), "not a JPEG (it starts 89 50 4e 47)");
  EXPECT_EQ(decode_jpeg_frame("").reason(), "not a JPEG (it starts nothing)");
}

TEST(JpegFrame, RefusesAFrameCutShort) {
  const std::string whole = test::two_halves(64, 32);
  const Result<RgbImage> cut =
      decode_jpeg_frame(std::string_view(whole).substr(0, whole.size() / 2));
  ASSERT_FALSE(cut.ok());
  EXPECT_EQ(cut.reason().rfind("a damaged JPEG (", 0), 0u) << cut.reason();
  EXPECT_EQ(cut.reason().find('\n'), std::string::npos);
}

TEST(JpegFrame, RefusesGarbageAfterTheStart) {
  const Result<RgbImage> r = decode_jpeg_frame(std::string("\xFF\xD8\xFF") + std::string(200, 'x'));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.reason().rfind("a damaged JPEG (", 0), 0u) << r.reason();
}

// The frame header says 65500x65500: refused before any pixel memory is taken.
TEST(JpegFrame, RefusesADeclaredSizeOverTheLimit) {
  std::string bytes = test::two_halves(16, 16);
  const std::size_t sof = bytes.find("\xFF\xC0");
  ASSERT_NE(sof, std::string::npos);
  bytes[sof + 5] = bytes[sof + 7] = '\xFF';
  bytes[sof + 6] = bytes[sof + 8] = '\xDC';
  EXPECT_EQ(decode_jpeg_frame(bytes).reason(),
            "declares 65500x65500 pixels, more than a shared frame may have (3840x2160)");
  EXPECT_EQ(decode_jpeg_frame(test::two_halves(64, 32), {32, 32, 1 << 20}).reason(),
            "declares 64x32 pixels, more than a shared frame may have (32x32)");
}

TEST(JpegFrame, RefusesTooManyBytes) {
  EXPECT_EQ(decode_jpeg_frame(test::two_halves(16, 16), {3840, 2160, 100})
                    .reason()
                    .find("bytes, more than a shared frame may have (100)") != std::string::npos,
            true);
}

}  // namespace
}  // namespace l2
