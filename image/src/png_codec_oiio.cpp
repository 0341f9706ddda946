// The image codec module (png_codec.hpp): PNG (and whatever else OpenImageIO reads) to and from
// 8-bit RGB. Loaded by png_io.cpp; no exception leaves it.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <png.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "media_oiio.hpp"
#include "picture_checks.hpp"
#include "png_codec.hpp"

namespace {

namespace OIIO = OIIO_NAMESPACE;
using l2::Failure;
using l2::Status;
using l2::png_codec::open_failed;
using l2::png_codec::RgbSink;
using l2::png_codec::Source;

l2::Result<std::string> encode_file(const char* name, int width, int height,
                                    const std::uint8_t* rgb) try {
  auto out = OIIO::ImageOutput::create(name);
  if (!out) {
    OIIO::geterror();  // cleared: our wording replaces OpenImageIO's
    const std::string ext = std::filesystem::path(name).extension().string();
    if (ext.empty()) {
      return Failure{"cannot write: no extension to choose a picture format by (give .png)"};
    }
    return Failure{"cannot write: no picture format is known for '" + ext + "' (give .png)"};
  }
  if (!out->supports("ioproxy")) {
    return Failure{std::string("cannot write: OpenImageIO cannot write ") + out->format_name() +
                   " into memory (give .png)"};
  }
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  // libpng's defaults (every row filter tried, zlib level 6) took 108-117 ms for a 1984x768
  // wall picture; one filter (each row minus the row above, which suits rendered pictures) and
  // zlib level 1 take 21-24 ms for files about 1.5x the size. Runs that keep every frame's pictures
  // spent most of their time here.
  spec.attribute("png:filter", PNG_FILTER_UP);
  spec.attribute("png:compressionLevel", 1);
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  if (!out->set_ioproxy(&memory) || !out->open(name, spec) ||
      !out->write_image(OIIO::TypeDesc::UINT8, rgb) || !out->close()) {
    return Failure{"cannot write: " + out->geterror()};
  }
  return std::string(bytes.begin(), bytes.end());
} catch (const std::exception& e) {
  return Failure{std::string("cannot write: ") + e.what()};
}

// --- PNG files, read with libpng itself ------------------------------------------------------
//
// Through OpenImageIO a damaged PNG printed libpng's own line ("libpng error: IHDR: CRC error")
// on stderr before ours, and its error came back as several lines: OpenImageIO's libpng error
// handler records the message and returns, and libpng then calls its default handler, which
// prints before it jumps back. Here the handler keeps the message and jumps back itself, so
// nothing is printed; warnings (a chunk libpng skips) are not failures and are dropped.

struct PngRead {
  std::FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  bool ended_early = false;  // the file ended before libpng had all it needed
  int colour_type = -1;      // as the file stores its pixels (PNG_COLOR_TYPE_...), once known
  bool one_row = false;      // the pixels' buffer holds one row, each read over the last
  char error[256] = {};      // libpng's message (a plain buffer: it crosses a longjmp)
  ~PngRead() {
    if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    if (file) std::fclose(file);
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

bool is_png(std::FILE* file) {
  png_byte signature[8];
  const bool png = std::fread(signature, 1, 8, file) == 8 && png_sig_cmp(signature, 0, 8) == 0;
  std::rewind(file);
  return png;
}

std::string size_refused(long width, long height, int max_side) {
  return std::to_string(width) + "x" + std::to_string(height) +
         " pixels, larger than any picture read here (sides up to " + std::to_string(max_side) +
         ")";
}

// The check every reader makes on the size a file's header claims, before anything is allocated
// for the pixels: nothing when the picture may be read, otherwise the reason (empty when the
// caller refused it: it says why itself). The caller is asked first, so that a bound of its own
// tighter than ours (a model's texture) names the picture whatever the size claimed.
std::optional<std::string> refusal(const RgbSink& sink, long width, long height) {
  const auto side = [](long v) { return static_cast<int>(std::min<long>(v, INT_MAX)); };
  if (!sink.accept(sink.context, side(width), side(height))) return std::string();
  if (width > sink.max_side || height > sink.max_side) {
    return size_refused(width, height, sink.max_side);
  }
  return std::nullopt;
}

// refusal()'s reason as a Status: a size the caller refused is no failure of ours.
Status refused(const std::string& why) {
  if (why.empty()) return {};
  return Failure{why};
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

// --- other formats, through OpenImageIO ---------------------------------------------------

// The logical screen a GIF file declares, or nothing when the file is not a GIF. OpenImageIO's
// GIF reader allocates the whole screen, 4 bytes a pixel, as it opens the file, before its spec
// can be checked: a 29-byte GIF claiming 16384x16384 took 1 GB.
std::optional<std::pair<long, long>> gif_screen(std::FILE* file) {
  unsigned char header[10];
  const bool read = std::fread(header, 1, sizeof header, file) == sizeof header;
  std::rewind(file);
  if (!read || std::memcmp(header, "GIF", 3) != 0) {  // all giflib asks of a GIF's version
    return std::nullopt;
  }
  return std::pair<long, long>(header[6] | header[7] << 8, header[8] | header[9] << 8);
}

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// OpenImageIO's reason, or ours where it gives none (its PNM reader fails a file that ends
// early with an empty error).
std::string read_failed(const std::string& format, const std::string& error) {
  if (!error.empty()) return "cannot read: " + l2::png_codec::one_line(error);
  return "cannot read: the " + upper(format) + " file is damaged or ends early";
}

// The format a picture's first bytes say it is in (OpenImageIO's name), for formats that begin
// with a signature; empty for others. (OpenImageIO's own test, valid_file(), fails a damaged
// file, which is when the question is asked.)
std::string format_by_signature(const unsigned char* head, std::size_t n) {
  const auto starts = [&](std::string_view magic) {
    return n >= magic.size() && std::memcmp(head, magic.data(), magic.size()) == 0;
  };
  if (starts("GIF")) return "gif";
  if (starts("BM")) return "bmp";
  if (n >= 2 && head[0] == 'P' && head[1] >= '1' && head[1] <= '6') return "pnm";
  if (starts("II*\0") || starts("MM\0*")) return "tiff";
  if (starts("\xff\xd8\xff")) return "jpeg";
  if (starts("DDS ")) return "dds";
  if (starts("8BPS")) return "psd";
  if (starts("\x76\x2f\x31\x01")) return "openexr";
  if (starts("RIFF") && n >= 12 && std::memcmp(head + 8, "WEBP", 4) == 0) return "webp";
  return {};
}

std::string format_by_signature(const char* path) {
  unsigned char head[12] = {};
  std::FILE* file = std::fopen(path, "rb");
  if (!file) return {};
  const std::size_t n = std::fread(head, 1, sizeof head, file);
  std::fclose(file);
  return format_by_signature(head, n);
}

// Where a picture's bytes are: a file, or memory (a texture embedded in a model file).
struct Input {
  const char* path = nullptr;           // the file; null: the picture is in memory
  const std::uint8_t* bytes = nullptr;  // in memory, `size` bytes
  std::size_t size = 0;
  const char* format_hint = "";  // memory: the format when the first bytes do not say ("tga")
  bool in_memory() const { return path == nullptr; }
};

// The input as a stdio stream, for libpng and the signature checks.
std::FILE* open_stream(const Input& input) {
  if (!input.in_memory()) return std::fopen(input.path, "rb");
  // Read in place: a stream opened "rb" never writes to its buffer.
  return ::fmemopen(const_cast<std::uint8_t*>(input.bytes), input.size, "rb");
}

// A PNG's header, and with `rows` its rows, decoded with libpng, each row dropped: ok, or why
// not. The image cache reads a PNG with OpenImageIO's reader, whose error handler returns, so
// libpng printed its own line ("libpng error: IDAT: incorrect data check") before ours, and only
// once the cache reached the damage, a frame into the run; its ICO reader's handler crashed the
// process (SIGFPE) on a PNG icon cut short.
Status check_png(const Input& input, bool rows) {
  PngRead read;
  read.file = open_stream(input);
  if (!read.file) return Failure{std::string("cannot read: ") + std::strerror(errno)};
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

// An OpenImageIO reader and, for a picture in memory, what it reads from (which must outlive it:
// declared first, destroyed last).
struct Opened {
  std::unique_ptr<OIIO::Filesystem::IOMemReader> memory;
  std::unique_ptr<OIIO::ImageInput> in;
};

// A picture in memory opened by the reader its first bytes (or else its hint) name.
l2::Result<Opened> open_bytes(const Input& input, const OIIO::ImageSpec& config) {
  Opened opened;
  const std::string format = format_by_signature(input.bytes, input.size);
  // By the format's name or an extension ("tga"): a file name would be opened.
  opened.in = OIIO::ImageInput::create(format.empty() ? std::string(input.format_hint) : format);
  if (!opened.in) {
    OIIO::geterror();  // cleared: our wording replaces OpenImageIO's
    return Failure{"cannot read: not a picture of a format known here"};
  }
  opened.memory = std::make_unique<OIIO::Filesystem::IOMemReader>(input.bytes, input.size);
  OIIO::ImageSpec spec;
  if (!opened.in->set_ioproxy(opened.memory.get()) || !opened.in->open("memory", spec, config)) {
    std::string why = opened.in->geterror();
    if (why.empty()) why = "damaged or ends early";
    return Failure{"cannot read: a " + upper(opened.in->format_name()) + " picture: " + why};
  }
  return opened;
}

l2::Result<Opened> open_oiio(const Input& input, const OIIO::ImageSpec& config) {
  if (input.in_memory()) return open_bytes(input, config);
  Opened opened;
  opened.in = OIIO::ImageInput::open(input.path, &config);
  if (!opened.in) return Failure{open_failed(input.path)};
  return opened;
}

// An opened picture that is not a PNG, through OpenImageIO, as read_rgb() says; `file_size`
// bytes hold it.
Status read_oiio(OIIO::ImageInput& in, std::uintmax_t file_size, RgbSink sink, Source& source) {
  const OIIO::ImageSpec& spec = in.spec();
  const std::string compression = spec.get_string_attribute("compression");
  source = {in.format_name(), spec.nchannels >= 3 ? 3 : 1,
            std::string(in.format_name()) == "jpeg" || compression.rfind("jpeg", 0) == 0};
  if (spec.nchannels < 1 || spec.width <= 0 || spec.height <= 0) {
    return Failure{"not an image with pixels"};
  }
  // OpenImageIO picks the reader by content, not by name: a volume or deep image (a DDS volume
  // texture named .png) reads width x height x depth pixels, more than the picture holds.
  if (spec.depth != 1 || spec.deep) {
    return Failure{spec.deep
                       ? std::string("a deep image, not a picture")
                       : "a volume (depth " + std::to_string(spec.depth) + "), not a picture"};
  }
  // Checked before the buffer is asked for: a 74-byte file can claim 20000x20000 pixels.
  if (const auto why = refusal(sink, spec.width, spec.height)) return refused(*why);
  // What the reader declares beyond the size (tiles, samples) against the file's bytes.
  if (const Status s = l2::png_codec::check_opened(in, file_size, false, false); !s.ok()) return s;
  std::uint8_t* dst = sink.allocate(sink.context, spec.width, spec.height);
  if (!dst) return Failure{"cannot read: out of memory"};
  if (spec.nchannels >= 3) {  // the first three channels, straight into the picture
    if (!in.read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, dst)) {
      return Failure{read_failed(in.format_name(), in.geterror())};
    }
    return {};
  }
  const std::size_t count = static_cast<std::size_t>(spec.width) * spec.height;
  std::vector<std::uint8_t> grey(count);
  if (!in.read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT8, grey.data())) {
    return Failure{read_failed(in.format_name(), in.geterror())};
  }
  for (std::size_t i = 0; i < count; ++i) dst[i * 3] = dst[i * 3 + 1] = dst[i * 3 + 2] = grey[i];
  return {};
}

// An alpha channel is dropped, as a DVI link drops it (spec §1): the colour bytes are kept as
// stored, not multiplied by alpha (OpenImageIO's default for PNG, which would garble a header
// in a captured RGBA frame). Grey is spread over R, G and B.
Status read_input(const Input& input, RgbSink sink, Source* source_or_null) try {
  Source ignored;
  Source& source = source_or_null ? *source_or_null : ignored;
  if (input.in_memory() && input.size == 0) return Failure{"cannot read: no bytes"};
  {
    PngRead read;
    read.file = open_stream(input);
    // OpenImageIO said only "Could not open file" (and of a folder, "Not a PNG file").
    if (!read.file) return Failure{std::string("cannot read: ") + std::strerror(errno)};
    struct stat file_status {};
    if (!input.in_memory() && ::fstat(::fileno(read.file), &file_status) == 0 &&
        S_ISDIR(file_status.st_mode)) {
      return Failure{"cannot read: a folder, not a file"};
    }
    if (is_png(read.file)) return read_png_file(read, sink, source);
    if (const auto screen = gif_screen(read.file)) {
      if (const auto why = refusal(sink, screen->first, screen->second)) return refused(*why);
    }
  }
  // What the header declares, before a reader trusts it (picture_checks.hpp).
  const l2::png_codec::PictureBytes bytes =
      input.in_memory() ? l2::png_codec::memory_bytes(input.bytes, input.size)
                        : l2::png_codec::file_bytes(input.path);
  if (const auto facts = l2::png_codec::check_before_open(bytes); !facts.ok()) {
    return Failure{facts.reason()};
  }
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto opened = open_oiio(input, config);
  if (!opened.ok()) return Failure{opened.reason()};
  return read_oiio(*opened->in, bytes.size, sink, source);
} catch (const std::exception& e) {
  return Failure{std::string("cannot read: ") + e.what()};
}

Status read_rgb(const char* path, RgbSink sink, Source* source) {
  return read_input({path}, sink, source);
}

Status read_rgb_bytes(const std::uint8_t* bytes, std::size_t size, const char* format_hint,
                      RgbSink sink, Source* source) {
  return read_input({nullptr, bytes, size, format_hint}, sink, source);
}

}  // namespace

namespace l2::png_codec {

// When OpenImageIO cannot open a file it reports the reader its name chose: a damaged GIF named
// .png was "Not a PNG file". The reason is the reader's that knows the content, and says what
// the file is.
std::string one_line(const std::string& text) {
  std::string line;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    if (end > at) line += (line.empty() ? "" : "; ") + text.substr(at, end - at);
    at = end + 1;
  }
  return line;
}

std::string open_failed(const char* path) {
  const std::string error = one_line(OIIO::geterror());
  const std::string format = format_by_signature(path);
  if (format.empty()) return "cannot read: " + (error.empty() ? "not a picture" : error);
  const auto reader = OIIO::ImageInput::create(format);
  OIIO::ImageSpec spec;
  std::string why = "damaged";
  if (reader && !reader->open(path, spec)) why = one_line(reader->geterror());
  if (why.empty()) why = "damaged or ends early";
  return "cannot read: a " + upper(format) + " file: " + why;
}

Status check_png_data(const char* path) {
  return check_png({path}, true);
}

Status check_png_bytes(std::string_view bytes, bool rows) {
  return check_png({nullptr, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()},
                   rows);
}

}  // namespace l2::png_codec

namespace {

constexpr l2::png_codec::Codec kCodec{encode_file,
                                      read_rgb,
                                      read_rgb_bytes,
                                      l2::png_codec::open_regions,
                                      l2::png_codec::open_movie,
                                      l2::png_codec::render_text,
                                      l2::png_codec::encode_rgb,
                                      l2::png_codec::picture_shape,
                                      l2::png_codec::make_tiled_copy};

}  // namespace

// Named as png_codec::kEntryPoint says.
extern "C" __attribute__((visibility("default"))) const l2::png_codec::Codec* l2_png_codec_v13() {
  return &kCodec;
}
