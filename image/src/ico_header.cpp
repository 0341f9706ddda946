#include "image/ico_header.hpp"

#include <string>

#include "byte_fields.hpp"

namespace l2::png_codec {

namespace {

Failure refused(const std::string& what) {
  return Failure{"a bitmap " + what};
}

// What the reader reads by the directory entry: the mask's rows 8 pixels at a time, and colours
// from a palette of the entry's size (0: 256).
Status check_entry(std::string_view entry, std::uint32_t bits) {
  const std::uint32_t width = le(entry, 0, 1), colours = le(entry, 2, 1);
  if (bits < 32 && width % 8 != 0) {
    return refused("of " + std::to_string(bits) + " bits a pixel, " + std::to_string(width) +
                   " pixels wide: a transparency mask is read here only for widths that are "
                   "multiples of 8 (save the icon at 32 bits a pixel, or as PNG)");
  }
  if (bits <= 8 && colours != 0 && colours < (1u << bits)) {
    return refused("of " + std::to_string(bits) + " bits a pixel whose directory entry says " +
                   std::to_string(colours) + " colours, fewer than its bits index");
  }
  return {};
}

}  // namespace

Status check_ico_bitmap(std::string_view entry, std::string_view h, std::uint64_t offset,
                        std::uintmax_t file_size) {
  const std::uint32_t size = le(h, 0, 4), width = le(h, 4, 4), height = le(h, 8, 4);
  const std::uint32_t planes = le(h, 12, 2), bits = le(h, 14, 2), compression = le(h, 16, 4);
  const std::uint32_t colours = le(h, 32, 4);
  if (h.size() < 40 || size != 40)
    return refused("header of " + std::to_string(size) + " bytes, not 40");
  if (bits != 1 && bits != 4 && bits != 8 && bits != 16 && bits != 24 && bits != 32)
    return refused("of " + std::to_string(bits) +
                   " bits a pixel (an icon has 1, 4, 8, 16, 24 or 32)");
  if (planes != 1) return refused("of " + std::to_string(planes) + " planes (an icon has 1)");
  if (compression != 0)
    return refused("compressed (scheme " + std::to_string(compression) + "); an icon's is not");
  if (width < 1 || width > 256 || height < 2 || height > 512 || height % 2 != 0)
    return refused("of " + std::to_string(width) + "x" + std::to_string(height / 2) +
                   " pixels (an icon's are 1 to 256 a side)");
  const std::uint64_t rows = height / 2;
  const std::uint64_t palette = bits <= 8 ? 4ull * (colours != 0 ? colours : 1u << bits) : 0;
  if (bits <= 8 && colours > (1u << bits))
    return refused("of " + std::to_string(colours) + " colours at " + std::to_string(bits) +
                   " bits a pixel");
  const std::uint64_t colour_rows = (width * std::uint64_t{bits} + 31) / 32 * 4 * rows;
  const std::uint64_t mask_rows = (width + 31) / 32 * 4 * rows;
  const std::uint64_t needed = 40 + palette + colour_rows + mask_rows;
  if (offset + needed > file_size)
    return refused("of " + std::to_string(width) + "x" + std::to_string(rows) + " needing " +
                   std::to_string(needed) + " bytes, past the file's end");
  return check_entry(entry, bits);
}

}  // namespace l2::png_codec
