// A planned routing: which pipeserver renders which tile, and where each tile sits in that
// pipeserver's framebuffer (spec §4). Everything downstream — rendering, header drawing,
// scan-out, routing checks — reads this one structure.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "tilelayout/geometry.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

class RgbImage;

// How a tile's strips reach its display: routed (COPY, spec §4), or composited there (§7):
// colour-keyed over what is already on the display, or by depth.
enum class Compositing : std::uint8_t { Copy, Key, Depth };

// A tile that lies within one display: a logical tile after splitting at display edges.
struct DisplayTile {
  int display = 0;
  Rect on_display;       // dx, dy, w, h on the output display
  Rect on_canvas;        // the same pixels on the logical canvas (what the renderer draws)
  int logical_tile = 0;  // index into TileLayout::logical_tiles
  Compositing compositing = Compositing::Copy;
  std::uint32_t key = 0;    // Key: the key colour, R<<16 | G<<8 | B
  Orientation orientation;  // the display's: on_display is on_canvas turned so (tile_map)
  // In a wall of several meshes, `display` is the wall's number and this the mesh's, which its
  // strip headers carry (several_meshes.hpp); -1: the same as `display`.
  int header_display = -1;
};

// The display id a tile's strip headers carry.
inline int header_id(const DisplayTile& t) {
  return t.header_display < 0 ? t.display : t.header_display;
}

// Tile pixel (i, j) of `t` (from the top-left of on_display) shows the pixel of on_canvas at
// offset (u(i, j), v(i, j)): the display's PanelMap, anchored on the tile.
inline PanelMap tile_map(const DisplayTile& t) {
  PanelMap m = panel_map(t.orientation, 2, 2);  // only the signs and the swap matter
  m.u0 = (m.ux < 0 ? t.on_display.w - 1 : 0) + (m.uy < 0 ? t.on_display.h - 1 : 0);
  m.v0 = (m.vx < 0 ? t.on_display.w - 1 : 0) + (m.vy < 0 ? t.on_display.h - 1 : 0);
  return m;
}

// Columns before a tile's pixels on each of its scanlines: its header, and for KEY and DEPTH
// the extension word (§7).
inline int gap_columns(const DisplayTile& t) {
  return t.compositing == Compositing::Copy ? 2 : 4;
}
// Columns of a tile's strip: its width, and for DEPTH as many depth pixels after them.
inline int payload_columns(const DisplayTile& t) {
  return t.on_display.w * (t.compositing == Compositing::Depth ? 2 : 1);
}

// A tile placed in a pipeserver framebuffer. Its gap is the gap_columns(tile) columns before
// fb_x, on rows fb_y .. fb_y + row height - 1; its colour pixels are fb_x .. fb_x+w-1,
// fb_y .. fb_y+h-1, and a DEPTH tile's depth pixels the w columns after them.
struct PackedTile {
  DisplayTile tile;
  int fb_x = 0, fb_y = 0;
};

// A row of packed tiles (spec §4 rule 2): as tall as its tallest tile.
struct PackedRow {
  int y = 0, height = 0;
  int first_tile = 0, tile_count = 0;  // range in PipeserverPlan::tiles
};

struct PipeserverPlan {
  int pipeserver = 0;
  int mesh = 0;  // the mesh it feeds (several_meshes.hpp)
  // Depth walls: the pipeserver renders share `layer` (0..layers-1) of the scene's geometry, in
  // draw order. Sort-first pipeservers, and the overlay's, render all of it: layer 0 of 1.
  int layer = 0, layers = 1;
  int fb_width = 0, fb_height = 0;
  std::vector<PackedTile> tiles;  // in packing order
  std::vector<PackedRow> rows;
  // The stamp strip: one pixel that no display shows, for the frame number a live pipeserver
  // writes (l2wall/frame_stamp.hpp), at (stamp_x, rows[stamp_row].y). It is a tile of height
  // zero after the last tile of the first row with three columns left: by spec §4 rule 3 it
  // takes a SKIP header of width 1 on every scanline of that row, and the mesh routes nothing of
  // it. -1: no row has room; the stamp then marks the first tile's first pixel.
  int stamp_row = -1;
  int stamp_x = 0;
  int used_height() const { return rows.empty() ? 0 : rows.back().y + rows.back().height; }
  bool has_stamp_strip() const { return stamp_row >= 0; }
};

// Columns the stamp strip takes after its row's last tile: its SKIP header and its pixel.
inline constexpr int kStampStripColumns = 3;

// One mesh of a wall: its displays (wall ids, in mesh id order: displays[k] is the display
// its headers call k) and the wall pipeservers that feed its inputs 0.. (several_meshes.hpp).
struct MeshPart {
  int mesh = 0;
  std::vector<int> displays;
  int first_pipeserver = 0, pipeserver_count = 0;
};

struct TileLayout {
  Wall wall;
  // Every mesh, in mesh order: one for a wall of one mesh. A wall of several is planned mesh by
  // mesh and put together: tiles, pipeservers and logical tiles in the wall's numbers, each
  // tile's header_display its mesh's.
  std::vector<MeshPart> meshes;
  std::vector<Rect> logical_tiles;   // canvas rectangles, in tiling order; the overlay last
  std::vector<DisplayTile> tiles;    // split at display edges; pixels behind mullions dropped
  std::vector<int> tile_pipeserver;  // tiles[i] is rendered by pipeserver tile_pipeserver[i]
                                     // (a depth wall lists each display tile once a layer)
  std::vector<PipeserverPlan> pipeservers;  // one per pipeserver
  std::vector<std::string> warnings;        // for example canvas area left uncovered
};

// A wall that cannot be used as written. what() is one line naming file, line and field where
// they are known: "walls/x.toml:12: tiling.tile_width: must be 1..4095, got 0".
class LayoutError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Packs tiles into one framebuffer exactly per spec §4 rules 1, 2 and 5, KEY and DEPTH tiles
// with their four-column gaps and payloads (§7). Throws LayoutError naming the pipeserver, the
// tile and by how much it does not fit.
PipeserverPlan pack_tiles(int pipeserver, int fb_width, int fb_height,
                          const std::vector<DisplayTile>& tiles);

// Gives a packed plan its stamp strip, after the last tile of the first row with
// kStampStripColumns left (PipeserverPlan::stamp_row): what a live run's plans have. The tiles
// stay where they are; a plan whose rows are all full gets none.
void place_stamp_strip(PipeserverPlan& plan);

// Draws every header of spec §4 rule 3 (COPY / SKIP / END, and EXT with its extension word,
// §7) into `fb` for the given parity; touches only header pixels. `fb` must be fb_width x
// fb_height.
void draw_headers(const PipeserverPlan& plan, bool frame_parity, RgbImage& fb);

// Spec §4 rule 4: blacks every pixel that is neither a tile pixel nor a header gap of a packed
// row (scanlines below the last row, the rest of a row after its END, the parts of a row below
// a shorter tile). A renderer calls it so leftover pixels are never read as headers.
void clear_outside_tiles(const PipeserverPlan& plan, RgbImage& fb);

}  // namespace l2
