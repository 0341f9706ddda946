// PNG files at the edge of the system, through OpenImageIO (PNG reading: libpng). Errors name
// the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>

#include "image/rgb_image.hpp"

namespace l2 {

// Writes 8-bit RGB PNG (or the format the extension names); creates parent folders. The file is
// written whole or not at all (write_whole_file, image/folders.hpp): a full file system leaves no
// picture cut short under its name. Throws std::runtime_error naming the file and why
// ("out/display-2.png: cannot write: No space left on device").
void write_png(const std::filesystem::path& path, const RgbImage& image);

// The bytes of a PNG file of `image`, as write_png() would write them, for a program that sends
// a picture instead (the control page). Throws std::runtime_error when the codec module cannot
// be loaded.
std::string encode_png(const RgbImage& image);

// The bytes of an 8-bit grey PNG of `grey` (width x height bytes, row by row): the maps a wall
// reads as grey (alpha and beta maps), which RgbImage cannot hold. Throws std::invalid_argument
// when `grey` is not width x height bytes, std::runtime_error as encode_png().
std::string encode_grey_png(int width, int height, std::span<const std::uint8_t> grey);

// The largest side read_png() accepts: every picture the project reads is an input frame
// (8192 at most, the DVI link's limit) or one display (16384 at most, the vizserver's).
inline constexpr int kMaxPictureSide = 16384;

// Reads a PNG (with libpng) or any other 2-D picture OpenImageIO reads. An alpha channel is
// dropped, as a DVI link drops it (spec §1); grey is expanded to RGB; 16 bits become 8. Throws
// std::runtime_error naming the file and why, in one line ("the PNG file ends early
// (truncated)", "a damaged PNG (IHDR: CRC error)"; nothing is printed), also for a picture with
// a side over kMaxPictureSide (before allocating anything) and for a volume or deep image.
// `source`, when given, says what the file held before it became 8-bit RGB.
struct PictureSource {
  std::string format;       // "png", "jpeg", "tiff", "bmp", ... (OpenImageIO's names)
  int colour_channels = 3;  // 1: grey (R = G = B after reading); 3: colour, a palette too
  bool lossy = false;       // stored with a lossy compression (JPEG, also inside a TIFF)
};
// `accept`, when given, is called with the picture's size once the file's header is read and
// before any pixel buffer is allocated (also for a size over kMaxPictureSide, so a bound of the
// caller's own is the one that names it); what it throws (a size the caller cannot take) leaves
// read_png() as it was thrown. A 70-byte file can claim 16384x16384 pixels, 805 MB of them.
using SizeCheck = std::function<void(int width, int height)>;
RgbImage read_png(const std::filesystem::path& path, PictureSource* source = nullptr,
                  const SizeCheck& accept = {});

// Reads a picture held in memory as read_png() reads a file (a texture embedded in a model
// file): a PNG with libpng, other formats through OpenImageIO, told by their first bytes or else
// by `format_hint` (an extension: "tga"). Errors begin with `name` ("model.glb: embedded texture
// 0: cannot read: ..."), as read_png()'s with the file's.
RgbImage read_picture_bytes(std::span<const std::uint8_t> bytes, const std::string& name,
                            const std::string& format_hint = {}, const SizeCheck& accept = {});

// Reads a scanned-out frame (lightning2_emu's inputs, strip_headers dump, captured frames of
// golden entries) with read_png(), and refuses one whose file cannot hold strip headers, which
// are bit patterns in its pixel bytes: a grey picture (one channel: R = G = B, where a header
// needs 48 free bits over two pixels) or a lossy one (JPEG: the compression changes pixel
// bytes). Both used to be read and reported as damaged headers. Throws std::runtime_error
// naming the file and why. Other pictures (golden displays, references) are read with
// read_png(), which takes any of these. `accept` as for read_png().
RgbImage read_scanned_frame(const std::filesystem::path& path, const SizeCheck& accept = {});

}  // namespace l2
