// Triangle meshes from PLY (ASCII or binary little-endian) and Wavefront OBJ files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/vec3.hpp>

namespace l2 {

struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;  // three per triangle; polygons are fanned
};

// Chooses the reader by extension (.ply, .obj). Throws std::runtime_error with one line naming
// the file, the line where known, and what is wrong.
TriangleMesh load_mesh(const std::filesystem::path& path);

}  // namespace l2
