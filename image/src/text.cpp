#include "image/text.hpp"

#include <stdexcept>
#include <string>

#include "png_codec.hpp"

namespace l2 {

TextMask render_text(std::string_view text, int cap_height) {
  if (text.empty() || cap_height <= 0) return {};
  const std::string line(text);
  // The codec module holds OpenImageIO: loaded on the first label, as on the first picture.
  Result<TextMask> mask = png_codec::codec("text").render_text(line.c_str(), cap_height);
  if (!mask.ok()) throw std::runtime_error("text: " + mask.reason());
  return std::move(mask).value();
}

}  // namespace l2
