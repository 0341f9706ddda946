// Reading a window's pixels back from the X server (XGetImage): the contents the screen shows,
// independent of the GL driver's buffers. Used for tests and the s-key screenshots.
#pragma once

#include "image/rgb_image.hpp"
#include "tilelayout/geometry.hpp"

struct GLFWwindow;

namespace l2 {

// `area` in window pixels. Throws DisplayError when the X server refuses (window not viewable
// or partly off screen) instead of letting Xlib's default handler end the process.
// Xlib stays inside the .cpp: its macros (None, Bool, Status) clash with ordinary C++ names.
RgbImage read_x11_window(GLFWwindow* window, const Rect& area);

}  // namespace l2
