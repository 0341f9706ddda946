// The boundary between png_io.cpp and the image codec module it loads on first use
// (png_codec_oiio.cpp, built as l2_png_oiio). OpenImageIO pulls in some 260 shared libraries
// (OpenCV, OpenVDB, FFmpeg, GStreamer...) whose relocations cost every process that links it
// about half a second of CPU at start, before main(); most runs of our programs (a pipeserver in a
// live wall, --help, a parse error) never touch an image file, and most that do only read or write
// PNG. So only the module links OpenImageIO, a process pays for it when it first reads or writes
// a picture of another format, and PNG files are read and written with libpng on this side of the
// boundary (png_libpng.hpp).
//
// The module is built from the same sources with the same compiler, so standard types cross.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "base/result.hpp"
#include "image/text.hpp"

namespace l2::png_codec {

// Where read_rgb() puts the pixels: asked once for a width x height 8-bit RGB buffer with
// contiguous rows, and only for sides up to max_side (a file's header can claim any size).
// `accept` is asked first, with the size the file's header claims (also one over max_side) and
// before read_rgb() or the library under it allocates anything for the pixels; when it says no,
// read_rgb() returns at once with no error of its own (the caller knows why). `allocate`
// returns nullptr when out of memory.
struct RgbSink {
  void* context;
  bool (*accept)(void* context, int width, int height);
  std::uint8_t* (*allocate)(void* context, int width, int height);
  int max_side;
};

// What read_rgb() found the file to hold before it became 8-bit RGB (png_io.hpp's
// PictureSource): filled once the file's header is read.
struct Source {
  std::string format;       // "png", or OpenImageIO's name of the format: "jpeg", "tiff", ...
  int colour_channels = 0;  // 1: grey; 3: colour (a palette is colour); alpha is not counted
  bool lossy = false;       // stored with a lossy compression: JPEG, also inside a TIFF
};

// A picture opened for reads of parts of its rows (image/picture_regions.hpp): through an image
// cache of bounded memory, so a picture far larger than memory can be shown a region at a time.
class RegionReader {
 public:
  virtual ~RegionReader() = default;
  // The picture's MIP levels (1: none), level 0 the picture itself, each level's sides half
  // the level's before it (rounded either way, never under 1).
  virtual int levels() const = 0;
  virtual int width(int level) const = 0;
  virtual int height(int level) const = 0;
  // Columns [x_begin, x_end) of row y of `level` (all within it) as 8-bit RGB into `rgb`.
  virtual Status read_row(int level, int y, int x_begin, int x_end, std::uint8_t* rgb) = 0;
};

// A movie's video stream decoded frame by frame into 8-bit RGB (image/movie_file.hpp).
class MovieDecoder {
 public:
  virtual ~MovieDecoder() = default;
  virtual int width() const = 0;
  virtual int height() const = 0;
  // The video stream's frames per second as its container says (0 when it says nothing).
  virtual double frames_per_second() const = 0;
  // The next frame into `rgb` (width x height x 3 bytes): true, or false (nothing written) when
  // the stream has no more.
  virtual Result<bool> next_frame(std::uint8_t* rgb) = 0;
};

// A picture's sides and how it is stored, after the checks open_regions makes (picture_shape).
struct PictureShape {
  int width = 0, height = 0;
  bool tiled = false;     // stored in tiles (a tiled TIFF, OpenEXR): any part read alone
  double decoded_mb = 0;  // its pixels decoded as 8-bit RGB, in MiB
};

// Told how far a long job has got, a fraction in [0, 1].
struct Progress {
  void* context;
  void (*tell)(void* context, double done);
};

// A failure's reason does not name the file. read_rgb() is ok, reading nothing, when the sink's
// `accept` refused the size (the caller knows why).
struct Codec {
  // A picture file's bytes, in the format `name`'s extension says; the caller writes them (so
  // that every error of the file system reaches it: OpenImageIO's PNG writer lost ENOSPC).
  Result<std::string> (*encode_file)(const char* name, int width, int height,
                                     const std::uint8_t* rgb);
  Status (*read_rgb)(const char* path, RgbSink sink, Source* source);
  // The same for a picture in memory (`size` bytes): its format told by its first bytes, else by
  // `format_hint` (an extension, "tga"). The bytes are only read.
  Status (*read_rgb_bytes)(const std::uint8_t* bytes, std::size_t size, const char* format_hint,
                           RgbSink sink, Source* source);
  // Through an image cache holding at most `cache_megabytes` of decoded tiles.
  Result<std::unique_ptr<RegionReader>> (*open_regions)(const char* path, float cache_megabytes);
  Result<std::unique_ptr<MovieDecoder>> (*open_movie)(const char* path);
  Result<TextMask> (*render_text)(const char* text, int cap_height);  // image/text.hpp
  Result<PictureShape> (*picture_shape)(const char* path);
  // `source` (any picture, read in rows) copied into `target`, a tiled TIFF with MIP levels,
  // holding a band of rows of each level at a time (tiled_copy_oiio.cpp).
  Status (*make_tiled_copy)(const char* source, const char* target, Progress progress);
};

// The module's one exported symbol: a function returning its Codec. The name carries the
// version of the structures above: a program and a module built from different sources (a
// partial rebuild) then fail with "has no l2_png_codec_v4" instead of misreading each other's
// structures (a picture's size limit read as garbage, or a crash). Change both with them.
inline constexpr const char* kEntryPoint = "l2_png_codec_v15";
using EntryPoint = const Codec* (*)();

// The module, loaded on first use (png_io.cpp); throws std::runtime_error naming `file` (the
// picture or movie asked for) when it cannot be loaded.
const Codec& codec(const std::filesystem::path& file);

}  // namespace l2::png_codec
