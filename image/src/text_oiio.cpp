// Text through OpenImageIO's render_text (FreeType), into a coverage mask.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "media_oiio.hpp"

namespace l2::png_codec {

namespace {

namespace OIIO = OIIO_NAMESPACE;

// A name, not a path: the file DejaVuSansMono.ttf in the system's font folders.
constexpr const char* kFont = "DejaVuSansMono";

// The font's file, looked up once per process where OpenImageIO would look ($OPENIMAGEIO_FONTS,
// then the system's and the user's font folders). Given only the name, OpenImageIO walks those
// folders again at every call: a picture of a few dozen labels took seconds. The name itself
// when no file is found, so OpenImageIO's own search says what is missing.
std::string font_path() {
  namespace fs = std::filesystem;
  std::vector<fs::path> folders;
  if (const char* extra = std::getenv("OPENIMAGEIO_FONTS")) {
    std::string list = extra;
    for (std::size_t at = 0; at <= list.size();) {
      const std::size_t end = std::min(list.find(':', at), list.size());
      if (end > at) folders.emplace_back(list.substr(at, end - at));
      at = end + 1;
    }
  }
  if (const char* home = std::getenv("HOME")) {
    folders.emplace_back(fs::path(home) / ".fonts");
    folders.emplace_back(fs::path(home) / ".local/share/fonts");
  }
  folders.emplace_back("/usr/share/fonts");
  folders.emplace_back("/usr/local/share/fonts");
  const std::string file = std::string(kFont) + ".ttf";
  for (const fs::path& folder : folders) {
    std::error_code ec;
    for (fs::recursive_directory_iterator
             it(folder, fs::directory_options::skip_permission_denied, ec),
         end;
         !ec && it != end; it.increment(ec)) {
      if (it->path().filename() == file) return it->path().string();
    }
  }
  return kFont;
}

const std::string& font() {
  static const std::string path = font_path();
  return path;
}
// DejaVu's capitals are 0.729 of its em, its ascent 0.928, its descenders 0.236.
constexpr double kCapsPerEm = 0.729, kAscentPerEm = 0.928, kDescentPerEm = 0.236;

}  // namespace

Result<TextMask> render_text(const char* text, int cap_height) try {
  const int size = std::max(1, static_cast<int>(std::lround(cap_height / kCapsPerEm)));
  const OIIO::ROI box = OIIO::ImageBufAlgo::text_size(text, size, font());
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
  // A label is a few thousand pixels: a thread pool costs more than the drawing.
  OIIO::ImageBufAlgo::zero(buf, {}, 1);
  const float ink[1] = {1.0f};
  if (!OIIO::ImageBufAlgo::render_text(buf, 0, mask.above + cap_height, text, size, font(), ink,
                                       OIIO::ImageBufAlgo::TextAlignX::Left,
                                       OIIO::ImageBufAlgo::TextAlignY::Baseline, 0, {}, 1)) {
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
