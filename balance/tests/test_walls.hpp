// Walls the balance tests share.
#pragma once

#include "tilelayout/wall.hpp"

namespace l2::test {

// One 100x100 display, two pipeservers, 2x2 strips dealt round-robin: pipeserver 0 renders
// tiles 0 and 2 (the left column), pipeserver 1 tiles 1 and 3.
inline Wall strips_wall(int fb_width = 256, int fb_height = 256) {
  Wall w;
  Display d;
  d.width = d.height = 100;
  w.displays = {d};
  w.canvas_width = w.canvas_height = 100;
  w.tiling.kind = TilingKind::Strips;
  w.tiling.strip_count = w.tiling.substrip_count = 2;
  w.pipeserver_count = 2;
  w.framebuffer_width = fb_width;
  w.framebuffer_height = fb_height;
  return w;
}

}  // namespace l2::test
