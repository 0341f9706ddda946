// A FITS file's image headers, walked before OpenImageIO opens it. Its reader takes every block
// of 2880 bytes that begins "SIMPLE" or "XTENSION= 'IMAGE   '" for an image (the image cache
// reads the header of each as it opens the file), reads each header's cards until END, block
// after block, and sizes its list of axes by the NAXIS card's value: a NAXIS of 7777...7 (the
// reader clamps it to 2^31-1) asked for 8 GB (found by fuzz_picture_file). Pure: the bytes come
// through a function.
#pragma once

#include <cstdint>

#include "base/result.hpp"
#include "image/tiff_header.hpp"

namespace l2::png_codec {

// Nothing when the bytes are no FITS file (they begin otherwise than "SIMPLE"). Otherwise at
// most kMaxFitsImages image headers, each ending (END) within kMaxFitsHeaderBlocks blocks where
// the file holds them, each NAXIS of 0 to 999 (the format's range). Failure: one line saying
// what the file declares.
inline constexpr int kMaxFitsImages = 256;
inline constexpr int kMaxFitsHeaderBlocks = 64;
Status check_fits(const ReadAt& read, std::uintmax_t file_size);

}  // namespace l2::png_codec
