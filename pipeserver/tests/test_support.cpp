#include "test_support.hpp"

#include "pipeserver/pipeserver.hpp"
#include "verify/verify_run.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace l2::test {

TileLayout small_layout(int pipeservers, int tile_w, int tile_h, int fb_w, int fb_h) {
  TileLayout layout;
  Wall& wall = layout.wall;
  wall.name = "small";
  wall.canvas_width = 136;
  wall.canvas_height = 48;
  for (const int x : {0, 72}) {
    Display& d = wall.displays.emplace_back();
    d.id = x == 0 ? 0 : 1;
    d.width = 64;
    d.height = 48;
    d.canvas_x = x;
  }
  wall.pipeserver_count = pipeservers;
  wall.framebuffer_width = fb_w;
  wall.framebuffer_height = fb_h;
  for (int y = 0; y < wall.canvas_height; y += tile_h) {
    for (int x = 0; x < wall.canvas_width; x += tile_w) {
      const Rect logical =
          intersect({x, y, tile_w, tile_h}, {0, 0, wall.canvas_width, wall.canvas_height});
      const int index = static_cast<int>(layout.logical_tiles.size());
      layout.logical_tiles.push_back(logical);
      for (const Display& d : wall.displays) {
        const Rect part = intersect(logical, d.on_canvas());
        if (part.empty()) continue;
        const Rect on_display{part.x - d.canvas_x, part.y - d.canvas_y, part.w, part.h};
        layout.tiles.push_back(
            DisplayTile{d.id, on_display, part, index, Compositing::Copy, 0, {}});
        layout.tile_pipeserver.push_back(static_cast<int>(layout.tile_pipeserver.size()) %
                                         pipeservers);
      }
    }
  }
  for (int s = 0; s < pipeservers; ++s) {
    std::vector<DisplayTile> mine;
    for (std::size_t i = 0; i < layout.tiles.size(); ++i) {
      if (layout.tile_pipeserver[i] == s) mine.push_back(layout.tiles[i]);
    }
    layout.pipeservers.push_back(pack_tiles(s, fb_w, fb_h, mine));
  }
  return layout;
}

Reassembly reassemble(const Wall& wall, const std::vector<RgbImage>& frames) {
  Reassembly out;
  for (const Display& d : wall.displays) out.displays.emplace_back(d.width, d.height);
  bool seen[2] = {false, false};
  for (const RgbImage& frame : frames) {
    for (int y = 0; y < frame.height(); ++y) {
      const std::uint8_t* row = frame.row(y).data();
      parse_scanline(row, frame.width(), 3, out.errors, [&](const ParsedStrip& s) {
        seen[s.header.frame ? 1 : 0] = true;
        if (s.header.op == StripOp::Ext) out.composited_pixels += s.length;
        if (s.header.op != StripOp::Copy) return;
        ++out.copies;
        out.copied_pixels += s.length;
        if (s.header.display >= out.displays.size()) {
          ++out.errors.missing_display;
          return;
        }
        RgbImage& dst = out.displays[s.header.display];
        if (s.header.y >= dst.height() || s.header.x + s.length > dst.width()) {
          ++out.errors.clips;
          return;
        }
        std::memcpy(dst.row(s.header.y).data() + s.header.x * 3,
                    row + static_cast<std::size_t>(s.source_x) * 3,
                    static_cast<std::size_t>(s.length) * 3);
      });
    }
  }
  for (int p = 0; p < 2; ++p) {
    if (seen[p]) out.parities_seen.push_back(p);
  }
  return out;
}

ImageDiff& ImageDiff::operator+=(const ImageDiff& o) {
  pixels_differing += o.pixels_differing;
  pixels_beyond_one += o.pixels_beyond_one;
  max_channel_diff = std::max(max_channel_diff, o.max_channel_diff);
  at_tile_edges += o.at_tile_edges;
  return *this;
}

RgbImage crop(const RgbImage& image, const Rect& r) {
  RgbImage out(r.w, r.h);
  for (int y = 0; y < r.h; ++y)
    for (int x = 0; x < r.w; ++x) out.set(x, y, image.at(r.x + x, r.y + y));
  return out;
}

ImageDiff compare(const RgbImage& a, const RgbImage& b) {
  if (a.width() != b.width() || a.height() != b.height()) {
    throw std::invalid_argument("compare: images differ in size");
  }
  ImageDiff d;
  const auto pa = a.bytes(), pb = b.bytes();
  for (std::size_t i = 0; i < pa.size(); i += 3) {
    int worst = 0;
    for (std::size_t c = 0; c < 3; ++c) worst = std::max(worst, std::abs(pa[i + c] - pb[i + c]));
    if (worst > 0) ++d.pixels_differing;
    if (worst > 1) ++d.pixels_beyond_one;
    d.max_channel_diff = std::max(d.max_channel_diff, worst);
  }
  return d;
}

ImageDiff compare(const RgbImage& a, const RgbImage& b, const TileLayout& layout, int display) {
  ImageDiff d = compare(a, b);
  std::vector<bool> edge(static_cast<std::size_t>(a.width()) * a.height(), false);
  for (const DisplayTile& t : layout.tiles) {
    if (t.display != display) continue;
    const Rect& r = t.on_display;
    for (int y = r.y; y < r.bottom(); ++y)
      for (int x = r.x; x < r.right(); ++x)
        if (x == r.x || y == r.y || x == r.right() - 1 || y == r.bottom() - 1)
          edge[static_cast<std::size_t>(y) * a.width() + x] = true;
  }
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      if (a.at(x, y) != b.at(x, y) && edge[static_cast<std::size_t>(y) * a.width() + x])
        ++d.at_tile_edges;
  return d;
}

WallCheck check_wall(const TileLayout& layout, Scene& scene, int frame, bool locate_edges) {
  std::vector<RgbImage> frames;
  for (int s = 0; s < static_cast<int>(layout.pipeservers.size()); ++s) {
    Pipeserver ps(layout, s);
    frames.push_back(ps.render_frame(frame, scene));
  }
  WallCheck out;
  out.reassembly = reassemble(layout.wall, frames);
  // KEY and DEPTH strips are composited by the emulator's router (spec §7), not by this copy.
  const bool composited = std::any_of(layout.tiles.begin(), layout.tiles.end(), [](const auto& t) {
    return t.compositing != Compositing::Copy;
  });
  if (composited) out.reassembly.displays = route_on_wall(layout.wall, frames);
  for (const Display& d : layout.wall.displays) {
    const RgbImage& got = out.reassembly.displays[static_cast<std::size_t>(d.id)];
    const RgbImage want = render_reference(layout, d.id, scene, frame);
    out.diffs.push_back(locate_edges ? compare(got, want, layout, d.id) : compare(got, want));
    out.display_pixels += static_cast<long>(d.width) * d.height;
  }
  return out;
}

SceneOptions small_options() {
  SceneOptions o;
  o.triangles = 3000;
  o.grid = 12;
  o.tessellation = 4;
  o.patches = 3;
  return o;
}

}  // namespace l2::test
