// `tilelayout --wall W` for a wall of several meshes (tilelayout/several_meshes.hpp): every
// mesh planned and printed under a line saying which displays and pipeservers are its own;
// --png, --scanout and --verify write each mesh's files into DIR/mesh-<m>/, in the mesh's own
// numbers (display ids as its headers carry them, pipeservers as its inputs), and --png a
// picture of which mesh drives which display. --verify checks one mesh at a time, so memory
// stays that of one mesh however many there are.
#pragma once

#include <string>

#include "tilelayout/test_frame.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

struct PlanOutputs {
  std::string png_dir, scanout_dir, verify_dir;
  bool parity = false;
  PatternPlace place = PatternPlace::Display;
};

// Exit status as tilelayout's: 0 planned (and verified right), 1 a mesh does not plan, 3 a file
// could not be written, 4 --verify found pixels out of place on some mesh.
int run_several_meshes(const Wall& wall, const PlanOutputs& outputs);

}  // namespace l2
