// Pieces of the codec module (png_codec.hpp) its source files share: the opening of picture
// regions and movies, and OpenImageIO's error text in one line.
#pragma once

#include <string>
#include <string_view>

#include "png_codec.hpp"

namespace l2::png_codec {

// OpenImageIO's error text (several lines, one per complaint) as one line: "a; b".
std::string one_line(const std::string& text);

Result<std::unique_ptr<RegionReader>> open_regions(const char* path,
                                                   float cache_megabytes);  // regions_oiio.cpp
Result<PictureShape> picture_shape(const char* path);                       // regions_oiio.cpp
// picture_shape with a PNG's rows decoded once too (check_png_data).
Result<PictureShape> checked_picture(const char* path);  // regions_oiio.cpp
Status make_tiled_copy(const char* source, const char* target,
                       Progress progress);                           // tiled_copy_oiio.cpp
Result<std::unique_ptr<MovieDecoder>> open_movie(const char* path);  // movie_ffmpeg.cpp
Result<TextMask> render_text(const char* text, int cap_height);      // text_oiio.cpp

}  // namespace l2::png_codec
