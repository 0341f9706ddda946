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
