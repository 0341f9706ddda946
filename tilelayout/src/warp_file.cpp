#include "tilelayout/warp_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "command_line/printable.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

constexpr std::size_t kPfmChannels = 3;
constexpr std::size_t kQuotedWord = 24;  // a header word quoted in an error is cut here

bool header_blank(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// Reads the header's words one at a time: each is followed by exactly one blank, the last one
// before the data.
class Header {
 public:
  Header(std::string_view bytes, std::string name) : bytes_(bytes), name_(std::move(name)) {}

  std::string_view word(std::string_view field) {
    while (at_ < bytes_.size() && header_blank(bytes_[at_]) && at_ < kMaxPfmHeaderBytes) ++at_;
    const std::size_t start = at_;
    while (at_ < bytes_.size() && !header_blank(bytes_[at_]) && at_ < kMaxPfmHeaderBytes) ++at_;
    if (at_ >= bytes_.size() || at_ >= kMaxPfmHeaderBytes) {
      fail(field, fmt::format("the header ends before it (a PFM header is \"PF\", width, height "
                              "and scale within {} bytes)",
                              kMaxPfmHeaderBytes));
    }
    const std::string_view w = bytes_.substr(start, at_ - start);
    ++at_;  // its one blank
    return w;
  }

  // Points across the display: its size (one per pixel) down to 2 (one at each edge pixel).
  int dimension(std::string_view field, int display, std::string_view what) {
    const std::string_view w = word(field);
    int v = 0;
    const auto [end, error] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (error != std::errc() || end != w.data() + w.size() || v <= 0)
      fail(field, fmt::format("must be a positive integer, got {}", quoted(w)));
    const int least = std::min(display, 2);
    if (v < least || v > display) {
      fail(field, fmt::format("must be {}..{} points (the display is {} {}), got {}", least,
                              display, display, what, v));
    }
    return v;
  }

  std::size_t data_start() const { return at_; }

  [[noreturn]] void fail(std::string_view field, std::string_view message) const {
    throw LayoutError(fmt::format("{}: {}: {}", name_, field, message));
  }

  static std::string quoted(std::string_view s) {
    const bool cut = s.size() > kQuotedWord;
    return fmt::format("\"{}{}\"", printable(s.substr(0, kQuotedWord)), cut ? "..." : "");
  }

 private:
  std::string_view bytes_;
  std::string name_;
  std::size_t at_ = 0;
};

float read_pfm_float(const char* p, bool little) {
  std::uint32_t bits;
  std::memcpy(&bits, p, sizeof bits);
  if (little != (std::endian::native == std::endian::little)) bits = __builtin_bswap32(bits);
  return std::bit_cast<float>(bits);
}

}  // namespace

std::size_t max_warp_pfm_bytes(int width, int height) {
  return kMaxPfmHeaderBytes +
         static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * kPfmChannels * 4;
}

WarpMap parse_warp_pfm(std::string_view bytes, std::string_view name, int width, int height) {
  Header header(bytes, printable(name));
  const std::string_view magic = header.word("magic");
  if (magic != "PF") {
    header.fail("magic",
                fmt::format("must be \"PF\" (a 3-channel float PFM), got {}{}",
                            Header::quoted(magic), magic == "Pf" ? " (a 1-channel PFM)" : ""));
  }
  const int grid_width = header.dimension("width", width, "wide");
  const int grid_height = header.dimension("height", height, "high");
  const std::string_view s = header.word("scale");
  double scale = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), scale);
  if (error != std::errc() || end != s.data() + s.size() || !(scale != 0) || !std::isfinite(scale))
    header.fail("scale", fmt::format("must be a non-zero number, got {}", Header::quoted(s)));
  const std::size_t points =
      static_cast<std::size_t>(grid_width) * static_cast<std::size_t>(grid_height);
  const std::size_t need = points * kPfmChannels * 4;
  const std::size_t got = bytes.size() - header.data_start();
  if (got != need) {
    header.fail("data", fmt::format("{}x{} points of 3 floats are {} bytes after the header, "
                                    "the file has {}",
                                    grid_width, grid_height, need, got));
  }
  // The file's rows run bottom to top; the map's run top to bottom.
  const bool little = scale < 0;
  const char* data = bytes.data() + header.data_start();
  std::vector<float> positions(2 * points);
  for (int row = 0; row < grid_height; ++row) {
    const char* in =
        data + static_cast<std::size_t>(grid_height - 1 - row) * grid_width * kPfmChannels * 4;
    float* out = positions.data() + static_cast<std::size_t>(row) * grid_width * 2;
    for (int x = 0; x < grid_width; ++x, in += kPfmChannels * 4, out += 2) {
      out[0] = read_pfm_float(in, little);
      out[1] = read_pfm_float(in + 4, little);
    }
  }
  return warp_map_from_positions(width, height, grid_width, grid_height, positions);
}

}  // namespace l2
