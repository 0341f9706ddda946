#include "image/jpeg_frame.hpp"

#include <fmt/format.h>

// libjpeg's header wants FILE and size_t declared first.
#include <csetjmp>
#include <cstdio>
#include <string>

#include <jpeglib.h>

#include "image/declared_size.hpp"

namespace l2 {
namespace {

// libjpeg reports a fatal error by calling error_exit, which must not return: it jumps back to
// the decode's setjmp with the message kept. Warnings (a stream cut short, bad data) are kept
// too: a frame with any is refused.
struct Errors {
  jpeg_error_mgr mgr{};
  std::jmp_buf back{};
  char message[JMSG_LENGTH_MAX] = {};
  bool warned = false;
};

void error_exit(j_common_ptr info) {
  Errors* e = reinterpret_cast<Errors*>(info->err);
  info->err->format_message(info, e->message);
  std::longjmp(e->back, 1);
}

void emit_message(j_common_ptr info, int level) {
  Errors* e = reinterpret_cast<Errors*>(info->err);
  if (level >= 0 || e->warned) return;  // trace messages, or a warning already kept
  info->err->format_message(info, e->message);
  e->warned = true;
}

std::string first_bytes(std::string_view b) {
  std::string out;
  for (std::size_t i = 0; i < b.size() && i < 4; ++i)
    out += fmt::format("{}{:02x}", i ? " " : "", static_cast<unsigned char>(b[i]));
  return out.empty() ? "nothing" : out;
}

// The declared picture against the limits and the bytes (declared_size.hpp): before decoding.
Status check_size(const jpeg_decompress_struct& d, std::size_t bytes,
                  const JpegFrameLimits& limits) {
  if (static_cast<int>(d.image_width) > limits.max_width ||
      static_cast<int>(d.image_height) > limits.max_height)
    return Failure{fmt::format("declares {}x{} pixels, more than a shared frame may have ({}x{})",
                               d.image_width, d.image_height, limits.max_width, limits.max_height)};
  png_codec::Declared declared;
  declared.format = "jpeg";
  declared.width = d.image_width;
  declared.height = d.image_height;
  declared.channels = d.num_components;
  declared.decoded_whole = jpeg_has_multiple_scans(const_cast<jpeg_decompress_struct*>(&d));
  return png_codec::check_declared(declared, bytes);
}

// Decodes into `out`; the jump target is here, with no object of this frame needing a
// destructor run between setjmp and longjmp.
bool decode(jpeg_decompress_struct& d, Errors& errors, std::string_view bytes,
            const JpegFrameLimits& limits, RgbImage& out, std::string& why) {
  if (setjmp(errors.back)) return false;
  jpeg_create_decompress(&d);
  jpeg_mem_src(&d, reinterpret_cast<const unsigned char*>(bytes.data()),
               static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&d, TRUE);
  if (const Status s = check_size(d, bytes.size(), limits); !s.ok()) {
    why = s.reason();
    return false;
  }
  d.out_color_space = JCS_RGB;
  jpeg_start_decompress(&d);
  out = RgbImage(static_cast<int>(d.output_width), static_cast<int>(d.output_height));
  while (d.output_scanline < d.output_height) {
    JSAMPROW row = out.row(static_cast<int>(d.output_scanline)).data();
    jpeg_read_scanlines(&d, &row, 1);
  }
  jpeg_finish_decompress(&d);
  return true;
}

}  // namespace

Result<RgbImage> decode_jpeg_frame(std::string_view bytes, const JpegFrameLimits& limits) {
  if (bytes.size() > limits.max_bytes)
    return Failure{fmt::format("{} bytes, more than a shared frame may have ({})", bytes.size(),
                               limits.max_bytes)};
  if (bytes.size() < 3 || bytes.substr(0, 3) != "\xFF\xD8\xFF")
    return Failure{fmt::format("not a JPEG (it starts {})", first_bytes(bytes))};
  if (const Result<png_codec::HeaderFacts> facts =
          png_codec::check_header(bytes.substr(0, 4096), bytes.size());
      !facts.ok())
    return Failure{facts.reason()};
  jpeg_decompress_struct d{};
  Errors errors;
  d.err = jpeg_std_error(&errors.mgr);
  errors.mgr.error_exit = error_exit;
  errors.mgr.emit_message = emit_message;
  RgbImage out;
  std::string why;
  const bool done = decode(d, errors, bytes, limits, out, why);
  jpeg_destroy_decompress(&d);
  if (!done) return Failure{why.empty() ? fmt::format("a damaged JPEG ({})", errors.message) : why};
  if (errors.warned) return Failure{fmt::format("a damaged JPEG ({})", errors.message)};
  return out;
}

}  // namespace l2
