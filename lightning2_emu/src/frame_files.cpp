#include "lightning2_emu/frame_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <optional>
#include <stdexcept>

#include "command_line/size_text.hpp"
#include "strip_headers/strip_header.hpp"

namespace l2 {
namespace {

int parse_int(std::string_view text, const std::string& what) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || text.empty()) {
    throw std::invalid_argument(fmt::format("{}: '{}' is not a number", what, text));
  }
  return value;
}

// Name order with numbers by value: "frame-2" before "frame-10", as a person numbers frames
// without zero padding. Equal runs of digits that differ in leading zeros fall back to the
// plain comparison, so the order stays total.
bool frame_order(const std::filesystem::path& a, const std::filesystem::path& b) {
  const std::string x = a.filename().string(), y = b.filename().string();
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  std::size_t i = 0, j = 0;
  while (i < x.size() && j < y.size()) {
    if (!digit(x[i]) || !digit(y[j])) {
      if (x[i] != y[j]) return x[i] < y[j];
      ++i, ++j;
      continue;
    }
    std::size_t i_end = i, j_end = j;
    while (i_end < x.size() && digit(x[i_end])) ++i_end;
    while (j_end < y.size() && digit(y[j_end])) ++j_end;
    while (i < i_end - 1 && x[i] == '0') ++i;  // leading zeros do not count
    while (j < j_end - 1 && y[j] == '0') ++j;
    if (i_end - i != j_end - j) return i_end - i < j_end - j;
    const int order = x.compare(i, i_end - i, y, j, j_end - j);
    if (order != 0) return order < 0;
    i = i_end, j = j_end;
  }
  if (x.size() - i != y.size() - j) return x.size() - i < y.size() - j;
  return x < y;
}

}  // namespace

InputLimit parse_size(const std::string& text, const std::string& what) {
  const std::optional<SizeText> size = parse_size_text(text);
  if (!size) throw std::invalid_argument(fmt::format("{}: '{}' is not WIDTHxHEIGHT", what, text));
  if (size->width < 1 || size->height < 1) {
    throw std::invalid_argument(fmt::format("{}: '{}' must be at least 1x1", what, text));
  }
  return {size->width, size->height};
}

std::vector<DisplaySpec> parse_display_list(const std::string& text) {
  std::vector<DisplaySpec> displays;
  for (const std::string& part : list_items(text)) {
    const int id = static_cast<int>(displays.size());
    const InputLimit size = parse_size(part, fmt::format("--displays: display {}", id));
    displays.push_back({id, size.width, size.height, 0});
  }
  return displays;
}

void apply_group_list(const std::string& text, std::vector<DisplaySpec>& displays) {
  const std::vector<std::string> parts = list_items(text);
  if (parts.size() != displays.size()) {
    throw std::invalid_argument(
        fmt::format("--groups: {} groups given for {} displays", parts.size(), displays.size()));
  }
  for (std::size_t d = 0; d < parts.size(); ++d) {
    const std::string what = fmt::format("--groups: display {}", d);
    const int group = parse_int(parts[d], what);
    if (group < 0 || group >= kMaxDisplays) {  // as a wall file's swap_groups
      throw std::invalid_argument(
          fmt::format("{}: group {} is not 0..{}", what, group, kMaxDisplays - 1));
    }
    displays[d].swap_group = group;
  }
}

Rgb parse_colour(const std::string& text, const std::string& what) {
  std::string hex = text;
  if (!hex.empty() && hex[0] == '#') hex.erase(0, 1);
  unsigned value = 0;
  const auto [end, ec] = std::from_chars(hex.data(), hex.data() + hex.size(), value, 16);
  if (hex.size() != 6 || ec != std::errc{} || end != hex.data() + hex.size()) {
    throw std::invalid_argument(fmt::format("{}: '{}' is not a colour RRGGBB", what, text));
  }
  return {static_cast<std::uint8_t>(value >> 16), static_cast<std::uint8_t>(value >> 8),
          static_cast<std::uint8_t>(value)};
}

std::vector<std::filesystem::path> list_frames(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    throw std::runtime_error(fmt::format("{}: not a folder of frames", folder.string()));
  }
  static const std::vector<std::string> kExtensions = {".png",  ".ppm", ".pnm", ".tif",
                                                       ".tiff", ".bmp", ".jpg", ".jpeg"};
  std::vector<fs::path> frames;
  for (const auto& entry : fs::directory_iterator(folder)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (entry.is_regular_file() &&
        std::find(kExtensions.begin(), kExtensions.end(), ext) != kExtensions.end()) {
      frames.push_back(entry.path());
    }
  }
  if (frames.empty()) {
    throw std::runtime_error(fmt::format("{}: no frame images in this folder", folder.string()));
  }
  std::sort(frames.begin(), frames.end(), frame_order);
  return frames;
}

}  // namespace l2
