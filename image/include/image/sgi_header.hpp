// An SGI image's RLE tables and rows, walked before OpenImageIO opens it. Its reader sizes the
// tables by the header's ysize x zsize but indexes them by the rows and channels the dimension
// gives (one row of one channel in 145 bytes, its tables empty, crashed it at the first row:
// found by fuzz_picture_file), takes every offset and length as the table says, and decodes a
// row's runs without counting them against the row's width or its bytes. Pure: the bytes come
// through a function.
#pragma once

#include <cstdint>

#include "base/result.hpp"
#include "image/tiff_header.hpp"

namespace l2::png_codec {

// Nothing when the bytes are no SGI image of RLE storage (magic 474, storage 1); otherwise the
// tables must hold every row of every channel and lie in the file, each row's bytes in the file,
// and each row's runs within its bytes and the image's width, as the reader decodes them.
// Failure: one line saying what the file declares.
Status check_sgi_rle(const ReadAt& read, std::uintmax_t file_size);

}  // namespace l2::png_codec
