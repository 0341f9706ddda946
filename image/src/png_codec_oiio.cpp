// The image codec module (png_codec.hpp): whatever OpenImageIO reads and writes, to and from
// 8-bit RGB. Programs read and write PNG themselves (png_libpng.hpp); a PNG that reaches the
// module anyway is read with the same libpng reader, the others through OpenImageIO. Loaded by
// png_io.cpp; no exception leaves it.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
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

#include "image/picture_formats.hpp"
#include "image/rla_header.hpp"
#include "media_oiio.hpp"
#include "picture_checks.hpp"
#include "picture_readers.hpp"
#include "png_codec.hpp"
#include "png_libpng.hpp"

namespace {

namespace OIIO = OIIO_NAMESPACE;
using l2::Failure;
using l2::Status;
using l2::png_codec::Input;
using l2::png_codec::refusal;
using l2::png_codec::refused;
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
  const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
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

// OpenImageIO's reason, or ours where it gives none (its PNM reader fails a file that ends
// early with an empty error).
std::string read_failed(const std::string& format, const std::string& error) {
  if (!error.empty()) return "cannot read: " + l2::png_codec::one_line(error);
  return "cannot read: the " + l2::png_codec::format_label(format) +
         " file is damaged or ends early";
}

// An OpenImageIO reader and, for a picture in memory, what it reads from (which must outlive it:
// declared first, destroyed last).
struct Opened {
  std::unique_ptr<OIIO::Filesystem::IOMemReader> memory;
  std::unique_ptr<OIIO::ImageInput> in;
};

// A picture in memory opened by the reader its first bytes (or else its hint) name.
l2::Result<Opened> open_bytes(const Input& input, const OIIO::ImageSpec& config) {
  const std::string_view head(reinterpret_cast<const char*>(input.bytes),
                              std::min(input.size, l2::png_codec::kRlaHeaderBytes));
  const auto choice = l2::png_codec::choose_reader(head, input.format_hint);
  if (!choice.ok()) return Failure{choice.reason()};
  if (const Status s = l2::png_codec::check_chosen(*choice, head); !s.ok()) {
    return Failure{s.reason()};
  }
  Opened opened;
  opened.in = l2::png_codec::make_reader(choice->format);
  if (!opened.in) return Failure{"cannot read: not a picture of a format known here"};
  opened.memory = std::make_unique<OIIO::Filesystem::IOMemReader>(input.bytes, input.size);
  OIIO::ImageSpec spec;
  if (!opened.in->set_ioproxy(opened.memory.get()) || !opened.in->open("memory", spec, config)) {
    std::string why = opened.in->geterror();
    if (why.empty()) why = "damaged or ends early";
    return Failure{"cannot read: a " + l2::png_codec::format_label(opened.in->format_name()) +
                   " picture: " + why};
  }
  return opened;
}

l2::Result<Opened> open_oiio(const Input& input, const OIIO::ImageSpec& config) {
  if (input.in_memory()) return open_bytes(input, config);
  auto in = l2::png_codec::open_reader(input.path, &config);
  if (!in.ok()) return Failure{in.reason()};
  Opened opened;
  opened.in = std::move(in).value();
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
  if (spec.depth > 1 || spec.deep) {
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
    const l2::png_codec::Stream file = l2::png_codec::open_stream(input);
    // OpenImageIO said only "Could not open file" (and of a folder, "Not a PNG file").
    if (!file) return Failure{std::string("cannot read: ") + std::strerror(errno)};
    struct stat file_status {};
    if (!input.in_memory() && ::fstat(::fileno(file.get()), &file_status) == 0 &&
        S_ISDIR(file_status.st_mode)) {
      return Failure{"cannot read: a folder, not a file"};
    }
    if (l2::png_codec::is_png(file.get())) return l2::png_codec::read_png(file.get(), sink, source);
    if (const auto screen = gif_screen(file.get())) {
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

}  // namespace l2::png_codec

namespace {

constexpr l2::png_codec::Codec kCodec{encode_file,
                                      read_rgb,
                                      read_rgb_bytes,
                                      l2::png_codec::open_regions,
                                      l2::png_codec::open_movie,
                                      l2::png_codec::render_text,
                                      l2::png_codec::picture_shape,
                                      l2::png_codec::make_tiled_copy};

}  // namespace

// Named as png_codec::kEntryPoint says.
extern "C" __attribute__((visibility("default"))) const l2::png_codec::Codec* l2_png_codec_v15() {
  return &kCodec;
}
