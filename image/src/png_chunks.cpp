#include "png_chunks.hpp"

#include <sys/stat.h>

#include <cstdio>
#include <cstring>
#include <memory>

namespace l2::png_codec {

namespace {

// Deflate turns no input into more than 1032 times its size (a 258-byte match in under 2 bits):
// image data this much smaller than the pixels cannot hold them.
constexpr double kMostInflation = 1032;

std::uint32_t big_endian(const unsigned char* b) {
  return std::uint32_t{b[0]} << 24 | std::uint32_t{b[1]} << 16 | std::uint32_t{b[2]} << 8 | b[3];
}

int channels(int colour_type) {
  switch (colour_type) {
    case 2:
      return 3;  // RGB
    case 4:
      return 2;  // grey and alpha
    case 6:
      return 4;  // RGBA
    default:
      return 1;  // grey, palette
  }
}

const Failure kTruncated{"cannot read: the PNG file ends early (truncated)"};

}  // namespace

double PngLayout::decoded_bytes() const {
  return double(width) * height * channels(colour_type) * bit_depth / 8;
}

Result<PngLayout> png_layout(const char* path) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path, "rb"), std::fclose);
  struct stat status {};
  if (!file || ::fstat(::fileno(file.get()), &status) != 0) return Failure{"cannot read"};
  const auto size = static_cast<std::uint64_t>(status.st_size);
  // Its first four bytes say PNG (is_png): the rest of the signature damaged is libpng's words.
  unsigned char signature[8] = {};
  if (std::fread(signature, 1, 8, file.get()) == 8 &&
      std::memcmp(signature, "\x89PNG\r\n\x1a\n", 8) != 0) {
    return Failure{"cannot read: a damaged PNG (PNG file corrupted by ASCII conversion)"};
  }
  PngLayout layout;
  bool header = false, idat_ended = false, end = false;
  for (std::uint64_t at = 8; at < size;) {
    unsigned char head[8];
    if (std::fseek(file.get(), static_cast<long>(at), SEEK_SET) != 0 ||
        std::fread(head, 1, 8, file.get()) != 8) {
      return idat_ended ? Result<PngLayout>(layout) : kTruncated;
    }
    const std::uint32_t length = big_endian(head);
    const bool idat = std::memcmp(head + 4, "IDAT", 4) == 0;
    // Cut short inside a chunk before the last pixel: the reader runs out of image data.
    if (at + 12 + length > size) return idat_ended ? Result<PngLayout>(layout) : kTruncated;
    if (!header) {
      unsigned char ihdr[13];
      if (std::memcmp(head + 4, "IHDR", 4) != 0 || length != 13 ||
          std::fread(ihdr, 1, 13, file.get()) != 13) {
        return Failure{"cannot read: a damaged PNG (no IHDR chunk first)"};
      }
      layout.width = big_endian(ihdr);
      layout.height = big_endian(ihdr + 4);
      layout.bit_depth = ihdr[8];
      layout.colour_type = ihdr[9];
      layout.interlaced = ihdr[12] != 0;
      header = true;
    }
    if (idat) layout.image_data += length;
    idat_ended = idat_ended || (!idat && layout.image_data > 0);
    end = std::memcmp(head + 4, "IEND", 4) == 0;
    if (end) break;
    at += 12 + std::uint64_t{length};
  }
  if (!header || (!end && !idat_ended)) return kTruncated;  // it stops at a chunk's end
  if (layout.decoded_bytes() > kMostInflation * (double(layout.image_data) + 1)) {
    return Failure{"cannot read: a PNG of " + std::to_string(layout.width) + "x" +
                   std::to_string(layout.height) + " pixels whose image data, " +
                   std::to_string(layout.image_data) +
                   " bytes, is too little to hold them (cut short or damaged)"};
  }
  return layout;
}

}  // namespace l2::png_codec
