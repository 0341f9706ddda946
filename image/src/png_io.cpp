#include "image/png_io.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <stdexcept>
#include <string>

namespace l2 {

namespace OIIO = OIIO_NAMESPACE;

void write_png(const std::filesystem::path& path, const RgbImage& image) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) throw std::runtime_error(path.string() + ": cannot write: " + OIIO::geterror());
  const OIIO::ImageSpec spec(image.width(), image.height(), RgbImage::kChannels,
                             OIIO::TypeDesc::UINT8);
  if (!out->open(path.string(), spec) || !out->write_image(OIIO::TypeDesc::UINT8, image.data()) ||
      !out->close()) {
    throw std::runtime_error(path.string() + ": cannot write: " + out->geterror());
  }
}

RgbImage read_png(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw std::runtime_error(path.string() + ": cannot read: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels < 1 || spec.width <= 0 || spec.height <= 0) {
    throw std::runtime_error(path.string() + ": not an image with pixels");
  }
  const int channels = spec.nchannels;
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(spec.width) * spec.height * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data())) {
    throw std::runtime_error(path.string() + ": cannot read: " + in->geterror());
  }
  RgbImage image(spec.width, spec.height);
  std::uint8_t* dst = image.data();
  const std::size_t count = static_cast<std::size_t>(spec.width) * spec.height;
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t* src = pixels.data() + i * channels;
    dst[i * 3 + 0] = src[0];
    dst[i * 3 + 1] = channels >= 3 ? src[1] : src[0];
    dst[i * 3 + 2] = channels >= 3 ? src[2] : src[0];
  }
  return image;
}

}  // namespace l2
