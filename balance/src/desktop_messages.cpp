#include "balance/desktop_messages.hpp"

#include <fmt/format.h>
#include <zstd.h>

#include <algorithm>
#include <array>

#include "balance/message_words.hpp"

namespace l2 {
namespace {

constexpr char kBase64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
// Fast enough for what a control line carries; zstd (level 1) keeps desktops small, whose
// large areas of one colour are most of them.
constexpr int kZstdLevel = 1;

void append_base64(std::string& out, const std::uint8_t* bytes, std::size_t n) {
  out.reserve(out.size() + (n + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= n; i += 3) {
    const std::uint32_t v = bytes[i] << 16 | bytes[i + 1] << 8 | bytes[i + 2];
    for (int shift : {18, 12, 6, 0}) out += kBase64[(v >> shift) & 63];
  }
  if (i == n) return;
  const std::uint32_t v = bytes[i] << 16 | (i + 1 < n ? bytes[i + 1] << 8 : 0);
  out += kBase64[(v >> 18) & 63];
  out += kBase64[(v >> 12) & 63];
  out += i + 1 < n ? kBase64[(v >> 6) & 63] : '=';
  out += '=';
}

// Empty for text that is not base64.
std::vector<std::uint8_t> from_base64(std::string_view text, bool& ok) {
  static const std::array<int, 256> value = [] {
    std::array<int, 256> v{};
    v.fill(-1);
    for (int i = 0; i < 64; ++i) v[static_cast<unsigned char>(kBase64[i])] = i;
    return v;
  }();
  std::vector<std::uint8_t> out;
  ok = text.size() % 4 == 0;
  if (!ok) return out;
  out.reserve(text.size() / 4 * 3);
  for (std::size_t i = 0; i < text.size(); i += 4) {
    const int pad = (text[i + 3] == '=') + (text[i + 2] == '=');
    if (pad > 0 && i + 4 != text.size()) return ok = false, out;
    std::uint32_t v = 0;
    for (std::size_t j = 0; j < 4; ++j) {
      const int d = j >= 4u - pad ? 0 : value[static_cast<unsigned char>(text[i + j])];
      if (d < 0) return ok = false, out;
      v = v << 6 | static_cast<std::uint32_t>(d);
    }
    out.push_back(static_cast<std::uint8_t>(v >> 16));
    if (pad < 2) out.push_back(static_cast<std::uint8_t>(v >> 8));
    if (pad < 1) out.push_back(static_cast<std::uint8_t>(v));
  }
  return out;
}

Rect rect_words(Words& w) {
  Rect r;
  r.x = static_cast<int>(w.integer("x", 0, kMaxDesktopSide - 1));
  r.y = static_cast<int>(w.integer("y", 0, kMaxDesktopSide - 1));
  r.w = static_cast<int>(w.integer("width", 1, kMaxDesktopSide));
  r.h = static_cast<int>(w.integer("height", 1, kMaxDesktopSide));
  return r;
}

}  // namespace

std::string encode(const DesktopMessage& m) {
  std::string out =
      fmt::format("DESKTOP {} {} {} {}", m.frame, m.width, m.height, m.regions.size());
  for (const Rect& r : m.regions) out += fmt::format(" {} {} {} {}", r.x, r.y, r.w, r.h);
  return out + fmt::format(" {}", m.rects);
}

DesktopMessage decode_desktop(std::string_view line) {
  Words w(line);
  w.keyword("DESKTOP");
  DesktopMessage m;
  m.frame = static_cast<int>(w.integer("frame", 0, kMaxFrame));
  m.width = static_cast<int>(w.integer("width", 1, kMaxDesktopSide));
  m.height = static_cast<int>(w.integer("height", 1, kMaxDesktopSide));
  const auto n = w.integer("region count", 0, kMaxControlTiles);
  for (long long i = 0; i < n; ++i) m.regions.push_back(rect_words(w));
  m.rects = static_cast<int>(w.integer("rect count", 0, kMaxControlTiles * 64LL));
  w.end();
  return m;
}

std::string encode_desktop_rect(const Rect& r, const std::uint8_t* rgb, std::size_t stride) {
  const std::size_t row = static_cast<std::size_t>(r.w) * 3;
  std::vector<std::uint8_t> raw(row * static_cast<std::size_t>(r.h));
  for (int y = 0; y < r.h; ++y)
    std::copy_n(rgb + static_cast<std::size_t>(y) * stride, row, raw.data() + y * row);
  std::vector<std::uint8_t> packed(ZSTD_compressBound(raw.size()));
  const std::size_t n =
      ZSTD_compress(packed.data(), packed.size(), raw.data(), raw.size(), kZstdLevel);
  if (ZSTD_isError(n)) throw ControlError("desktop: zstd cannot compress a rectangle");
  std::string out = fmt::format("RECT {} {} {} {} ", r.x, r.y, r.w, r.h);
  append_base64(out, packed.data(), n);
  return out;
}

DesktopRect decode_desktop_rect(std::string_view line) {
  Words w(line);
  w.keyword("RECT");
  DesktopRect d;
  d.rect = rect_words(w);
  const std::size_t expected = static_cast<std::size_t>(d.rect.area()) * 3;
  if (expected > kMaxDesktopRectBytes) w.fail("a rectangle larger than a RECT line may carry");
  bool ok = false;
  const std::vector<std::uint8_t> packed = from_base64(w.word(), ok);
  if (!ok) w.fail("its pixels are not base64");
  w.end();
  const unsigned long long size = ZSTD_getFrameContentSize(packed.data(), packed.size());
  if (size != expected) w.fail("its pixels do not fill the rectangle");
  d.rgb.resize(expected);
  const std::size_t n = ZSTD_decompress(d.rgb.data(), expected, packed.data(), packed.size());
  if (ZSTD_isError(n) || n != expected) w.fail("its pixels are damaged");
  return d;
}

std::vector<Rect> desktop_bands(const Rect& r) {
  std::vector<Rect> bands;
  const int rows = static_cast<int>(std::max<std::size_t>(
      1, kMaxDesktopRectBytes / (static_cast<std::size_t>(std::max(r.w, 1)) * 3)));
  for (int y = r.y; y < r.bottom(); y += rows)
    bands.push_back({r.x, y, r.w, std::min(rows, r.bottom() - y)});
  return bands;
}

}  // namespace l2
