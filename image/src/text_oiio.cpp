// Text through OpenImageIO's render_text (FreeType), into a coverage mask.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

#include "media_oiio.hpp"

namespace l2::png_codec {

namespace {

namespace OIIO = OIIO_NAMESPACE;

// A name, not a path: OpenImageIO looks for DejaVuSansMono.ttf in the system's font folders
// (/usr/share/fonts and below, $OPENIMAGEIO_FONTS).
constexpr const char* kFont = "DejaVuSansMono";
// DejaVu's capitals are 0.729 of its em, its ascent 0.928, its descenders 0.236.
constexpr double kCapsPerEm = 0.729, kAscentPerEm = 0.928, kDescentPerEm = 0.236;

}  // namespace

Result<TextMask> render_text(const char* text, int cap_height) try {
  const int size = std::max(1, static_cast<int>(std::lround(cap_height / kCapsPerEm)));
  const OIIO::ROI box = OIIO::ImageBufAlgo::text_size(text, size, kFont);
  if (!box.defined()) {
    OIIO::geterror();  // cleared: ours says which package holds the font
    return Failure{std::string("cannot draw text: no font ") + kFont +
                   " in the system's font folders (Debian: fonts-dejavu-core)"};
  }
  TextMask mask;
  mask.width = std::max(1, box.xend);
  mask.above = static_cast<int>(std::ceil(size * (kAscentPerEm - kCapsPerEm)));
  mask.height = mask.above + cap_height + static_cast<int>(std::ceil(size * kDescentPerEm));
  OIIO::ImageBuf buf(OIIO::ImageSpec(mask.width, mask.height, 1, OIIO::TypeDesc::UINT8));
  OIIO::ImageBufAlgo::zero(buf);
  const float ink[1] = {1.0f};
  if (!OIIO::ImageBufAlgo::render_text(buf, 0, mask.above + cap_height, text, size, kFont, ink)) {
    return Failure{"cannot draw text: " + buf.geterror()};
  }
  mask.coverage.resize(static_cast<std::size_t>(mask.width) * mask.height);
  buf.get_pixels(OIIO::ROI(0, mask.width, 0, mask.height), OIIO::TypeDesc::UINT8,
                 mask.coverage.data());
  return mask;
} catch (const std::exception& e) {
  return Failure{std::string("cannot draw text: ") + e.what()};
}

}  // namespace l2::png_codec
