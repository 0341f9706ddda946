// An OpenEXR file's header attributes as exr_header.hpp walks them, on bytes laid out here by
// hand: the magic number, the version and its flags, then name, type, size and value per
// attribute, each header ended by an empty name.
#include <gtest/gtest.h>

#include <string>

#include "image/exr_header.hpp"

namespace l2::png_codec {
namespace {

std::string le32(std::uint32_t v) {
  return {static_cast<char>(v), static_cast<char>(v >> 8), static_cast<char>(v >> 16),
          static_cast<char>(v >> 24)};
}

// An attribute declaring `size` bytes of value and holding `value`.
std::string attribute(const std::string& name, const std::string& type, std::uint32_t size,
                      const std::string& value) {
  return name + '\0' + type + '\0' + le32(size) + value;
}

std::string exr(std::uint32_t flags, const std::string& headers) {
  return std::string("\x76\x2f\x31\x01", 4) + le32(2 | flags) + headers;
}

Status check(const std::string& file) {
  return check_exr(
      [&](std::uint64_t at, std::size_t n) {
        return at >= file.size() ? std::string() : file.substr(at, n);
      },
      file.size());
}

TEST(ExrHeader, AttributesWithinTheFilePass) {
  const std::string header = attribute("compression", "compression", 1, std::string(1, '\0')) +
                             attribute("lineOrder", "lineOrder", 1, std::string(1, '\0')) + '\0';
  EXPECT_TRUE(check(exr(0, header + std::string(64, '\0'))).ok());
}

TEST(ExrHeader, AnAttributeLargerThanTheFileIsRefused) {
  // 8 bytes of magic and version, "junk\0" and "opaque\0" (12), the size (4): 24 bytes read,
  // 3 left.
  const std::string file = exr(0, attribute("junk", "opaque", 1677721600, "abc"));
  EXPECT_EQ(check(file).reason(),
            "cannot read: an OpenEXR attribute 'junk' of type 'opaque' declaring 1677721600 bytes, "
            "more than the 3 the file has left");
  EXPECT_EQ(check(exr(0, attribute("junk", "opaque", 0xFFFFFFFF, "abc"))).reason(),
            "cannot read: an OpenEXR attribute 'junk' of type 'opaque' declaring -1 bytes, more "
            "than the 3 the file has left");
}

TEST(ExrHeader, EveryPartOfAMultipartFileIsWalked) {
  const std::string part = attribute("name", "string", 1, "a") + '\0';
  const std::string bad = attribute("name", "string", 1000, "b") + '\0';
  // Flag 0x1000: several parts, the list ended by an empty header.
  EXPECT_TRUE(check(exr(0x1000, part + part + '\0')).ok());
  EXPECT_EQ(check(exr(0x1000, part + bad + '\0')).reason(),
            "cannot read: an OpenEXR attribute 'name' of type 'string' declaring 1000 bytes, more "
            "than the 3 the file has left");
  // A single part ends at its header: what follows is pixel data, not attributes.
  EXPECT_TRUE(check(exr(0, part + bad)).ok());
}

// A data window from (x0, y0) to (x1, y1), both corners in it.
std::string window(std::int32_t x0, std::int32_t y0, std::int32_t x1, std::int32_t y1) {
  return attribute("dataWindow", "box2i", 16,
                   le32(static_cast<std::uint32_t>(x0)) + le32(static_cast<std::uint32_t>(y0)) +
                       le32(static_cast<std::uint32_t>(x1)) + le32(static_cast<std::uint32_t>(y1)));
}

std::string tiles(std::uint32_t width, std::uint32_t height) {
  return attribute("tiles", "tiledesc", 9, le32(width) + le32(height) + std::string(1, '\0'));
}

std::string compression(unsigned char code) {
  return attribute("compression", "compression", 1, std::string(1, static_cast<char>(code)));
}

// `count` channels named A, B, ... of `type` (0 UINT, 1 HALF, 2 FLOAT), each 16 bytes after its
// name, the list ended by an empty name.
std::string channels(int count, std::uint32_t type) {
  std::string list;
  for (int c = 0; c < count; ++c) {
    list += std::string(1, static_cast<char>('A' + c)) + '\0' + le32(type) + std::string(4, '\0') +
            le32(1) + le32(1);
  }
  list += '\0';
  return attribute("channels", "chlist", static_cast<std::uint32_t>(list.size()), list);
}

// OpenEXR allocates a part's offset table, eight bytes a chunk, from its data window as it opens
// the file.
TEST(ExrHeader, ADataWindowWhoseOffsetsAloneOutgrowTheFileIsRefused) {
  // The window's attribute is "dataWindow\0" (11), "box2i\0" (6), the size (4) and 16 bytes:
  // 37. Without a compression, a line a chunk: 2 lines, 16 bytes of offsets, in 8 + 37 + 1 + 8.
  EXPECT_TRUE(check(exr(0, window(0, 0, 1, 1) + '\0' + std::string(8, '\0'))).ok());
  EXPECT_EQ(check(exr(0, window(0, 0, 0, 8191) + '\0' + std::string(100, '\0'))).reason(),
            "cannot read: an OpenEXR data window of 1x8192 pixels in at least 8192 chunks, whose "
            "offsets alone are more than the file's 146 bytes");
  // DWAB puts 256 lines in a chunk: 512 lines are 2 chunks, 16 bytes; as ZIP (16 lines), 32
  // chunks, 256 bytes. The compression's attribute: 12 + 12 + 4 + 1 = 29 bytes; 8 + 37 + 29 + 1
  // + 100 in all.
  EXPECT_TRUE(
      check(exr(0, window(0, 0, 0, 511) + compression(9) + '\0' + std::string(100, '\0'))).ok());
  EXPECT_EQ(
      check(exr(0, window(0, 0, 0, 511) + compression(3) + '\0' + std::string(100, '\0'))).reason(),
      "cannot read: an OpenEXR data window of 1x512 pixels in at least 32 chunks, whose offsets "
      "alone are more than the file's 175 bytes");
  // Tiled: 64x64 pixels in 1x1 tiles, 4096 of them (the tile description "tiles\0" (6),
  // "tiledesc\0" (9), the size and 9 bytes: 28), in 8 + 37 + 28 + 1 + 1000 bytes.
  EXPECT_EQ(
      check(exr(0, window(0, 0, 63, 63) + tiles(1, 1) + '\0' + std::string(1000, '\0'))).reason(),
      "cannot read: an OpenEXR data window of 64x64 pixels in at least 4096 chunks, whose "
      "offsets alone are more than the file's 1074 bytes");
  EXPECT_TRUE(
      check(exr(0, window(0, 0, 63, 63) + tiles(32, 32) + '\0' + std::string(32, '\0'))).ok());
}

// OpenEXR allocates the buffer of a chunk as it opens the file: fuzz_picture_file's 26 half
// channels a million pixels wide, in PIZ's chunks of 32 lines, asked for 1.6 GB.
TEST(ExrHeader, AChunkLargerThanAReaderMayHoldIsRefused) {
  const std::string padding(1 << 12, '\0');
  // 1000000 x 32 x 52 bytes = 1587 MiB.
  EXPECT_EQ(
      check(exr(0, channels(26, 1) + compression(4) + window(0, 0, 999999, 63) + '\0' + padding))
          .reason(),
      "cannot read: an OpenEXR data window of 1000000x64 pixels of 52 bytes each, in chunks "
      "of 1000000x32 (1587 MiB decoded), more than a reader may hold (512 MiB)");
  // Scanlines of none: 1000000 x 1 x 52 bytes is 50 MiB, and 64 chunks fit the padding.
  EXPECT_TRUE(
      check(exr(0, channels(26, 1) + compression(0) + window(0, 0, 999999, 63) + '\0' + padding))
          .ok());
  // Tiles of 16384x16384 of 3 floats: 3072 MiB.
  EXPECT_EQ(
      check(exr(0, channels(3, 2) + window(0, 0, 99, 99) + tiles(16384, 16384) + '\0' + padding))
          .reason(),
      "cannot read: an OpenEXR data window of 100x100 pixels of 12 bytes each, in chunks of "
      "16384x16384 (3072 MiB decoded), more than a reader may hold (512 MiB)");
}

TEST(ExrHeader, ADataWindowBeyondAnyWallIsRefusedWhateverTheFile) {
  EXPECT_EQ(check(exr(0, window(-2000000000, 0, 2000000000, 0) + '\0')).reason(),
            "cannot read: an OpenEXR data window of 4000000001x1 pixels, more than 1048576 a "
            "side");
}

TEST(ExrHeader, TheOffsetsOfEveryPartCountTogether) {
  // Two parts of 8 lines, a line a chunk: 16 chunks, 128 bytes of offsets together. They fit in
  // 8 + 2 * (37 + 1) + 1 + 60 = 145 bytes, not in the same without the 60 bytes after (85).
  const std::string part = window(0, 0, 0, 7) + '\0';
  EXPECT_TRUE(check(exr(0x1000, part + part + '\0' + std::string(60, '\0'))).ok());
  EXPECT_EQ(check(exr(0x1000, part + part + '\0')).reason(),
            "cannot read: an OpenEXR data window of 1x8 pixels in at least 16 chunks, whose "
            "offsets alone are more than the file's 85 bytes");
}

// OpenEXR reads a name of at most 255 characters, with or without the long-names flag, and 256
// bytes of a longer one, the rest read as the next field: a size is found where it finds it
// (fuzz_picture_file found 1.6 GB behind a name of 33 characters, which a walk stopping at 31
// read elsewhere).
TEST(ExrHeader, ALongNameRunsIntoTheNextFieldAsForTheReader) {
  const std::string short_name(33, 'n');
  EXPECT_EQ(check(exr(0, short_name + '\0' + "xx" + '\0' + le32(1000) + "abc")).reason(),
            "cannot read: an OpenEXR attribute '" + short_name +
                "' of type 'xx' declaring 1000 bytes, more than the 3 the file has left");
  // 256 bytes of name, then "xx\0" is the type, then the size: 1000 bytes.
  const std::string name(256, 'n');
  EXPECT_EQ(check(exr(0, name + "xx" + '\0' + le32(1000) + "abc")).reason(),
            "cannot read: an OpenEXR attribute '" + name +
                "' of type 'xx' declaring 1000 bytes, more than the 3 the file has left");
}

// Names are the file's bytes: printed as escapes, the refusal stays one line (the picture-file
// fuzzer found a type holding a PNG signature's line breaks).
TEST(ExrHeader, NamesArePrintedAsEscapes) {
  EXPECT_EQ(check(exr(0, attribute("a\nb", "\x1b[2J", 1000, "abc"))).reason(),
            "cannot read: an OpenEXR attribute 'a\\nb' of type '\\x1b[2J' declaring 1000 bytes, "
            "more than the 3 the file has left");
}

// A type OpenEXR knows is read at its own size, not the one declared: a compression declaring
// 129 bytes is one, and what follows it is the next attribute (the picture-file fuzzer found a
// 1.7 GB one there). A preview's pixels are its width x height x 4 bytes.
TEST(ExrHeader, KnownTypesAreReadAtTheirOwnSize) {
  const std::string file =
      exr(0, attribute("compression", "compression", 129, std::string(1, '\0')) +
                 attribute("junk", "opaque", 1000, "abc"));
  EXPECT_EQ(check(file).reason(),
            "cannot read: an OpenEXR attribute 'junk' of type 'opaque' declaring 1000 bytes, more "
            "than the 3 the file has left");
  EXPECT_EQ(check(exr(0, attribute("preview", "preview", 8, le32(65536) + le32(65536)))).reason(),
            "cannot read: an OpenEXR attribute 'preview' of type 'preview' declaring 17179869192 "
            "bytes, more than the 8 the file has left");
  // Two channels of 16 bytes each after their names, and the list's empty name: 39 bytes.
  const std::string channels = std::string("R\0", 2) + std::string(16, '\0') +
                               std::string("G\0", 2) + std::string(16, '\0') + '\0';
  EXPECT_TRUE(check(exr(0, attribute("channels", "chlist", 7, channels) + '\0')).ok());
}

TEST(ExrHeader, OtherBytesAreNoExr) {
  EXPECT_TRUE(check("P6\n8 8\n255\n").ok());
  EXPECT_TRUE(check("").ok());
}

}  // namespace
}  // namespace l2::png_codec
