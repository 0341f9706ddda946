#include "lightning2_emu/frame_builder.hpp"

#include <algorithm>

namespace l2::testing {

Rgb pattern(int display, int x, int y) {
  std::uint32_t h = static_cast<std::uint32_t>(display + 1) * 0x9E3779B1u;
  h ^= static_cast<std::uint32_t>(x) * 0x85EBCA77u;
  h ^= static_cast<std::uint32_t>(y) * 0xC2B2AE3Du;
  h ^= h >> 15;
  h *= 0x2C1B3C6Du;
  h ^= h >> 12;
  return {static_cast<std::uint8_t>(h), static_cast<std::uint8_t>(h >> 8),
          static_cast<std::uint8_t>(h >> 16)};
}

void FrameBuilder::raw_header(int x, int y, std::uint64_t value) {
  write_header_pixels(value, image_.row(y).data() + x * 3, 3);
}

int FrameBuilder::copy(int x, int y, int display, int dx, int dy, int width, bool parity) {
  header(x, y, StripHeader::copy(parity, display, dx, dy, width));
  for (int k = 0; k < width && x + 2 + k < image_.width(); ++k) {
    image_.set(x + 2 + k, y, pattern(display, dx + k, dy));
  }
  return x + 2 + width;
}

int FrameBuilder::copy_fill(int x, int y, int display, int dx, int dy, int width, Rgb colour,
                            bool parity) {
  header(x, y, StripHeader::copy(parity, display, dx, dy, width));
  image_.fill_rect(x + 2, y, width, 1, colour);
  return x + 2 + width;
}

int FrameBuilder::skip(int x, int y, int width, bool parity) {
  header(x, y, StripHeader::skip(parity, width));
  return x + 2 + width;
}

int FrameBuilder::ext(int x, int y, int display, int dx, int dy, int width, const Extension& e) {
  StripHeader h = StripHeader::copy(false, display, dx, dy, width);
  h.op = StripOp::Ext;
  header(x, y, h);
  raw_header(x + 2, y, encode(e));
  return x + 4;
}

int FrameBuilder::depth(int x, int y, int display, int dx, int dy, const std::vector<Rgb>& colours,
                        const std::vector<std::uint32_t>& depths) {
  const int w = static_cast<int>(colours.size());
  const int at = ext(x, y, display, dx, dy, w, Extension::depth());
  for (int k = 0; k < w; ++k) {
    const std::uint32_t d = depths[static_cast<std::size_t>(k)];
    image_.set(at + k, y, colours[static_cast<std::size_t>(k)]);
    image_.set(at + w + k, y,
               {static_cast<std::uint8_t>(d >> 16), static_cast<std::uint8_t>(d >> 8),
                static_cast<std::uint8_t>(d)});
  }
  return at + 2 * w;
}

bool pack_frame(std::span<const Tile> tiles, bool parity, RgbImage& frame) {
  frame.fill({});
  const int width = frame.width();
  std::size_t next = 0;
  int row_y = 0;
  while (next < tiles.size()) {
    // One row: as many tiles as fit.
    std::size_t end = next;
    int x = 0, height = 0;
    while (end < tiles.size() && x + 2 + tiles[end].w <= width) {
      x += 2 + tiles[end].w;
      height = std::max(height, tiles[end].h);
      ++end;
    }
    if (end == next || row_y + height > frame.height()) return false;
    for (int r = 0; r < height; ++r) {
      const int y = row_y + r;
      std::uint8_t* row = frame.row(y).data();
      int gx = 0;
      for (std::size_t t = next; t < end; ++t) {
        const Tile& tile = tiles[t];
        const StripHeader h =
            r < tile.h ? StripHeader::copy(parity, tile.display, tile.dx, tile.dy + r, tile.w)
                       : StripHeader::skip(parity, tile.w);
        write_header_pixels(encode(h), row + gx * 3, 3);
        if (r < tile.h) {
          for (int k = 0; k < tile.w; ++k) {
            const Rgb c = pattern(tile.display, tile.dx + k, tile.dy + r);
            std::uint8_t* p = row + (gx + 2 + k) * 3;
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
          }
        }
        gx += 2 + tile.w;
      }
      // END follows if two pixels remain; the frame is black already, which reads as END.
    }
    row_y += height;
    next = end;
  }
  return true;
}

RgbImage pattern_image(int display, int width, int height) {
  RgbImage image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) image.set(x, y, pattern(display, x, y));
  }
  return image;
}

}  // namespace l2::testing
