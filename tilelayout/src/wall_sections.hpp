// The sections of a wall file, each read by its own function. Private to the loader.
#pragma once

#include "tilelayout/wall.hpp"
#include "toml_fields.hpp"

namespace l2 {

// `stereo` (optional, top level or a [stereo] section): read first, since it says what the
// displays' `eye` may be.
void read_stereo(const TomlFields& top, Wall& wall);
// The displays' eyes (`eye`; a passive grid twinned for the right eye): needs the displays.
void read_stereo_displays(const TomlFields& top, Wall& wall);
// What a stereo wall cannot do yet, refused in one line: needs everything else read.
void check_stereo(const TomlFields& top, const Wall& wall);
// [display_grid] or [[display]]: fills wall.displays.
void read_displays(const TomlFields& top, Wall& wall);
// `gain`, `offset` and `lut` of one display (a [[display]] entry, one of a grid's `colour`).
ColourMatch read_colour(const TomlFields& f);
// `warp` of one [[display]] entry (optional): needs the display's size.
void read_warp(const TomlFields& f, Display& d);
// `alpha`, `beta` and `alpha_gamma` of one [[display]] entry (optional): needs the display's size.
void read_levels(const TomlFields& f, Display& d);
// [display_grid] `colour` (optional): one table of those keys per display, in id order.
void read_grid_colour(const TomlFields& grid, std::vector<Display>& displays);
// [displays] (optional): each display's refresh clock and the house sync. Needs the displays.
void read_display_clocks(const TomlFields& top, Wall& wall);
// [canvas] (optional): fills the canvas size and checks every display lies on it.
void read_canvas(const TomlFields& top, Wall& wall);
// [tiling]: needs the canvas.
void read_tiling(const TomlFields& top, Wall& wall);
// [pipeservers] and [mesh].
void read_pipeservers_and_mesh(const TomlFields& top, Wall& wall);
// [depth] and [overlay] (optional): needs the displays and the pipeservers.
void read_compositing(const TomlFields& top, Wall& wall);
// [balance] (optional): needs [depth] and [overlay] read, which it cannot be combined with.
void read_balance(const TomlFields& top, Wall& wall);
// The meshes (several_meshes.hpp): as the displays give them, else the planner's choice, and
// each mesh's share of the pipeservers. Needs everything else read: a wall of several meshes
// refuses what only a wall of one mesh can do yet.
void read_meshes(const TomlFields& top, Wall& wall);
// `blend` (optional, top level or a [blend] section): needs the displays, whose overlaps it
// blends.
void read_blend(const TomlFields& top, Wall& wall);

}  // namespace l2
