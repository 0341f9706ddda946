// What a picture's header declares against what its file can hold (declared_size.hpp): the
// figures worked out by hand here from the format's storage.
#include <gtest/gtest.h>

#include <string>

#include "image/declared_size.hpp"

namespace l2::png_codec {
namespace {

Declared picture(const char* format, long long w, long long h, int channels = 3) {
  Declared d;
  d.format = format;
  d.width = w;
  d.height = h;
  d.channels = channels;
  return d;
}

TEST(DeclaredSize, RawSamplesMustBeInTheFile) {
  // A 1000x1000 RGB TIFF stored uncompressed is 3,000,000 bytes: 64 to 1 (a bit a pixel spread
  // to a byte a channel, with room) lets 46,000 bytes through, not 45,000.
  Declared d = picture("tiff", 1000, 1000);
  d.compression = "none";
  EXPECT_TRUE(check_declared(d, 46000).ok());
  EXPECT_EQ(check_declared(d, 45000).reason(),
            "cannot read: declares 1000x1000 pixels of 3 channels (3 MiB decoded), more than a "
            "tiff file of 45000 bytes can hold");
  d.compression = "lzw";  // a dictionary coder may hold far more
  EXPECT_TRUE(check_declared(d, 45000).ok());
}

TEST(DeclaredSize, TilesLargerThanTheCacheAreRefused) {
  Declared d = picture("tiff", 65536, 65536);
  d.compression = "zip";
  d.tile_width = d.tile_height = 65536;
  EXPECT_EQ(check_declared(d, 1 << 30).reason(),
            "cannot read: tiles of 65536x65536 pixels (12288 MiB each), more than the 64 MiB a "
            "reader holds");
  d.tile_width = d.tile_height = 512;  // 768 KiB a tile
  EXPECT_TRUE(check_declared(d, 1 << 30).ok());
}

TEST(DeclaredSize, AProgressiveJpegIsDecodedWhole) {
  Declared d = picture("jpeg", 20000, 10000);  // 600,000,000 bytes as RGB: 573 MiB, rounded up
  d.decoded_whole = true;
  EXPECT_EQ(check_declared(d, 50000000).reason(),
            "cannot read: a progressive jpeg of 20000x10000 pixels is decoded whole, 573 MiB, "
            "more than the 512 MiB a picture read whole may take; save it as baseline");
  d.decoded_whole = false;
  EXPECT_TRUE(check_declared(d, 50000000).ok());
}

// Readers that decode a picture whole whatever part is asked for (an icon's PNG, a GIF's
// screen) are bounded as a progressive JPEG is; a TIFF, PNG or BMP is read a part at a time.
TEST(DeclaredSize, FormatsDecodedWholeAreBoundedToo) {
  EXPECT_TRUE(decoded_whole_by("ico"));
  EXPECT_TRUE(decoded_whole_by("gif"));
  EXPECT_FALSE(decoded_whole_by("tiff"));
  EXPECT_FALSE(decoded_whole_by("bmp"));
  Declared d = picture("ico", 16384, 16384);  // 805,306,368 bytes: 768 MiB
  d.decoded_whole = true;
  EXPECT_EQ(check_declared(d, 1 << 20).reason(),
            "cannot read: a ico of 16384x16384 pixels is decoded whole, 768 MiB, more than the "
            "512 MiB a picture read whole may take; save it as a tiled TIFF");
}

// giflib reads any file starting "GIF" and allocates its screen on opening, 4 bytes a pixel:
// 57 bytes of "GIF8JJ" declaring 19018x19018 asked for 1.4 GB (fuzz_picture_file). The screen is
// bounded as a picture decoded whole.
TEST(DeclaredSize, AnyGifVersionHasItsScreenChecked) {
  const auto gif = [](const char* version, int side) {
    std::string g = std::string("GIF") + version;
    g += {static_cast<char>(side & 0xFF), static_cast<char>(side >> 8),
          static_cast<char>(side & 0xFF), static_cast<char>(side >> 8)};
    return g;
  };
  // 19018^2 x 4 = 1,446,737,296 bytes: 1380 MiB rounded up.
  EXPECT_EQ(check_header(gif("8JJ", 19018), 57).reason(),
            "cannot read: declares 19018x19018 pixels of 4 channels (1380 MiB decoded), more than "
            "a gif file of 57 bytes can hold");
  EXPECT_EQ(check_header(gif("89a", 16384), 1000000).reason(),
            "cannot read: a gif of 16384x16384 pixels is decoded whole, 1024 MiB, more than the "
            "512 MiB a picture read whole may take; save it as a tiled TIFF");
  EXPECT_TRUE(check_header(gif("89a", 8192), 1000000).ok());  // 256 MiB
}

// A DDS header of `width` x `height`, one level, its pixel format's `flags`; no masks, no bits.
std::string dds_header(char width, char height, char flags) {
  std::string dds(128, '\0');
  dds.replace(0, 4, "DDS ");
  dds[12] = height;
  dds[16] = width;
  dds[28] = 1;
  dds[80] = flags;
  return dds;
}

// An uncompressed DDS's channels are unpacked by bit masks: OpenImageIO's reader shifts a mask
// of zero for ever (fuzz_picture_file's 194-byte 8x8 DDS).
TEST(DeclaredSize, ADdsChannelMaskOfZeroIsRefused) {
  std::string dds = dds_header(8, 8, 0x40);  // RGB: red, green and blue masks
  dds[88] = 24;                              // bits a pixel
  dds[94] = '\xff';
  dds[97] = '\xff';
  dds[100] = '\xff';
  EXPECT_TRUE(check_header(dds, 400).ok());
  dds[97] = 0;  // green: none
  EXPECT_EQ(check_header(dds, 400).reason(),
            "cannot read: a DDS whose green bit mask is zero, no channel its reader can unpack");
  dds[97] = '\xff';
  dds[80] = 0x41;  // and alpha, whose mask is zero
  EXPECT_EQ(check_header(dds, 400).reason(),
            "cannot read: a DDS whose alpha bit mask is zero, no channel its reader can unpack");
  // The reader takes red, green and blue whatever flag RGB says: ALPHAPIXELS alone, with an
  // alpha mask and no colour masks.
  dds[80] = 0x01;
  dds[107] = '\xff';
  dds[94] = 0;
  EXPECT_EQ(check_header(dds, 400).reason(),
            "cannot read: a DDS whose red bit mask is zero, no channel its reader can unpack");
  // Alpha alone (flag 0x2) takes the alpha mask: fuzz_picture_file's 212-byte DDS, flags
  // 0xFFFDFFC2 (RGB among them) and colour masks set, its alpha mask zero.
  dds[80] = '\xc2';
  dds[81] = '\xff';
  dds[82] = '\xfd';
  dds[83] = '\xff';
  dds[94] = '\xff';
  dds[107] = 0;
  EXPECT_EQ(check_header(dds, 400).reason(),
            "cannot read: a DDS whose alpha bit mask is zero, no channel its reader can unpack");
  dds[107] = '\xff';
  EXPECT_TRUE(check_header(dds, 400).ok());
  // Luminance takes the first mask; compressed pixels (FOURCC) none.
  dds[80] = 0;
  dds[81] = 0;
  dds[82] = 0x02;
  dds[83] = 0;
  dds[94] = 0;
  EXPECT_EQ(check_header(dds, 400).reason(),
            "cannot read: a DDS whose luminance bit mask is zero, no channel its reader can "
            "unpack");
  dds[80] = 0x04;
  dds[82] = 0;
  EXPECT_TRUE(check_header(dds, 400).ok());
}

// Its bytes a pixel come from the bit count: fuzz_picture_file's 164-byte DDS, ALPHAPIXELS alone
// and a count of 4227792896 (0xFBFF0000), had OpenImageIO's reader ask for 2 GB.
TEST(DeclaredSize, AnUncompressedDdsOfBitsNoPixelHasIsRefused) {
  std::string dds = dds_header(20, 24, 0x01);  // ALPHAPIXELS alone: all four masks
  for (const int at : {94, 97, 100, 107}) dds[at] = '\xff';
  for (const int bits : {8, 16, 24, 32}) {
    dds[88] = static_cast<char>(bits);
    EXPECT_TRUE(check_header(dds, 400).ok()) << bits;
  }
  dds.replace(88, 4, std::string("\x00\x00\xff\xfb", 4));
  EXPECT_EQ(check_header(dds, 400).reason(),
            "cannot read: an uncompressed DDS of 4227792896 bits a pixel (the format has 8, 16, "
            "24 or 32)");
  dds.replace(88, 4, std::string(4, '\0'));
  EXPECT_FALSE(check_header(dds, 400).ok());
  dds[84] = 4;  // FOURCC: compressed, its pixels' size from the code, not the count
  dds[80] = 0x05;
  EXPECT_TRUE(check_header(dds, 400).ok());
}

// What a reader declares of depth and tiles, as declared: a FITS of three axes naming two has
// depth 0, on which the image cache aborted (fuzz_picture_file).
TEST(DeclaredSize, NoDepthOrTileSideIsRefused) {
  Declared d = picture("fits", 9, 4, 1);
  d.depth = 0;
  EXPECT_EQ(check_declared(d, 2880 * 2).reason(),
            "cannot read: declares 9x4x0 pixels of 1 channels of 1 bytes, not a picture");
  d.depth = 1;
  EXPECT_TRUE(check_declared(d, 2880 * 2).ok());
  d.tile_width = 16;
  d.tile_height = 16;
  d.tile_depth = 0;
  EXPECT_EQ(check_declared(d, 2880 * 2).reason(),
            "cannot read: declares tiles of 16x16x0 pixels, not a tiling");
}

// An SGI header: magic 474 (0x01DA), storage, bytes a channel, dimension (big-endian), sides.
// fuzz_picture_file's 109 bytes of storage 64 and 0 bytes a channel crashed the reader as it
// read a row.
TEST(DeclaredSize, AnSgiHeaderOutsideTheFormatIsRefused) {
  std::string sgi("\x01\xDA\x00\x01\x00\x03\x00\x02\x00\x02\x00\x03", 12);
  sgi.resize(512 + 2 * 2 * 3, '\0');
  EXPECT_TRUE(check_header(sgi, sgi.size()).ok());
  sgi[3] = 2;
  EXPECT_TRUE(check_header(sgi, sgi.size()).ok());
  sgi[3] = 0;
  EXPECT_EQ(check_header(sgi, sgi.size()).reason(),
            "cannot read: an SGI image of 0 bytes a channel (the format has 1 or 2)");
  sgi[3] = 1;
  sgi[2] = 0x40;
  EXPECT_EQ(check_header(sgi, sgi.size()).reason(),
            "cannot read: an SGI image of storage 64 (the format has 0, verbatim, and 1, RLE)");
  sgi[2] = 1;
  EXPECT_TRUE(check_header(sgi, sgi.size()).ok());
  sgi[5] = 4;
  EXPECT_EQ(check_header(sgi, sgi.size()).reason(),
            "cannot read: an SGI image of dimension 4 (the format has 1 to 3)");
}

TEST(DeclaredSize, HeadersBeforeTheReader) {
  // "DDS " and 124 bytes: height at 12, width at 16, levels at 28 (little-endian).
  std::string dds(128, '\0');
  dds.replace(0, 4, "DDS ");
  dds[12] = 64;  // 64x64: levels 64, 32, ..., 1 are 7
  dds[16] = 64;
  dds[28] = 7;
  EXPECT_TRUE(check_header(dds, 20000).ok());
  dds[28] = 8;
  EXPECT_EQ(check_header(dds, 20000).reason(),
            "cannot read: a DDS of 64x64 declaring 8 mipmap levels, more than its sides (7) or "
            "its 20000 bytes allow");
  // A JPEG's first frame marker: SOF2 after an APP0 of 16 bytes is progressive.
  std::string jpeg = std::string("\xFF\xD8\xFF\xE0\x00\x10", 6) + std::string(14, '\0') +
                     std::string("\xFF\xC2\x00\x11", 4);
  EXPECT_TRUE(check_header(jpeg, 1000)->decoded_whole);
  jpeg[21] = '\xC0';
  EXPECT_FALSE(check_header(jpeg, 1000)->decoded_whole);
}

}  // namespace
}  // namespace l2::png_codec
