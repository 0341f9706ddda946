// A base-colour texture of a model's material, as the mesh scene draws it: its pixels, and the
// name it has in every GL context that draws it.
#pragma once

#include <cstdint>

#include "image/rgb_image.hpp"

namespace l2 {

// The largest side of a texture a model may have: every pipeserver holds each texture whole,
// and once more in each of its GL contexts, so 8192x8192 (192 MiB of RGB pixels) is already a
// lot. It is also the largest frame side a board takes (spec §5).
inline constexpr int kMaxTextureSide = 8192;

struct ModelTexture {
  explicit ModelTexture(RgbImage pixels);  // takes the next id of the process

  RgbImage image;  // rows top to bottom: texture coordinate (u, v) = (0, 0) is the top left
  // Unique in the process, and the texture's GL name in every context: a context that has no
  // texture of that name has not been given it yet (tile_renderer.cpp).
  std::uint32_t id;
};

}  // namespace l2
