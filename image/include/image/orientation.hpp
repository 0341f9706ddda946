// How a display panel hangs on the wall: turned clockwise, seen from the front, by a multiple of
// 90 degrees, then mirrored in its own raster; and PanelMap, which canvas pixel each of the
// panel's pixels shows. Pure integer geometry: every stage that turns pixels (the pipeserver
// packing a tile, the reference a check compares with, a window showing the panel as it hangs)
// asks this one map, so they cannot disagree.
#pragma once

#include <cstdint>
#include <string_view>

namespace l2 {

enum class Flip : std::uint8_t { None, Horizontal, Vertical };
inline constexpr std::string_view kFlipNames[] = {"none", "horizontal", "vertical"};

struct Orientation {
  int rotation = 0;  // 0, 90, 180 or 270
  Flip flip = Flip::None;

  // Whether the panel's canvas rectangle is its native size turned (portrait for a landscape
  // panel).
  bool turned() const { return rotation == 90 || rotation == 270; }
  bool identity() const { return rotation == 0 && flip == Flip::None; }
  friend bool operator==(const Orientation&, const Orientation&) = default;
};

// Panel pixel (x, y) shows canvas pixel (u, v) = (ux*x + uy*y + u0, vx*x + vy*y + v0): the panel
// mirrored first (flip, in panel coordinates), then turned (rotation), onto its canvas rectangle.
// The linear part is a signed permutation, so the inverse is its transpose.
struct PanelMap {
  int ux = 1, uy = 0, u0 = 0;
  int vx = 0, vy = 1, v0 = 0;

  int u(int x, int y) const { return ux * x + uy * y + u0; }
  int v(int x, int y) const { return vx * x + vy * y + v0; }
  // The panel pixel that shows canvas pixel (u, v).
  int x_of(int u, int v) const { return ux * (u - u0) + vx * (v - v0); }
  int y_of(int u, int v) const { return uy * (u - u0) + vy * (v - v0); }
  bool straight() const { return ux == 1 && uy == 0 && vx == 0 && vy == 1; }
  friend bool operator==(const PanelMap&, const PanelMap&) = default;
};

// The map of a panel of `width` x `height` native pixels whose canvas rectangle's top-left
// corner is (x0, y0). At rotation 90 (no flip), panel pixel (x, y) shows canvas pixel
// (x0 + height - 1 - y, y0 + x): the panel's top edge runs down the right side of its rectangle.
inline PanelMap panel_map(Orientation o, int width, int height, int x0 = 0, int y0 = 0) {
  // Mirror: x' = sx*x + tx, y' = sy*y + ty.
  const int sx = o.flip == Flip::Horizontal ? -1 : 1, tx = sx < 0 ? width - 1 : 0;
  const int sy = o.flip == Flip::Vertical ? -1 : 1, ty = sy < 0 ? height - 1 : 0;
  PanelMap m;
  switch (o.rotation) {
    case 90:  // u = height-1 - y', v = x'
      m = {0, -sy, height - 1 - ty, sx, 0, tx};
      break;
    case 180:  // u = width-1 - x', v = height-1 - y'
      m = {-sx, 0, width - 1 - tx, 0, -sy, height - 1 - ty};
      break;
    case 270:  // u = y', v = width-1 - x'
      m = {0, sy, ty, -sx, 0, width - 1 - tx};
      break;
    default:
      m = {sx, 0, tx, 0, sy, ty};
      break;
  }
  m.u0 += x0;
  m.v0 += y0;
  return m;
}

}  // namespace l2
