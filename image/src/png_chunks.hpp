// A PNG file's chunks walked by their lengths, before OpenImageIO's image cache reads it. The
// cache trusted the header: a 69-byte PNG claiming 100000x100000 pixels was read row by row until
// libpng said "Not enough image data" (printed on stderr by libpng, a line before ours), one cut
// short likewise, and an interlaced one, which the cache reads whole, aborted the process on the
// cache's own assertion.
#pragma once

#include <cstdint>
#include <string>

#include "base/result.hpp"

namespace l2::png_codec {

struct PngLayout {
  std::uint32_t width = 0, height = 0;
  int bit_depth = 0, colour_type = 0;
  bool interlaced = false;
  std::uint64_t image_data = 0;  // bytes of all IDAT chunks
  // Bytes the pixels take decoded, as the file stores them (bit depth, channels).
  double decoded_bytes() const;
};

// The layout of the PNG at `path`, or why it cannot be read ("cannot read: the PNG file ends
// early (truncated)", "cannot read: a PNG of 100000x100000 pixels whose image data, 12 bytes, is
// too little to hold them (cut short or damaged)"). Only the chunks' lengths are read, not their
// contents: a file whose data is damaged is found by the reader.
Result<PngLayout> png_layout(const char* path);

}  // namespace l2::png_codec
