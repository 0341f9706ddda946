#include "image/declared_size.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "byte_fields.hpp"

namespace l2::png_codec {

namespace {

// Megabytes rounded up, as text: any size a header can declare, never converted to an integer.
std::string mib(double bytes) {
  return fmt::format("{:.0f} MiB", std::ceil(bytes / (1 << 20)));
}

// A DDS (Microsoft's header: "DDS ", then 124 bytes): levels beyond the halvings of its larger
// side cannot exist, and every level holds at least one byte.
Status check_dds(std::string_view b, std::uintmax_t file_size) {
  if (b.size() < 128) return {};
  const std::uint32_t height = le(b, 12, 4), width = le(b, 16, 4), levels = le(b, 28, 4);
  const std::uint32_t largest = std::max(width, height);
  int possible = 1;
  for (std::uint32_t side = largest; side > 1; side /= 2) ++possible;
  if (levels > static_cast<std::uint32_t>(possible) || levels > file_size) {
    return Failure{"cannot read: a DDS of " + std::to_string(width) + "x" + std::to_string(height) +
                   " declaring " + std::to_string(levels) +
                   " mipmap levels, more than its sides (" + std::to_string(possible) +
                   ") or its " + std::to_string(file_size) + " bytes allow"};
  }
  // Uncompressed pixels (no FOURCC) are unpacked by the bit masks of the channels the reader
  // takes from the flags: luminance (then alpha, with ALPHAPIXELS), alpha alone (then the green
  // mask's channel), else red, green and blue whatever flag RGB says (then alpha). It spreads a
  // channel's bits over a byte in steps of its mask's width: a mask of zero never ends (found by
  // fuzz_picture_file: an 8x8 RGB DDS of 194 bytes whose green mask is zero, and one of 212
  // bytes flagged alpha alone whose alpha mask is zero, held their readers for good).
  const std::uint32_t flags = le(b, 80, 4);
  // (Without FOURCC and without any of RGB, LUMINANCE, ALPHAPIXELS and alpha alone, the reader
  // refuses the file itself.)
  if ((flags & 0x4) == 0 && (flags & (0x40 | 0x20000 | 0x1 | 0x2)) != 0) {
    struct Channel {
      std::size_t at;
      const char* name;
    };
    std::vector<Channel> used;
    if ((flags & 0x20000) != 0) {
      used = {{92, "luminance"}, {104, "alpha"}};
    } else if ((flags & 0x2) != 0) {
      used = {{104, "alpha"}, {96, "green"}};
    } else {
      used = {{92, "red"}, {96, "green"}, {100, "blue"}, {104, "alpha"}};
    }
    if ((flags & 0x1) == 0) used.pop_back();  // no ALPHAPIXELS: not the last one
    // Its bytes a pixel come from the bit count, which the reader checks only where RGB,
    // LUMINANCE, YUV or alpha alone is flagged: ALPHAPIXELS alone with a count of 4227792896 had
    // it ask for 2 GB for a row of 20 pixels (found by fuzz_picture_file).
    if (const std::uint32_t bits = le(b, 88, 4);
        bits != 8 && bits != 16 && bits != 24 && bits != 32) {
      return Failure{"cannot read: an uncompressed DDS of " + std::to_string(bits) +
                     " bits a pixel (the format has 8, 16, 24 or 32)"};
    }
    for (const Channel& c : used) {
      if (le(b, c.at, 4) == 0) {
        return Failure{std::string("cannot read: a DDS whose ") + c.name +
                       " bit mask is zero, no channel its reader can unpack"};
      }
    }
  }
  return {};
}

// Whether a JPEG's frame is progressive (SOF2, SOF6, SOF10, SOF14): its markers up to the first
// frame header, each marker's length skipped.
bool jpeg_progressive(std::string_view b) {
  std::size_t at = 2;
  while (at + 4 <= b.size() && static_cast<unsigned char>(b[at]) == 0xFF) {
    const unsigned char m = static_cast<unsigned char>(b[at + 1]);
    if (m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC)
      return m == 0xC2 || m == 0xC6 || m == 0xCA || m == 0xCE;
    const std::size_t length =
        static_cast<unsigned char>(b[at + 2]) << 8 | static_cast<unsigned char>(b[at + 3]);
    at += 2 + length;
  }
  return false;
}

// A GIF's logical screen (its reader allocates it on opening, before any check of ours): its
// sides against what the file's LZW data can hold.
Status check_gif(std::string_view b, std::uintmax_t file_size) {
  if (b.size() < 10) return {};
  const auto le16 = [&](std::size_t at) {
    return static_cast<long long>(static_cast<unsigned char>(b[at]) |
                                  static_cast<unsigned char>(b[at + 1]) << 8);
  };
  Declared d;
  d.format = "gif";
  d.width = le16(6);
  d.height = le16(8);
  d.channels = 4;
  d.decoded_whole = true;  // the screen is allocated as the file is opened, whoever reads it
  return check_declared(d, file_size);
}

// An SGI image's header (big-endian: magic 474, storage, bytes per channel, dimension, sides):
// its reader trusts the storage and sample size it finds, and one of 0 bytes a channel crashed
// it as it read a row (found by fuzz_picture_file). The format has verbatim or RLE storage, 1 or
// 2 bytes a channel and 1 to 3 dimensions; anything else is no SGI image.
Status check_sgi(std::string_view b) {
  if (b.size() < 12) return {};
  const auto byte = [&](std::size_t at) { return static_cast<unsigned char>(b[at]); };
  const unsigned storage = byte(2), bpc = byte(3), dimension = byte(4) << 8 | byte(5);
  if (storage > 1) {
    return Failure{"cannot read: an SGI image of storage " + std::to_string(storage) +
                   " (the format has 0, verbatim, and 1, RLE)"};
  }
  if (bpc != 1 && bpc != 2) {
    return Failure{"cannot read: an SGI image of " + std::to_string(bpc) +
                   " bytes a channel (the format has 1 or 2)"};
  }
  if (dimension < 1 || dimension > 3) {
    return Failure{"cannot read: an SGI image of dimension " + std::to_string(dimension) +
                   " (the format has 1 to 3)"};
  }
  return {};
}

bool is(std::string_view a, std::initializer_list<std::string_view> names) {
  return std::find(names.begin(), names.end(), a) != names.end();
}

}  // namespace

Result<HeaderFacts> check_header(std::string_view b, std::uintmax_t file_size) {
  HeaderFacts facts;
  if (b.substr(0, 4) == "DDS ") {
    if (const Status s = check_dds(b, file_size); !s.ok()) return Failure{s.reason()};
  }
  // giflib takes any file starting "GIF" (a version of "8JJ" too: the fuzzer's 57 bytes of
  // 19018x19018 asked for 1.4 GB).
  if (b.substr(0, 3) == "GIF") {
    if (const Status s = check_gif(b, file_size); !s.ok()) return Failure{s.reason()};
  }
  if (b.substr(0, 2) == "\x01\xDA") {
    if (const Status s = check_sgi(b); !s.ok()) return Failure{s.reason()};
  }
  if (b.size() >= 3 && b.substr(0, 3) == "\xFF\xD8\xFF") facts.decoded_whole = jpeg_progressive(b);
  return facts;
}

bool decoded_whole_by(std::string_view format) {
  return is(format, {"ico", "gif", "targa", "iff", "webp", "heif", "jpeg2000"});
}

double max_expansion(std::string_view format, std::string_view compression) {
  // Raw samples: a bit a pixel (PBM, 1-bit BMP or TIFF) spread to a byte per channel is the most.
  if (is(format, {"pnm", "fits", "pfm"})) return 8;
  if (format == "bmp") return 400;    // RLE8: 255 pixels in 2 bytes, 3 bytes each decoded
  if (format == "hdr") return 200;    // a run of 127 of one channel in 2 bytes, as 4-byte floats
  if (format == "targa") return 512;  // a run of 128 pixels in 1 + 1 bytes, 4 bytes each
  if (format == "dds") return 64;     // block-compressed: 4 bits a pixel at least, RGBA floats
  if (format == "gif") return 12000;  // LZW: 4096 pixels for a 12-bit code, 4 bytes each
  if (format == "tiff" && (compression.empty() || compression == "none")) return 64;
  if (format == "tiff" && compression == "packbits") return 520;
  // Deflate and LZW reach about 1000 to 1, JPEG's all-zero blocks a few thousand: what is left
  // is bounded by a generous figure rather than trusted.
  return 20000;
}

Status check_declared(const Declared& d, std::uintmax_t file_size) {
  // A reader's numbers as it declared them: none below one, no more channels or bytes to one
  // than any format has.
  if (d.width < 1 || d.height < 1 || d.depth < 1 || d.channels < 1 || d.channels > 64 ||
      d.bytes_per_channel < 1 || d.bytes_per_channel > 8) {
    return Failure{"cannot read: declares " + std::to_string(d.width) + "x" +
                   std::to_string(d.height) + "x" + std::to_string(d.depth) + " pixels of " +
                   std::to_string(d.channels) + " channels of " +
                   std::to_string(d.bytes_per_channel) + " bytes, not a picture"};
  }
  if (d.tile_width < 0 || (d.tile_width > 0 && (d.tile_height < 1 || d.tile_depth < 1))) {
    return Failure{"cannot read: declares tiles of " + std::to_string(d.tile_width) + "x" +
                   std::to_string(d.tile_height) + "x" + std::to_string(d.tile_depth) +
                   " pixels, not a tiling"};
  }
  const std::string sides = std::to_string(d.width) + "x" + std::to_string(d.height) +
                            (d.depth > 1 ? "x" + std::to_string(d.depth) : "");
  if (d.width > kMaxDeclaredSide || d.height > kMaxDeclaredSide || d.depth > kMaxDeclaredSide ||
      double(d.width) * double(d.height) * double(d.depth) > double(kMaxDeclaredPixels)) {
    return Failure{"cannot read: declares " + sides + " pixels, more than any wall shows (up to " +
                   std::to_string(kMaxDeclaredSide) + " a side, " +
                   std::to_string(kMaxDeclaredPixels >> 30) + " gigapixels)"};
  }
  const double decoded = double(d.width) * double(d.height) * double(d.depth) * d.channels *
                         std::max(d.bytes_per_channel, 1);
  const double holds = double(file_size) * max_expansion(d.format, d.compression) + 65536;
  if (decoded > holds) {
    return Failure{"cannot read: declares " + sides + " pixels of " + std::to_string(d.channels) +
                   " channels (" + mib(decoded) + " decoded), more than a " + d.format +
                   " file of " + std::to_string(file_size) + " bytes can hold"};
  }
  const double tile = double(d.tile_width) * double(d.tile_height) * double(d.tile_depth) *
                      d.channels * std::max(d.bytes_per_channel, 1);
  if (tile > kMaxTileMegabytes * (1 << 20)) {
    return Failure{"cannot read: tiles of " + std::to_string(d.tile_width) + "x" +
                   std::to_string(d.tile_height) + " pixels (" + mib(tile) +
                   " each), more than the " + std::to_string(int(kMaxTileMegabytes)) +
                   " MiB a reader holds"};
  }
  if (d.decoded_whole && decoded > kMaxWholeMegabytes * (1 << 20)) {
    const bool jpeg = d.format == "jpeg";
    return Failure{"cannot read: a " + std::string(jpeg ? "progressive " : "") + d.format + " of " +
                   sides + " pixels is decoded whole, " + mib(decoded) + ", more than the " +
                   std::to_string(int(kMaxWholeMegabytes)) +
                   " MiB a picture read whole may take; save it as " +
                   (jpeg ? "baseline" : "a tiled TIFF")};
  }
  return {};
}

}  // namespace l2::png_codec
