// An OpenEXR file's headers, walked before OpenImageIO opens it: OpenEXR allocates each
// attribute's value at the size the header declares before reading it, so an attribute of a few
// bytes declaring 1.6 GB was allocated whole (found by fuzz_picture_file). Pure: the bytes come
// through a function.
#pragma once

#include <cstdint>

#include "base/result.hpp"
#include "image/tiff_header.hpp"

namespace l2::png_codec {

// Far more attributes than the headers of any file's parts hold (a part has some twenty).
inline constexpr int kMaxExrAttributes = 65536;

// Nothing when the bytes are no OpenEXR file (its magic number first); otherwise each
// attribute's size against the bytes the file has left, and their count, each field read as
// OpenEXR reads it (a name of up to 255 characters; a longer one runs into the next field). A
// header cut short is left to the reader, which says so. Failure: one line saying what the file
// declares.
Status check_exr(const ReadAt& read, std::uintmax_t file_size);

}  // namespace l2::png_codec
