// Where a packed tile goes on the viz path (docs/vizserver-protocol.md):
// its display rectangle and how it is composited. Header-only, for the users that link the
// vizserver library (the live pipeserver, l2wall's golden images).
#pragma once

#include "tilelayout/tile_layout.hpp"
#include "viz_link/tile_sender.hpp"

namespace l2 {

inline viz::TileTarget viz_target(const DisplayTile& t) {
  const Rect& r = t.on_display;
  const viz::TileKind how = t.compositing == Compositing::Key     ? viz::TileKind::Key
                            : t.compositing == Compositing::Depth ? viz::TileKind::Depth
                                                                  : viz::TileKind::Copy;
  return {t.display, r.x, r.y, r.w, r.h, how, t.key};
}

}  // namespace l2
