// Walls of more displays than one mesh addresses. A strip header's display id has 6 bits, so a
// mesh drives at most 64 displays; a larger wall is served by several meshes, as an
// installation chains several Lightning-2 meshes, each with its own display ids 0..63 and its
// own pipeservers: a pipeserver's headers cannot say which mesh, so each feeds exactly one.
// This file owns which mesh drives each display, how the pipeservers are shared out, and the
// wall each mesh sees (its displays renumbered 0.., its pipeservers as inputs 0..), which the
// planner plans as any wall of one mesh. Pure: no I/O.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

// The planner's choice of meshes for `displays` (in id order): the fewest meshes, each of
// adjacent displays. The displays are cut in two along the longer side of the box their
// centres span, in proportion to the meshes each side gets, and each side again, until each
// part fits a mesh (a k-d split of the wall). Returns each display's mesh, in id order.
std::vector<int> choose_meshes(const std::vector<Display>& displays);

// How many of `pipeservers` feed each mesh: in proportion to the pixels of its displays
// (largest remainders first, ties to the lower mesh), at least one each. `mesh_pixels` holds
// each mesh's display pixels; needs pipeservers >= mesh_pixels.size().
std::vector<int> share_pipeservers(int pipeservers, const std::vector<long long>& mesh_pixels);

// Every mesh of `wall`, in mesh order (one for a wall of one mesh).
std::vector<MeshPart> mesh_parts(const Wall& wall);

// The meshes of a plan: TileLayout::meshes, or the wall's when a plan made by hand left them
// out.
std::vector<MeshPart> meshes_of(const TileLayout& layout);

// The wall one mesh sees: the whole canvas, its displays with ids 0.. in wall id order, its
// share of the pipeservers; everything else as `wall` says. A wall of one mesh.
Wall mesh_wall(const Wall& wall, const MeshPart& part);

// A mesh's plan: the plan of mesh_wall, in the mesh's own numbers (display ids as its headers
// carry them, pipeservers as its inputs).
struct MeshPlan {
  MeshPart part;
  TileLayout layout;
};

// Plans one mesh; a LayoutError says which mesh before the planner's words.
MeshPlan plan_mesh(const Wall& wall, const MeshPart& part);

// The plan of every mesh put together in the wall's numbers: what plan_layout gives for a wall
// of several meshes, and what a live run drives. Its pipeservers are the wall's (each plan's
// `mesh` says which it feeds), its tiles' `display` the wall's display and `header_display`
// the mesh's, logical tiles mesh after mesh.
TileLayout plan_several_meshes(const Wall& wall);

// "mesh 1: 40 displays (wall displays 8-15, 24-31, ...), 40 pipeservers (40-79 as its inputs
// 0-39), 10 x 5 boards": one line for people, the wall's numbers beside the mesh's.
std::string mesh_heading(const MeshPart& part, int board_rows, int board_columns);

// Throws LayoutError when `wall` has several meshes, naming the file and saying what `what`
// ("lightning2_emu") cannot do: "walls/s.toml:7: the wall's 80 displays need 2 meshes (a strip
// header addresses 64); lightning2_emu drives one mesh: l2wall run runs every mesh, tilelayout
// --wall plans and --verify checks them".
void require_one_mesh(const Wall& wall, std::string_view what);

// "8-15, 24-31, 40": ascending numbers as runs.
std::string number_runs(const std::vector<int>& ascending);

}  // namespace l2
