// The image codec module (png_codec.hpp): PNG (and whatever else OpenImageIO reads) to and from
// 8-bit RGB. Loaded by png_io.cpp; no exception leaves it.
#include <OpenImageIO/imageio.h>

#include <exception>
#include <string>
#include <vector>

#include "png_codec.hpp"

namespace {

namespace OIIO = OIIO_NAMESPACE;
using l2::png_codec::RgbSink;

constexpr int kPngFilterUp = 0x20;  // libpng's PNG_FILTER_UP (png.h is not included here)

std::string write_rgb(const char* path, int width, int height, const std::uint8_t* rgb) try {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return "cannot write: " + OIIO::geterror();
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  // libpng's defaults (every row filter tried, zlib level 6) took 108-117 ms for a 1984x768
  // wall picture; one filter (each row minus the row above, which suits rendered pictures) and
  // zlib level 1 take 21-24 ms for files about 1.5x the size. Runs that keep every frame's pictures
  // spent most of their time here.
  spec.attribute("png:filter", kPngFilterUp);
  spec.attribute("png:compressionLevel", 1);
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, rgb) || !out->close()) {
    return "cannot write: " + out->geterror();
  }
  return {};
} catch (const std::exception& e) {
  return std::string("cannot write: ") + e.what();
}

// An alpha channel is dropped, as a DVI link drops it (spec §1): the colour bytes are kept as
// stored, not multiplied by alpha (OpenImageIO's default for PNG, which would garble a header
// in a captured RGBA frame). Grey is spread over R, G and B.
std::string read_rgb(const char* path, RgbSink sink) try {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) return "cannot read: " + OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels < 1 || spec.width <= 0 || spec.height <= 0) return "not an image with pixels";
  // OpenImageIO picks the reader by content, not by name: a volume or deep image (a DDS volume
  // texture named .png) reads width x height x depth pixels, more than the picture holds.
  if (spec.depth != 1 || spec.deep) {
    return spec.deep ? std::string("a deep image, not a picture")
                     : "a volume (depth " + std::to_string(spec.depth) + "), not a picture";
  }
  // Checked before the buffer is asked for: a 74-byte file can claim 20000x20000 pixels.
  if (spec.width > sink.max_side || spec.height > sink.max_side) {
    return std::to_string(spec.width) + "x" + std::to_string(spec.height) +
           " pixels, larger than any picture read here (sides up to " +
           std::to_string(sink.max_side) + ")";
  }
  std::uint8_t* dst = sink.allocate(sink.context, spec.width, spec.height);
  if (spec.nchannels >= 3) {  // the first three channels, straight into the picture
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, dst)) {
      return "cannot read: " + in->geterror();
    }
    return {};
  }
  const std::size_t count = static_cast<std::size_t>(spec.width) * spec.height;
  std::vector<std::uint8_t> grey(count);
  if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT8, grey.data())) {
    return "cannot read: " + in->geterror();
  }
  for (std::size_t i = 0; i < count; ++i) dst[i * 3] = dst[i * 3 + 1] = dst[i * 3 + 2] = grey[i];
  return {};
} catch (const std::exception& e) {
  return std::string("cannot read: ") + e.what();
}

constexpr l2::png_codec::Codec kCodec{write_rgb, read_rgb};

}  // namespace

// Named as png_codec::kEntryPoint says.
extern "C" __attribute__((visibility("default"))) const l2::png_codec::Codec* l2_png_codec_v2() {
  return &kCodec;
}
