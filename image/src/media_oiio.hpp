// Pieces of the codec module (png_codec.hpp) its source files share: the opening of picture
// regions and movies, and OpenImageIO's error text in one line.
#pragma once

#include <string>
#include <string_view>

#include "png_codec.hpp"

namespace l2::png_codec {

// OpenImageIO's error text (several lines, one per complaint) as one line: "a; b".
std::string one_line(const std::string& text);

// A PNG's pixels decoded with libpng, a row at a time and dropped, before the image cache reads
// it: ok, or why not in one line ("cannot read: a damaged PNG (IDAT: incorrect data check)"),
// nothing printed (png_read_libpng.cpp).
Status check_png_data(const char* path);
// The same for a PNG in memory (an icon's), its rows decoded only with `rows`.
Status check_png_bytes(std::string_view bytes, bool rows);

Result<std::unique_ptr<RegionReader>> open_regions(const char* path,
                                                   float cache_megabytes);  // regions_oiio.cpp
Result<PictureShape> picture_shape(const char* path);                       // regions_oiio.cpp
// picture_shape with a PNG's rows decoded once too (check_png_data).
Result<PictureShape> checked_picture(const char* path);  // regions_oiio.cpp
Status make_tiled_copy(const char* source, const char* target,
                       Progress progress);                           // tiled_copy_oiio.cpp
Result<std::unique_ptr<MovieDecoder>> open_movie(const char* path);  // movie_ffmpeg.cpp
Result<TextMask> render_text(const char* text, int cap_height);      // text_oiio.cpp
Status encode_pixels(int width, int height, int channels, const std::uint8_t* pixels,
                     std::string* out);  // png_encode.cpp

}  // namespace l2::png_codec
