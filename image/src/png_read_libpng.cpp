// PNG files read with libpng itself (png_libpng.hpp), for a whole picture and for the checks a PNG
// passes before the image cache reads it; and what this reader shares with png_codec_oiio.cpp's
// OpenImageIO reader: the picture's stream and the check on its claimed size. No exception
// leaves it.
//
// Through OpenImageIO a damaged PNG printed libpng's own line ("libpng error: IHDR: CRC error")
// on stderr before ours, and its error came back as several lines: OpenImageIO's libpng error
// handler records the message and returns, and libpng then calls its default handler, which
// prints before it jumps back. Here the handler keeps the message and jumps back itself, so
// nothing is printed; warnings (a chunk libpng skips) are not failures and are dropped.
#include <png.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "png_libpng.hpp"

namespace l2::png_codec {
namespace {

struct PngRead {
  std::FILE* file = nullptr;  // the caller's
  png_structp png = nullptr;
  png_infop info = nullptr;
  bool ended_early = false;  // the file ended before libpng had all it needed
  int colour_type = -1;      // as the file stores its pixels (PNG_COLOR_TYPE_...), once known
  bool one_row = false;      // the pixels' buffer holds one row, each read over the last
  char error[256] = {};      // libpng's message (a plain buffer: it crosses a longjmp)
  ~PngRead() {
    if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
  }
};

[[noreturn]] void png_failed(png_structp png, png_const_charp message) {
  auto* read = static_cast<PngRead*>(png_get_error_ptr(png));
  std::snprintf(read->error, sizeof read->error, "%s", message ? message : "");
  png_longjmp(png, 1);
}

void png_warned(png_structp, png_const_charp) {}

void png_read_bytes(png_structp png, png_bytep data, std::size_t size) {
  auto* read = static_cast<PngRead*>(png_get_io_ptr(png));
  if (std::fread(data, 1, size, read->file) == size) return;
  if (std::ferror(read->file)) png_failed(png, std::strerror(errno));
  read->ended_early = true;
  png_failed(png, "the file ends early");
}

// Header, then (after `size` accepts width x height: the buffer for the pixels, or nullptr) the
// pixels. Only libpng's C frames lie between the setjmp here and a longjmp, and nothing in this
// frame is changed after setjmp and read after the jump.
bool png_steps(PngRead& read, png_bytep (*size)(void*, png_uint_32, png_uint_32), void* context) {
  if (setjmp(png_jmpbuf(read.png))) return false;  // NOLINT(cert-err52-cpp)
  png_set_read_fn(read.png, &read, png_read_bytes);
  png_read_info(read.png, read.info);
  read.colour_type = png_get_color_type(read.png, read.info);
  png_set_expand(read.png);       // palette to RGB, grey below 8 bits to 8, tRNS to alpha
  png_set_scale_16(read.png);     // 16 bits to 8, rounded (as OpenImageIO converted them)
  png_set_strip_alpha(read.png);  // dropped, not multiplied in
  png_set_gray_to_rgb(read.png);  // grey spread over R, G and B
  const int passes = png_set_interlace_handling(read.png);
  png_read_update_info(read.png, read.info);
  const png_uint_32 width = png_get_image_width(read.png, read.info);
  const png_uint_32 height = png_get_image_height(read.png, read.info);
  if (png_get_rowbytes(read.png, read.info) != std::size_t{width} * 3) {
    png_failed(read.png, "not 8-bit RGB after conversion");
  }
  png_bytep pixels = size(context, width, height);
  if (!pixels) return true;  // refused or out of memory: sizing says which
  // One row's buffer (read.one_row) takes every row in turn: the data is checked, not kept.
  const std::size_t row_bytes = read.one_row ? 0 : std::size_t{width} * 3;
  for (int pass = 0; pass < passes; ++pass) {
    for (png_uint_32 y = 0; y < height; ++y) {
      png_read_row(read.png, pixels + std::size_t{y} * row_bytes, nullptr);
    }
  }
  png_read_end(read.png, nullptr);
  return true;
}

std::string size_refused(long width, long height, int max_side) {
  return std::to_string(width) + "x" + std::to_string(height) +
         " pixels, larger than any picture read here (sides up to " + std::to_string(max_side) +
         ")";
}

Status read_png_file(PngRead& read, RgbSink sink, Source& source) {
  read.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &read, png_failed, png_warned);
  if (read.png) read.info = png_create_info_struct(read.png);
  if (!read.png || !read.info) return Failure{"cannot read: out of memory"};
  struct Sizing {
    RgbSink sink;
    std::string refused;
  } sizing{sink, {}};
  // Checked before the buffer is asked for: a 74-byte file can claim 20000x20000 pixels.
  const auto size = [](void* context, png_uint_32 width, png_uint_32 height) -> png_bytep {
    auto& s = *static_cast<Sizing*>(context);
    if (const auto why = refusal(s.sink, width, height)) {
      s.refused = *why;
      return nullptr;
    }
    png_bytep pixels =
        s.sink.allocate(s.sink.context, static_cast<int>(width), static_cast<int>(height));
    if (!pixels) s.refused = "cannot read: out of memory";
    return pixels;
  };
  const bool read_all = png_steps(read, size, &sizing);
  if (read.colour_type >= 0) {
    source = {"png", (read.colour_type & PNG_COLOR_MASK_COLOR) ? 3 : 1, false};
  }
  if (!read_all) {
    if (read.ended_early) return Failure{"cannot read: the PNG file ends early (truncated)"};
    return Failure{std::string("cannot read: a damaged PNG (") + read.error + ")"};
  }
  return refused(sizing.refused);
}

// A PNG's header, and with `rows` its rows, decoded with libpng, each row dropped: ok, or why
// not. The image cache reads a PNG with OpenImageIO's reader, whose error handler returns, so
// libpng printed its own line ("libpng error: IDAT: incorrect data check") before ours, and only
// once the cache reached the damage, a frame into the run; its ICO reader's handler crashed the
// process (SIGFPE) on a PNG icon cut short.
Status check_png(const Input& input, bool rows) {
  const Stream file = open_stream(input);
  if (!file) return Failure{std::string("cannot read: ") + std::strerror(errno)};
  PngRead read;
  read.file = file.get();
  read.one_row = true;
  std::vector<std::uint8_t> row;
  const RgbSink sink{&row, [](void* context, int, int) { return context != nullptr; },
                     [](void* context, int width, int) {
                       auto& r = *static_cast<std::vector<std::uint8_t>*>(context);
                       r.resize(std::size_t(width) * 3);
                       return r.data();
                     },
                     INT_MAX};
  Source ignored;
  // A sink whose context is null accepts no size: only the header is read.
  return read_png_file(read, rows ? sink : RgbSink{nullptr, sink.accept, sink.allocate, INT_MAX},
                       ignored);
}

}  // namespace

bool is_png(std::FILE* file) {
  png_byte signature[8];
  // Its first four bytes, as libpng tells a PNG damaged in transfer (line ends converted) from
  // another format: read here, such a file is refused in our one line; another reader tried on
  // it printed libpng's own line beside it.
  const bool png = std::fread(signature, 1, 8, file) == 8 && png_sig_cmp(signature, 0, 4) == 0;
  std::rewind(file);
  return png;
}

Status read_png(std::FILE* file, RgbSink sink, Source& source) {
  PngRead read;
  read.file = file;
  return read_png_file(read, sink, source);
}

Stream open_stream(const Input& input) {
  if (!input.in_memory()) return {std::fopen(input.path, "rb"), std::fclose};
  // Read in place: a stream opened "rb" never writes to its buffer.
  return {::fmemopen(const_cast<std::uint8_t*>(input.bytes), input.size, "rb"), std::fclose};
}

std::optional<std::string> refusal(const RgbSink& sink, long width, long height) {
  const auto side = [](long v) { return static_cast<int>(std::min<long>(v, INT_MAX)); };
  if (!sink.accept(sink.context, side(width), side(height))) return std::string();
  if (width > sink.max_side || height > sink.max_side) {
    return size_refused(width, height, sink.max_side);
  }
  return std::nullopt;
}

Status refused(const std::string& why) {
  if (why.empty()) return {};
  return Failure{why};
}

Status check_png_data(const char* path) {
  return check_png({path}, true);
}

Status check_png_bytes(std::string_view bytes, bool rows) {
  return check_png({nullptr, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()},
                   rows);
}

}  // namespace l2::png_codec
