// What the codec module's whole-picture readers share: where a picture's bytes are, the check on
// the size a file's header claims, and the PNG reader on libpng (all in png_read_libpng.cpp)
// that png_codec_oiio.cpp hands PNG files to before OpenImageIO reads anything else.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

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

}  // namespace l2::png_codec
