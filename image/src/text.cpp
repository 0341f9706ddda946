#include "image/text.hpp"

#include <deque>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include "png_codec.hpp"

namespace l2 {

namespace {

// The last few labels drawn: a picture measures a centred label (text_width) before drawing
// it, and its legend repeats on every picture a program writes, each a call into the font
// renderer otherwise.
class RecentMasks {
 public:
  template <class Make>
  TextMask get(const std::string& text, int cap_height, Make make) {
    {
      const std::lock_guard lock(mutex_);
      for (const auto& [key, mask] : masks_) {
        if (key.second == cap_height && key.first == text) return mask;
      }
    }
    TextMask mask = make();
    const std::lock_guard lock(mutex_);
    masks_.emplace_front(std::pair{text, cap_height}, mask);
    if (masks_.size() > kKept) masks_.pop_back();
    return mask;
  }

 private:
  static constexpr std::size_t kKept = 32;
  std::mutex mutex_;
  std::deque<std::pair<std::pair<std::string, int>, TextMask>> masks_;
};

}  // namespace

TextMask render_text(std::string_view text, int cap_height) {
  if (text.empty() || cap_height <= 0) return {};
  static RecentMasks recent;
  const std::string line(text);
  return recent.get(line, cap_height, [&] {
    // The codec module holds OpenImageIO: loaded on the first label, as on the first picture.
    Result<TextMask> mask = png_codec::codec("text").render_text(line.c_str(), cap_height);
    if (!mask.ok()) throw std::runtime_error("text: " + mask.reason());
    return std::move(mask).value();
  });
}

}  // namespace l2
