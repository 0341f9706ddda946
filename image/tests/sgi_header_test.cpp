// An SGI image's RLE tables and rows against what its reader indexes and decodes
// (sgi_header.hpp): files built here byte by byte, each figure in the expectations worked out
// from the bytes by hand.
#include "image/sgi_header.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace l2::png_codec {
namespace {

std::string sgi16(unsigned v) {
  return {static_cast<char>(v >> 8), static_cast<char>(v)};
}
std::string sgi32(std::uint32_t v) {
  return sgi16(v >> 16) + sgi16(v & 0xFFFF);
}

// A 512-byte header: magic 474, `storage`, `bpc` bytes a channel, `dimension`, the sides.
std::string sgi_header(int storage, int bpc, int dimension, int x, int y, int z) {
  std::string h = sgi16(474) + std::string{char(storage), char(bpc)} + sgi16(dimension) + sgi16(x) +
                  sgi16(y) + sgi16(z);
  h.resize(512, '\0');
  return h;
}

// An RLE image of `rows` (one per row of each channel, in the tables' order), the tables
// sized y x z and their entries pointing at the rows placed after them.
std::string rle_image(int bpc, int dimension, int x, int y, int z,
                      const std::vector<std::string>& rows) {
  const std::size_t entries = static_cast<std::size_t>(y) * z;
  std::string starts, lengths, data;
  std::uint32_t at = static_cast<std::uint32_t>(512 + 8 * entries);
  for (std::size_t e = 0; e < entries; ++e) {
    const std::string row = e < rows.size() ? rows[e] : std::string("\0", 1);
    starts += sgi32(at);
    lengths += sgi32(static_cast<std::uint32_t>(row.size()));
    data += row;
    at += static_cast<std::uint32_t>(row.size());
  }
  return sgi_header(1, bpc, dimension, x, y, z) + starts + lengths + data;
}

Status check_rle(const std::string& file) {
  return check_sgi_rle(
      [&](std::uint64_t at, std::size_t n) {
        return at >= file.size() ? std::string() : file.substr(at, n);
      },
      file.size());
}

// Copy 4 samples, then the end.
const std::string kSgiRow("\x84\x01\x02\x03\x04\x00", 6);

TEST(SgiHeader, WellFormedRleImagesAndOtherFilesPass) {
  EXPECT_TRUE(check_rle(rle_image(1, 3, 4, 2, 3, std::vector<std::string>(6, kSgiRow))).ok());
  // Repeat 3 then copy 1: 4 samples; 2 bytes a channel: counts and samples are words.
  EXPECT_TRUE(check_rle(rle_image(1, 2, 4, 1, 1, {std::string("\x03\x09\x81\x07\x00", 5)})).ok());
  EXPECT_TRUE(
      check_rle(rle_image(2, 1, 2, 1, 1, {std::string("\x00\x82\x00\x01\x00\x02\x00\x00", 8)}))
          .ok());
  // Verbatim storage, another format, a header cut short: not this check's.
  EXPECT_TRUE(check_rle(sgi_header(0, 1, 3, 4, 4, 3) + std::string(48, '\0')).ok());
  EXPECT_TRUE(check_rle("\x89PNG\r\n\x1a\n").ok());
  EXPECT_TRUE(check_rle(std::string("\x01\xda\x01", 3)).ok());
}

TEST(SgiHeader, TablesThatDoNotHoldEveryRowAreRefused) {
  // fuzz_picture_file's finding: dimension 1 (one row of one channel), tables of 43283 x 0.
  const std::string finding =
      sgi_header(1, 1, 1, 256, 43283, 0).substr(0, 12) + std::string(133, 'x');
  EXPECT_EQ(check_rle(finding).reason(),
            "cannot read: an SGI image of 1 row(s) of 1 channel(s) whose RLE tables hold 0 "
            "(43283 x 0)");
  // Dimension 2: ysize rows of one channel; zsize 0 leaves no entries.
  EXPECT_EQ(check_rle(sgi_header(1, 1, 2, 4, 5, 0)).reason(),
            "cannot read: an SGI image of 5 row(s) of 1 channel(s) whose RLE tables hold 0 "
            "(5 x 0)");
  // 4 x 4 x 3 declares 12 entries, 96 bytes of tables, past a file of the header alone.
  EXPECT_EQ(check_rle(sgi_header(1, 1, 3, 4, 4, 3)).reason(),
            "cannot read: an SGI image declaring RLE tables of 12 rows, 96 bytes, past the end "
            "of its 512 bytes");
}

TEST(SgiHeader, RowsOutsideTheFileOrPastTheirWidthAreRefused) {
  std::string file = rle_image(1, 2, 4, 1, 1, {kSgiRow});
  file.replace(512, 4, sgi32(600));  // the row's 6 bytes at 600, in a file of 526
  EXPECT_EQ(check_rle(file).reason(),
            "cannot read: an SGI image whose row 0 is 6 bytes at 600, past the end of its 526 "
            "bytes");
  // Repeat 5 samples in a row 4 wide: the reader wrote past the row.
  EXPECT_EQ(check_rle(rle_image(1, 2, 4, 1, 1, {std::string("\x05\x07\x00", 3)})).reason(),
            "cannot read: an SGI image whose row 0 runs past its 3 bytes or its width of 4");
  // Copy 4 with 2 samples left in the row's bytes; a repeat whose sample is missing; with 2
  // bytes a channel, a count word cut in half.
  EXPECT_FALSE(check_rle(rle_image(1, 2, 4, 1, 1, {std::string("\x84\x01\x02", 3)})).ok());
  EXPECT_FALSE(check_rle(rle_image(1, 2, 4, 1, 1, {std::string("\x03", 1)})).ok());
  EXPECT_FALSE(check_rle(rle_image(2, 2, 4, 1, 1, {std::string("\x00", 1)})).ok());
  // Row 1 of 2 is the bad one.
  EXPECT_EQ(check_rle(rle_image(1, 2, 4, 2, 1, {kSgiRow, std::string("\x7f\x07\x00", 3)})).reason(),
            "cannot read: an SGI image whose row 1 runs past its 3 bytes or its width of 4");
}

}  // namespace
}  // namespace l2::png_codec
