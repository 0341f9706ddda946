// A desktop's pixels for one frame (--scene vnc, docs/vnc.md), from the coordinator to one
// pipeserver on its windows channel, in answer to its WANT: only the rectangles of the desktop
// that its tiles show and that changed since the last frame it was sent. One header line, then
// its RECT lines:
//
//   DESKTOP <frame> <width> <height> <n> (<x> <y> <w> <h>)... <rects>
//                      width x height: the desktop; n regions: the canvas rectangles this
//                      pipeserver holds the desktop of (its tiles, clipped to the desktop);
//                      rects: how many RECT lines follow
//   RECT <x> <y> <w> <h> <pixels>
//                      the desktop's pixels in that rectangle (inside one region): RGB rows
//                      top to bottom, zstd-compressed, in base64
//
// A region the pipeserver did not hold in its last frame is sent whole.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "balance/control_messages.hpp"

namespace l2 {

struct DesktopMessage {
  int frame = 0;
  int width = 0, height = 0;
  std::vector<Rect> regions;
  int rects = 0;
};

struct DesktopRect {
  Rect rect;
  std::vector<std::uint8_t> rgb;  // rect.w * rect.h * 3 bytes
};

// The largest desktop side (RFB's sizes are 16 bits).
inline constexpr int kMaxDesktopSide = 65535;
// A RECT line holds at most this many pixel bytes (before compression): desktop_bands cuts a
// rectangle in bands of rows that fit, so every line stays far under kMaxControlLine.
inline constexpr std::size_t kMaxDesktopRectBytes = 1u << 20;

std::string encode(const DesktopMessage& m);
DesktopMessage decode_desktop(std::string_view line);
// `rgb` points at the rectangle's top-left pixel, rows `stride` bytes apart.
std::string encode_desktop_rect(const Rect& r, const std::uint8_t* rgb, std::size_t stride);
// Throws ControlError for a line that is not one, or pixels that do not fill the rectangle.
DesktopRect decode_desktop_rect(std::string_view line);

// `r` as bands of whole rows, each at most kMaxDesktopRectBytes of pixels, top to bottom.
std::vector<Rect> desktop_bands(const Rect& r);

}  // namespace l2
