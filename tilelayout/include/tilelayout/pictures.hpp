// Pictures of a plan, for people: what each framebuffer holds and who renders which part of
// the wall. Pure drawing; tilelayout --png writes them.
#pragma once

#include "image/rgb_image.hpp"
#include "tilelayout/tile_layout.hpp"

namespace l2 {

// A distinct, bright colour for index i (displays, pipeservers).
Rgb palette_colour(int i);

// One pipeserver framebuffer: header gaps white (wider than 2 columns on large framebuffers, so
// they show scaled down), tiles in their destination display's colour and labelled "D<display>
// L<logical tile>" (the display alone where that does not fit), a DEPTH tile's depth pixels in a
// darker shade ("... depth"), unused space dark grey.
RgbImage framebuffer_picture(const PipeserverPlan& plan);
// The same with a legend below: what the colours and labels mean (tilelayout --png).
RgbImage framebuffer_page(const PipeserverPlan& plan);

// The canvas (shrunk by a whole factor when longer than 4096 pixels): mullions dark grey, display
// edges outlined, each display tile in its pipeserver's colour with a dark outline and labelled
// "P<pipeserver> L<logical tile>" (the pipeserver alone where that does not fit).
// In a depth wall, the tiles of one depth layer (0..wall_layers - 1) and the overlay.
RgbImage wall_picture(const TileLayout& layout, int layer = 0);
// The same with a legend below (tilelayout --png).
RgbImage wall_page(const TileLayout& layout, int layer = 0);
// A wall of several meshes (several_meshes.hpp): the canvas drawn as wall_picture draws it,
// each display in its mesh's colour, labelled "M<mesh> D<wall display>", with a legend of the
// pipeservers that feed each mesh.
RgbImage meshes_page(const Wall& wall);
// Depth layers of the plan: 1 for a wall without [depth].
int wall_layers(const TileLayout& layout);

}  // namespace l2
