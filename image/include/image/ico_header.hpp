// An ICO's image that is a bitmap (a BITMAPINFOHEADER, its palette, then the colour and mask
// rows), checked before OpenImageIO's ICO reader opens the file. The reader takes the bits a
// pixel from the bitmap's header but the sides and the palette's size from the image's directory
// entry, and trusts both: a header of a bit depth and size no icon has corrupted the heap
// (fuzz_picture_file's: 2304 header bytes, 1 bit a pixel, 16,778,241 pixels wide, 2048 planes;
// `strip_headers dump` aborted in free()); it writes the transparency mask 8 pixels at a time,
// past the end of its buffer unless the width is a multiple of 8 (a well-formed 12x12 icon of 4
// bits a pixel aborted dump: "double free or corruption"; found by fuzz_picture_file as a 4x4
// one); and it looks colours up in a palette of the entry's size by any value the bits hold.
// Pure: the bytes are the caller's.
#pragma once

#include <cstdint>
#include <string_view>

#include "base/result.hpp"

namespace l2::png_codec {

// `entry`: the image's 16-byte directory entry; `header`: the 40 bytes at its `offset` in a
// file of `file_size` bytes. Only what the format has: a 40-byte header, one plane, 1, 4, 8, 16,
// 24 or 32 bits a pixel, no compression, sides of 1 to 256 (the height counts colour and mask
// rows), a palette within its bits, rows within the file; and what the reader can read: below 32
// bits a pixel (those with a mask) an entry's width that is a multiple of 8, and at most 8 bits
// a pixel an entry's colours of 0 (256) or all the bits can index. Failure: "a bitmap ...", what
// the image declares.
Status check_ico_bitmap(std::string_view entry, std::string_view header, std::uint64_t offset,
                        std::uintmax_t file_size);

}  // namespace l2::png_codec
