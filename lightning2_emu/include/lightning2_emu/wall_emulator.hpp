// A wall file's wall as the emulator sees it: its displays as DisplaySpecs and the smallest
// mesh of boards that takes its pipeservers and displays. Every part that builds a router or
// an emulator for a wall (the live run, the MPI columns, golden checks, the verifier) asks here.
//
// Example:
//   const Wall wall = load_wall("walls/monitors-4x3.toml");
//   Emulator emulator(emulator_config(wall, /*workers=*/2));
//   Router column(wall_mesh(wall), display_specs(wall, {8, 9, 10, 11}), pool);
#pragma once

#include <span>
#include <vector>

#include "lightning2_emu/display_buffers.hpp"
#include "lightning2_emu/emulator.hpp"
#include "lightning2_emu/mesh.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

// Every display of the wall, in the wall's order.
std::vector<DisplaySpec> display_specs(const Wall& wall);
// The displays of the wall whose ids are in `ids`, in the wall's order.
std::vector<DisplaySpec> display_specs(const Wall& wall, std::span<const int> ids);
// The ids of the wall's displays, in the wall's order.
std::vector<int> display_ids(const Wall& wall);
// The mesh the live run builds: as few boards as take the wall's pipeservers and displays,
// inputs up to the wall's board limit.
Mesh wall_mesh(const Wall& wall);
// The whole wall on that mesh, `workers` routing threads.
EmulatorConfig emulator_config(const Wall& wall, int workers);

}  // namespace l2
