// PNG through libpng itself (png_read_libpng.cpp, png_encode.cpp: the object library
// l2_png_libpng), built into both sides of the codec module's boundary (png_codec.hpp): programs
// read and write PNG files with it directly, without loading the module (libpng is one small
// library; OpenImageIO's hundreds are what cost), and the module's readers share its stream, its
// check on the size a file's header claims, and its PNG reader, to which png_codec_oiio.cpp hands
// PNG files before OpenImageIO reads anything else.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "png_codec.hpp"

namespace l2::png_codec {

// Where a picture's bytes are: a file, or memory (a texture embedded in a model file).
struct Input {
  const char* path = nullptr;           // the file; null: the picture is in memory
  const std::uint8_t* bytes = nullptr;  // in memory, `size` bytes
  std::size_t size = 0;
  const char* format_hint = "";  // memory: the format when the first bytes do not say ("tga")
  bool in_memory() const { return path == nullptr; }
};

// The input as a stdio stream, for libpng and the signature checks; null (errno set) when it
// cannot be opened.
using Stream = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;
Stream open_stream(const Input& input);

// The check every reader makes on the size a file's header claims, before anything is allocated
// for the pixels: nothing when the picture may be read, otherwise the reason (empty when the
// caller refused it: it says why itself). The caller is asked first, so that a bound of its own
// tighter than ours (a model's texture) names the picture whatever the size claimed.
std::optional<std::string> refusal(const RgbSink& sink, long width, long height);
// refusal()'s reason as a Status: a size the caller refused is no failure of ours.
Status refused(const std::string& why);

// Whether `file` begins with PNG's signature; rewound either way.
bool is_png(std::FILE* file);
// A PNG file (`file`, still the caller's) into the sink as 8-bit RGB, as Codec::read_rgb says.
Status read_png(std::FILE* file, RgbSink sink, Source& source);

// A PNG's pixels decoded with libpng, a row at a time and dropped, before the image cache reads
// it: ok, or why not in one line ("cannot read: a damaged PNG (IDAT: incorrect data check)"),
// nothing printed.
Status check_png_data(const char* path);
// The same for a PNG in memory (an icon's), its rows decoded only with `rows`.
Status check_png_bytes(std::string_view bytes, bool rows);

// A PNG file's bytes, appended to *out: 8-bit RGB (`channels` 3) or grey (1), `pixels` row by
// row (png_encode.cpp).
Status encode_pixels(int width, int height, int channels, const std::uint8_t* pixels,
                     std::string* out);

}  // namespace l2::png_codec
