// An ICO's bitmap image against what OpenImageIO's ICO reader trusts (ico_header.hpp): entries
// and headers built here field by field (little-endian), each expectation written from the
// fields set.
#include "image/ico_header.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace l2::png_codec {
namespace {

std::string le_bytes(std::uint32_t v, int n) {
  std::string b;
  for (int i = 0; i < n; ++i) b += static_cast<char>((v >> (8 * i)) & 0xFF);
  return b;
}

// A directory entry of `width` x `width` pixels and `colours`.
std::string entry(int width, int colours) {
  return le_bytes(width, 1) + le_bytes(width, 1) + le_bytes(colours, 1) + std::string(13, '\0');
}

// A BITMAPINFOHEADER of `width` x `width` (its height counts colour and mask rows).
std::string header(int width, int bits) {
  return le_bytes(40, 4) + le_bytes(width, 4) + le_bytes(2 * width, 4) + le_bytes(1, 2) +
         le_bytes(bits, 2) + std::string(24, '\0');
}

// Big enough for any image here.
constexpr std::uintmax_t kFile = 1 << 20;

TEST(IcoHeader, BitmapsTheReaderReadsPass) {
  EXPECT_TRUE(check_ico_bitmap(entry(16, 16), header(16, 4), 22, kFile).ok());
  EXPECT_TRUE(check_ico_bitmap(entry(8, 0), header(8, 8), 22, kFile).ok());  // 0: 256
  EXPECT_TRUE(check_ico_bitmap(entry(8, 2), header(8, 1), 22, kFile).ok());
  EXPECT_TRUE(check_ico_bitmap(entry(4, 0), header(4, 32), 22, kFile).ok());  // no mask
}

TEST(IcoHeader, AMaskedBitmapOfAWidthNotAMultipleOfEightIsRefused) {
  EXPECT_EQ(check_ico_bitmap(entry(12, 16), header(12, 4), 22, kFile).reason(),
            "a bitmap of 4 bits a pixel, 12 pixels wide: a transparency mask is read here only "
            "for widths that are multiples of 8 (save the icon at 32 bits a pixel, or as PNG)");
  EXPECT_EQ(check_ico_bitmap(entry(4, 2), header(4, 1), 22, kFile).reason(),
            "a bitmap of 1 bits a pixel, 4 pixels wide: a transparency mask is read here only "
            "for widths that are multiples of 8 (save the icon at 32 bits a pixel, or as PNG)");
  // The entry's width is the reader's, not the header's.
  EXPECT_FALSE(check_ico_bitmap(entry(20, 0), header(24, 24), 22, kFile).ok());
}

TEST(IcoHeader, AnEntrysPaletteSmallerThanTheBitsIndexIsRefused) {
  EXPECT_EQ(check_ico_bitmap(entry(8, 2), header(8, 8), 22, kFile).reason(),
            "a bitmap of 8 bits a pixel whose directory entry says 2 colours, fewer than its "
            "bits index");
  EXPECT_FALSE(check_ico_bitmap(entry(8, 15), header(8, 4), 22, kFile).ok());
  EXPECT_TRUE(check_ico_bitmap(entry(8, 16), header(8, 4), 22, kFile).ok());
}

TEST(IcoHeader, AHeaderOutsideTheFormatIsRefused) {
  std::string h = header(8, 32);
  h.replace(0, 4, le_bytes(2304, 4));
  EXPECT_EQ(check_ico_bitmap(entry(8, 0), h, 22, kFile).reason(),
            "a bitmap header of 2304 bytes, not 40");
  EXPECT_EQ(check_ico_bitmap(entry(8, 0), header(8, 7), 22, kFile).reason(),
            "a bitmap of 7 bits a pixel (an icon has 1, 4, 8, 16, 24 or 32)");
  // 8x8 at 32 bits: 40 + 8 rows of 32 bytes + 8 mask rows of 4 = 328 bytes.
  EXPECT_TRUE(check_ico_bitmap(entry(8, 0), header(8, 32), 22, 22 + 328).ok());
  EXPECT_EQ(check_ico_bitmap(entry(8, 0), header(8, 32), 22, 22 + 327).reason(),
            "a bitmap of 8x8 needing 328 bytes, past the file's end");
}

}  // namespace
}  // namespace l2::png_codec
