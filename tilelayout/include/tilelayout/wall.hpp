// The description of a display wall, as read from a wall file (TOML): the output displays and
// where they sit on the logical canvas, the pipeservers, the mesh limits and swap-lock groups.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "image/level_map.hpp"
#include "image/orientation.hpp"
#include "image/warp_map.hpp"
#include "strip_headers/strip_header.hpp"
#include "tilelayout/colour_match.hpp"
#include "tilelayout/geometry.hpp"

namespace l2 {

// Which eye a display shows on a passive stereo wall (`eye` of a display): none on every other
// wall. Named as in the wall file.
enum class Eye { None, Left, Right };
inline constexpr std::string_view kEyeNames[] = {"none", "left", "right"};

// A display (panel or projector): its native raster, which strip headers address, and the canvas
// rectangle it shows as it hangs. A panel turned by 90 or 270 covers its native size turned.
struct Display {
  // Its number in the wall, 0..kMaxWallDisplays-1; in the wall of one mesh (mesh_wall) the
  // number strip headers carry, 0..63.
  int id = 0;
  int width = 0, height = 0;       // native, as the panel reports it: its frames' size
  int canvas_x = 0, canvas_y = 0;  // top-left corner of its canvas rectangle
  int swap_group = 0;              // displays of one group swap together (spec §6)
  std::string monitor;             // optional monitor name or index for --show monitors
  Orientation orientation;         // as mounted (image/orientation.hpp)
  ColourMatch colour;              // applied where its pixels leave the wall (colour_match.hpp)
  // `warp`: the geometry warp file as written, relative to the wall file, and its map, applied
  // before blend and colour where its pixels leave the wall; shared, so that copying a wall does
  // not copy a map of every pixel. No map when there is no warp or it changes nothing.
  std::string warp;
  std::shared_ptr<const WarpMap> warp_map;
  // `alpha`, `beta` (grey PNG files, as written) and `alpha_gamma`, and the one map of gains and
  // offsets they make, applied after the warp; none when there are none or it changes nothing.
  std::string alpha, beta;
  double alpha_gamma = 1.0;
  std::shared_ptr<const LevelMap> level_map;
  int mesh = 0;         // the mesh that drives it (several_meshes.hpp)
  Eye eye = Eye::None;  // passive stereo: the eye whose camera renders its tiles
  // How far its own refresh clock runs from the nominal rate, in parts per million ([displays]
  // clock_ppm): a free-running display refreshes every period / (1 + clock_ppm·1e-6).
  int clock_ppm = 0;

  int canvas_width() const { return orientation.turned() ? height : width; }
  int canvas_height() const { return orientation.turned() ? width : height; }
  Rect on_canvas() const { return {canvas_x, canvas_y, canvas_width(), canvas_height()}; }
  // Which canvas pixel each of its pixels shows.
  PanelMap panel_map() const {
    return l2::panel_map(orientation, width, height, canvas_x, canvas_y);
  }
  // The panel rectangle that shows canvas rectangle `r` (inside on_canvas()), and back.
  Rect to_panel(const Rect& r) const {
    const PanelMap m = panel_map();
    return bounds(m.x_of(r.x, r.y), m.y_of(r.x, r.y), m.x_of(r.right() - 1, r.bottom() - 1),
                  m.y_of(r.right() - 1, r.bottom() - 1));
  }
  Rect to_canvas(const Rect& r) const {
    const PanelMap m = panel_map();
    return bounds(m.u(r.x, r.y), m.v(r.x, r.y), m.u(r.right() - 1, r.bottom() - 1),
                  m.v(r.right() - 1, r.bottom() - 1));
  }

 private:
  // The rectangle with corner pixels (ax, ay) and (bx, by), in any order.
  static Rect bounds(int ax, int ay, int bx, int by) {
    return {std::min(ax, bx), std::min(ay, by), std::abs(bx - ax) + 1, std::abs(by - ay) + 1};
  }
};

// Every pipeserver is a mesh input: 64 board rows of 4 inputs (spec §5; lightning2_emu's
// Mesh::kMaxRows x Board::kInputs). More would plan and then be refused by every run.
inline constexpr int kMaxPipeservers = 256;

// A strip header addresses 64 displays (6 bits), so a larger wall is served by several meshes,
// each with its own display ids 0..63 and its own pipeservers (several_meshes.hpp), as an
// installation chains several Lightning-2 meshes. The limit is a sanity bound, not the spec's.
inline constexpr int kMaxMeshes = 16;
inline constexpr int kMaxWallDisplays = kMaxMeshes * kMaxDisplays;
inline constexpr int kMaxWallPipeservers = kMaxMeshes * kMaxPipeservers;

// Canvas positions are not in strip headers, so the canvas may be far larger than a display: a
// room of four walls unrolled is over 130000 pixels wide. Sides bounded so that a canvas's area
// fits an int.
inline constexpr int kMaxCanvasSide = 1 << 18;
inline constexpr long long kMaxCanvasArea = (1LL << 31) - 1;

enum class TilingKind { Grid, List, KdSplit, Strips };
enum class AssignmentPolicy { RoundRobin, ZigZag, Spiral, Blocks, AreaBalanced };

struct TilingSpec {
  TilingKind kind = TilingKind::Grid;
  int tile_width = 0, tile_height = 0;    // Grid
  std::vector<Rect> rects;                // List, in canvas coordinates
  int tile_count = 0;                     // KdSplit: number of tiles
  std::vector<std::vector<double>> cost;  // KdSplit: cost grid over the canvas (empty: uniform)
  int strip_count = 0;                    // Strips: horizontal strips ...
  int substrip_count = 0;                 // ... each cut into this many vertical sub-strips
};

// `[depth] layers = "all"`: as many layers as there are pipeservers to share them (sort-last).
inline constexpr int kAllLayers = -1;

// `[overlay]`: a rectangle of one display that the last pipeserver renders alone and sends as a
// KEY strip (spec §7): it covers what the other pipeservers route, except where it shows `key`.
struct Overlay {
  int display = 0;
  Rect on_display;
  std::uint32_t key = 0;  // R<<16 | G<<8 | B
  int line = 0;           // of [overlay] in the wall file, for errors found while planning
};

// `[balance]`: how the tiling follows the load, frame by frame (balance/): the wall's own tiling
// every frame, horizontal strips with vertical sub-strips whose edges move toward equal render
// time, or the k-d split re-cut over the last frame's times. Named as in the wall file.
enum class BalanceMode { Static, Strips, Kd };
inline constexpr std::string_view kBalanceModeNames[] = {"static", "strips", "kd"};

struct BalanceSpec {
  BalanceMode mode = BalanceMode::Static;
  // `assignment = "heaviest-first"`: the heaviest tile to the pipeserver that finishes first,
  // instead of [pipeservers] assignment ("policy").
  bool heaviest_first = false;
  // `survive_host_loss = true`: a live run goes on when a pipeserver dies, its tiles re-planned
  // over the others (l2wall run --survive-host-loss).
  bool survive_host_loss = false;
  // `resistance`: a new layout is taken only when predicted to shorten the frame by this
  // fraction; `tile_cost`: a display tile's fixed part in that prediction, as a fraction of
  // the mean tile time (balance/balancer.hpp, BalanceSettings). 0: off.
  double resistance = 0;
  double tile_cost = 0;
  int line = 0;  // of [balance], for errors found later
  // Whether it asks for more than the static tiling: a mode that re-cuts, or the assignment.
  bool balancing() const { return mode != BalanceMode::Static || heaviest_first; }
};

// `blend` (docs/wall-file.md, "Blending overlapping projectors"): where displays' canvas
// rectangles overlap (projectors, negative mullions), each display's pixels are weighted so that
// their light adds up to the picture in linear light at `gamma` (`"linear"`: 1). The maps are
// generated from the displays' rectangles (tilelayout/blend_map.hpp).
inline constexpr double kMaxBlendGamma = 4.0;

struct BlendSpec {
  bool on = false;
  double gamma = 1.0;  // 1..kMaxBlendGamma
  int line = 0;        // of `blend` in the wall file, for errors found later
};

// [displays]: whether the run models each display's own refresh clock, and whether a house
// sync locks them (frame lock). Without the section the displays swap exactly in lock with the
// emulator's refresh clock, as they always did.
struct FrameLockSpec {
  bool modelled = false;    // the wall has a [displays] section
  bool house_sync = false;  // sync = "house": every retrace locked to the house clock
  int line = 0;
};

// `stereo` (docs/wall-file.md, "Stereo walls"): how a wall shows two eyes. Passive: each eye has
// its own displays (Display::eye), every display of one eye twinned with one of the other that
// covers the same canvas rectangle. Active (frame-sequential): every display shows both eyes,
// one after the other (frame_eye below). Packed (side-by-side, top-bottom, as 3D TVs and
// projectors take HDMI frame packing): every display shows both eyes at once, one in each half
// (display_parts below).
enum class StereoMode { Mono, Passive, Active, SideBySide, TopBottom };
inline constexpr std::string_view kStereoModeNames[] = {"mono", "passive", "active", "side-by-side",
                                                        "top-bottom"};

// The eyes' camera, in scene units (the scene fits a sphere of radius 1 about the origin): the
// eyes stand `eye_separation` apart, left and right of the mono camera, and look parallel; the
// plane `convergence` in front of them shows both eyes the same picture (off-axis frusta).
struct StereoSpec {
  StereoMode mode = StereoMode::Mono;
  double eye_separation = 0.1;
  double convergence = 0;  // 0: the distance from the camera to the scene's centre
  int line = 0;            // of `stereo` in the wall file, for errors found later
  bool on() const { return mode != StereoMode::Mono; }
};
inline constexpr double kMaxEyeSeparation = 2.0;  // the scene's diameter
inline constexpr double kMaxConvergence = 1000.0;

struct Wall {
  std::filesystem::path source;  // the wall file, for error messages; empty when built in code
  std::string name;
  int canvas_width = 0, canvas_height = 0;
  std::vector<Display> displays;  // displays[i].id == i
  // The meshes (several_meshes.hpp): how many, and how many of the pipeservers feed each, in
  // mesh order (mesh 0 takes the first ones). One mesh: {pipeserver_count}.
  int mesh_count = 1;
  std::vector<int> mesh_pipeservers;
  int meshes_line = 0;  // where the file gives or implies them, for errors found later
  TilingSpec tiling;
  int pipeserver_count = 1;
  int framebuffer_width = 1280, framebuffer_height = 1024;
  AssignmentPolicy assignment = AssignmentPolicy::RoundRobin;
  int board_max_width = 1280, board_max_height = 1024;  // per-input limit of a board (spec §5)
  int refresh_hz = 60;
  // Depth compositing (spec §7): every display tile rendered as this many layers, each by a
  // different pipeserver with its share of the scene's geometry; 0: no depth compositing (sort-
  // first); kAllLayers: one layer per pipeserver (sort-last).
  int depth_layers = 0;
  std::optional<Overlay> overlay;
  BalanceSpec balance;
  BlendSpec blend;
  FrameLockSpec frame_lock;
  StereoSpec stereo;
  // Lines in the wall file (0: unknown), so errors found while planning can still point there.
  int tiling_line = 0, framebuffer_line = 0, depth_line = 0;
};

inline bool packed_stereo(const StereoSpec& s) {
  return s.mode == StereoMode::SideBySide || s.mode == StereoMode::TopBottom;
}

// What a display shows, part by part. On a packed stereo wall its left (side-by-side) or top
// (top-bottom) half shows the left eye and the other half the right eye, each the picture of the
// display's whole canvas rectangle squeezed into the half (the wall file's checks make the side
// even); the display unpacks and stretches each half back to the whole screen. Any other
// display is one part: its canvas rectangle, showing itself, with its own eye (passive) or none.
struct DisplayPart {
  Rect on_canvas;  // the part's pixels on the canvas
  Eye eye = Eye::None;
  Rect seen;  // the canvas rectangle whose picture it shows: on_canvas unless squeezed
};
inline std::vector<DisplayPart> display_parts(const StereoSpec& stereo, const Display& d) {
  const Rect r = d.on_canvas();
  if (stereo.mode == StereoMode::SideBySide) {
    const int half = r.w / 2;
    return {{{r.x, r.y, half, r.h}, Eye::Left, r}, {{r.x + half, r.y, half, r.h}, Eye::Right, r}};
  }
  if (stereo.mode == StereoMode::TopBottom) {
    const int half = r.h / 2;
    return {{{r.x, r.y, r.w, half}, Eye::Left, r}, {{r.x, r.y + half, r.w, half}, Eye::Right, r}};
  }
  return {{r, d.eye, r}};
}

// A passive stereo wall's twins (the wall file's checks make them one to one): each left-eye
// display with the right-eye display on its canvas rectangle, by left id. Empty for any other.
struct EyePair {
  int left = 0, right = 0;
};
inline std::vector<EyePair> eye_pairs(const Wall& wall) {
  std::vector<EyePair> pairs;
  for (const Display& l : wall.displays) {
    if (l.eye != Eye::Left) continue;
    for (const Display& r : wall.displays)
      if (r.eye == Eye::Right && r.on_canvas() == l.on_canvas()) pairs.push_back({l.id, r.id});
  }
  return pairs;
}

// What frame `frame` of the pipeline shows. On an active wall the frames that pipeservers render,
// stamp and the displays swap are eye frames: eye frame 2k is application frame k's left eye,
// 2k+1 its right, so both eyes of a frame reach every display in consecutive swaps and the
// stamp, headers and routing are those of a mono wall. Any other wall: the frame itself, no eye.
struct FrameEye {
  int frame = 0;  // the application frame: what the scene is set to
  Eye eye = Eye::None;
};
inline FrameEye frame_eye(const StereoSpec& stereo, int frame) {
  if (stereo.mode != StereoMode::Active) return {frame, Eye::None};
  return {frame / 2, frame % 2 == 0 ? Eye::Left : Eye::Right};
}

}  // namespace l2
