// The checks of declared_size.hpp and tiff_header.hpp as the module's two readers make them
// (png_codec_oiio.cpp reads a picture whole, regions_oiio.cpp a part at a time through the image
// cache): on the file's bytes before OpenImageIO opens it, and on what its reader declares once
// open, before any pixel is decoded.
#pragma once

#include <OpenImageIO/imageio.h>

#include <cstdint>

#include "image/declared_size.hpp"
#include "image/exr_header.hpp"
#include "image/sgi_header.hpp"
#include "image/tiff_header.hpp"

namespace l2::png_codec {

// A picture's bytes, in a file or in memory, read where the checks need them.
struct PictureBytes {
  ReadAt read;
  std::uintmax_t size = 0;
};
PictureBytes file_bytes(const char* path);
PictureBytes memory_bytes(const std::uint8_t* bytes, std::size_t size);

// What the first bytes declare (check_header), a TIFF's directories (check_tiff) and an ICO's
// PNG images (their headers, the first one's rows: libpng, not OpenImageIO's ICO reader), an
// OpenEXR file's header attributes (check_exr), an SGI image's RLE tables and rows
// (check_sgi_rle), a FITS file's image headers (check_fits).
Result<HeaderFacts> check_before_open(const PictureBytes& bytes);

// What the opened reader declares (check_declared). `cached`: the image cache will read it, so a
// picture its reader decodes whole (a progressive JPEG, `progressive`, or a format
// decoded_whole_by names) is bounded too; a whole read's size is its caller's to bound.
Status check_opened(const OIIO_NAMESPACE::ImageInput& in, std::uintmax_t file_size, bool cached,
                    bool progressive);

}  // namespace l2::png_codec
