// What a picture file's header declares, checked before any reader trusts it
// (image/declared_size.hpp, tiff_header.hpp, exr_header.hpp, sgi_header.hpp, fits_header.hpp,
// rla_header.hpp), on arbitrary bytes: the file's first bytes through check_header, check_tiff
// (a TIFF's directories, read where they point), check_exr (an OpenEXR file's attributes),
// check_sgi_rle (an SGI image's RLE tables and rows), check_fits (a FITS file's image headers)
// and check_rla (an RLA file's channel classes) at a size of the input's own choosing, numbers
// taken from the input as what a reader declared through check_declared, and the same first
// bytes through format_by_signature (image/picture_formats.hpp). Never a crash or an overflow
// (UBSan), and every refusal one line saying "cannot read: ".
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "fuzz_check.hpp"
#include "image/declared_size.hpp"
#include "image/exr_header.hpp"
#include "image/fits_header.hpp"
#include "image/picture_formats.hpp"
#include "image/rla_header.hpp"
#include "image/sgi_header.hpp"
#include "image/tiff_header.hpp"

namespace {

using l2::fuzz::require;

// The next `n` bytes as a little-endian number (zero past the end).
std::uint64_t take(const std::uint8_t*& data, std::size_t& size, int n) {
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t b = size > 0 ? *data : 0;
    if (size > 0) ++data, --size;
    v |= b << (8 * i);
  }
  return v;
}

void check_refusal(const l2::Status& s, const char* what) {
  if (s.ok()) return;
  l2::fuzz::require_one_line(s.reason(), what);
  require(s.reason().rfind("cannot read: ", 0) == 0, "a refusal starts with \"cannot read: \"");
}

const char* const kFormats[] = {"pnm", "fits", "pfm",  "bmp", "hdr",     "targa", "dds",
                                "gif", "tiff", "jpeg", "png", "openexr", "webp",  ""};
const char* const kCompressions[] = {"", "none", "lzw", "zip", "packbits", "jpeg"};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::uint64_t file_size = take(data, size, 8);
  const std::string_view header(reinterpret_cast<const char*>(data),
                                std::min<std::size_t>(size, 4096));
  const l2::Result<l2::png_codec::HeaderFacts> facts =
      l2::png_codec::check_header(header, file_size);
  if (!facts.ok()) check_refusal(l2::Failure{facts.reason()}, "a header refusal is one line");
  const l2::png_codec::ReadAt read = [&](std::uint64_t at, std::size_t n) {
    return at >= header.size() ? std::string() : std::string(header.substr(at, n));
  };
  check_refusal(l2::png_codec::check_tiff(read, file_size), "a TIFF refusal is one line");
  check_refusal(l2::png_codec::check_exr(read, file_size), "an OpenEXR refusal is one line");
  check_refusal(l2::png_codec::check_sgi_rle(read, file_size), "an SGI refusal is one line");
  check_refusal(l2::png_codec::check_fits(read, file_size), "a FITS refusal is one line");
  check_refusal(l2::png_codec::check_rla(header), "an RLA refusal is one line");
  // A signature names a format or none; one not read here is refused in one line.
  const std::string format = l2::png_codec::format_by_signature(header);
  if (!format.empty() && !l2::png_codec::read_here(format)) {
    check_refusal(l2::Failure{l2::png_codec::not_read_here(format)},
                  "a format refusal is one line");
  }

  l2::png_codec::Declared d;
  d.format = kFormats[take(data, size, 1) % std::size(kFormats)];
  d.compression = kCompressions[take(data, size, 1) % std::size(kCompressions)];
  // Sides as a reader's int holds them: negative ones included.
  d.width = static_cast<std::int32_t>(take(data, size, 4));
  d.height = static_cast<std::int32_t>(take(data, size, 4));
  d.depth = static_cast<std::int32_t>(take(data, size, 4));
  d.channels = static_cast<std::int32_t>(take(data, size, 4));
  d.bytes_per_channel = static_cast<int>(take(data, size, 1));
  d.tile_width = static_cast<std::int32_t>(take(data, size, 4));
  d.tile_height = static_cast<std::int32_t>(take(data, size, 4));
  d.tile_depth = static_cast<std::int32_t>(take(data, size, 4));
  d.decoded_whole = take(data, size, 1) & 1;
  check_refusal(l2::png_codec::check_declared(d, file_size), "a declared-size refusal is one line");
  return 0;
}
