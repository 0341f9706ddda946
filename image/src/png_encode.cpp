// PNG with libpng (png_libpng.hpp): the files write_png() writes, pictures a program sends rather
// than writes (the control page's displays), and grey maps (an import's alpha and beta maps).
// One row filter (each row minus the row above, which suits rendered pictures) and zlib level 1:
// libpng's defaults (every filter tried, level 6) made runs that keep every frame's pictures
// spend most of their time here, for files only a little smaller.
#include <png.h>

#include <csetjmp>
#include <string>

#include "png_libpng.hpp"

namespace l2::png_codec {
namespace {

struct PngWrite {
  png_structp png = nullptr;
  png_infop info = nullptr;
  std::string* out = nullptr;
  std::string error;
  ~PngWrite() { png_destroy_write_struct(&png, &info); }
};

void write_failed(png_structp png, png_const_charp message) {
  static_cast<PngWrite*>(png_get_error_ptr(png))->error = message;
  png_longjmp(png, 1);
}

void write_warned(png_structp, png_const_charp) {}

void append_bytes(png_structp png, png_bytep data, std::size_t size) {
  static_cast<PngWrite*>(png_get_io_ptr(png))->out->append(reinterpret_cast<char*>(data), size);
}

void no_flush(png_structp) {}

// Only libpng's C frames lie between the setjmp here and a longjmp, and nothing in this frame
// is changed after setjmp and read after the jump.
bool png_write_steps(PngWrite& w, int width, int height, int channels, const std::uint8_t* pixels) {
  if (setjmp(png_jmpbuf(w.png))) return false;  // NOLINT(cert-err52-cpp)
  png_set_write_fn(w.png, &w, append_bytes, no_flush);
  png_set_IHDR(w.png, w.info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_filter(w.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_set_compression_level(w.png, 1);
  png_write_info(w.png, w.info);
  const std::size_t stride = static_cast<std::size_t>(width) * channels;
  for (int y = 0; y < height; ++y) {
    // libpng's row type is not const; it only reads the row.
    png_write_row(w.png, const_cast<png_bytep>(pixels + stride * static_cast<std::size_t>(y)));
  }
  png_write_end(w.png, nullptr);
  return true;
}

}  // namespace

Status encode_pixels(int width, int height, int channels, const std::uint8_t* pixels,
                     std::string* out) {
  PngWrite w;
  w.out = out;
  w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &w, write_failed, write_warned);
  if (w.png) w.info = png_create_info_struct(w.png);
  if (!w.png || !w.info) return Failure{"cannot encode: out of memory"};
  if (!png_write_steps(w, width, height, channels, pixels))
    return Failure{"cannot encode: " + w.error};
  return {};
}

}  // namespace l2::png_codec
