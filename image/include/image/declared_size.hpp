// What a picture file's header declares, checked against what the file's bytes can hold before
// any reader trusts it. OpenImageIO believes headers: a few hundred bytes of PNM, PFM, TIFF, BMP,
// HDR or FITS declaring a width of 2e9 aborted the process inside its image cache (an assertion
// in its tile bookkeeping); a JPEG whose frame header says 65500x65500 had the cache decode for
// ever; a 35-byte GIF of 16384x16384 took 1.2 GB; a DDS declaring 2^32-1 mip levels hung the
// header's own reading. Pure arithmetic on the header's numbers and the file's size: each format
// stores its pixels in a way that bounds how many bytes of picture one byte of file can become.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "base/result.hpp"

namespace l2::png_codec {

// The largest side and picture a file may declare: far beyond any wall (a gigapixel picture is
// read a tile at a time), within what the readers' arithmetic holds.
inline constexpr long long kMaxDeclaredSide = 1 << 20;
inline constexpr long long kMaxDeclaredPixels = 1LL << 36;
// A tile larger than this is more than the image cache may hold (regions_oiio.cpp).
inline constexpr double kMaxTileMegabytes = 64;
// A picture a reader decodes whole (a progressive JPEG) larger than this is refused.
inline constexpr double kMaxWholeMegabytes = 512;

// What the bytes before the reader say, from the file's first bytes (at most 4096) and its size:
// a DDS's mip levels against its sides and its size, a GIF's screen against its size (both are
// trusted while the file is opened), an SGI image's storage, sample size and dimension (trusted
// as its rows are read), and whether a JPEG is progressive (decoded whole). Failure:
// one line saying what the file declares.
struct HeaderFacts {
  bool decoded_whole = false;
};
Result<HeaderFacts> check_header(std::string_view first_bytes, std::uintmax_t file_size);

// The first (largest) picture of a file as its reader describes it.
struct Declared {
  std::string format;       // the reader's name: "pnm", "jpeg", "tiff", ...
  std::string compression;  // as the reader names it ("none", "lzw", "zip", ...); may be empty
  long long width = 0, height = 0, depth = 1;
  int channels = 0, bytes_per_channel = 1;
  long long tile_width = 0, tile_height = 0, tile_depth = 1;  // 0: stored as scanlines
  bool decoded_whole = false;
};

// Whether OpenImageIO's reader of `format` decodes a picture whole on its first read, whatever
// part the cache asks for: an icon's PNG, a GIF's screen, a Targa, IFF, WebP, HEIF or JPEG 2000
// picture. Such a picture is bounded as a progressive JPEG is (Declared::decoded_whole).
bool decoded_whole_by(std::string_view format);

// At most how many bytes of decoded picture one byte of a file of this format (and compression)
// can hold: 1 for raw samples, a run-length or dictionary coder's longest run otherwise, with
// room for headers and palettes. Generous: a file that passes may still be damaged.
double max_expansion(std::string_view format, std::string_view compression);

// Failure ("cannot read: declares 2000000000x1 pixels of 3 channels (5722 MiB decoded), more
// than a pnm file of 319 bytes can hold") when the declared picture cannot be in the file, is
// larger than any wall could use, or has tiles or a whole decode larger than the readers may
// hold.
Status check_declared(const Declared& d, std::uintmax_t file_size);

}  // namespace l2::png_codec
