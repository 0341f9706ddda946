// Triangle meshes from model files, read with Assimp: glTF 2.0 (.gltf/.glb), OBJ, PLY, STL, FBX
// and the other formats it imports.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/vec3.hpp>

namespace l2 {

struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;  // three per triangle; polygons are triangulated
  std::vector<glm::vec3> normals;      // per vertex, unit length; empty: the file had none
  std::vector<glm::vec3> colours;      // per vertex base colour 0..1; empty: the file had none
};

// The node hierarchy is flattened (each mesh placed by its node's transform) into one mesh.
// Throws std::runtime_error with one line naming the file and what is wrong: unreadable or
// damaged (Assimp's reason), no triangles, a face with fewer than three vertices, an index out
// of range, or a coordinate that is not a finite float.
TriangleMesh load_mesh(const std::filesystem::path& path);

// Reads and checks the file as load_mesh does, without building the mesh (Assimp's
// post-processing, most of the time a large model takes): l2wall refuses a damaged model with
// it before starting the pipeservers. Throws as load_mesh does.
void check_model(const std::filesystem::path& path);

}  // namespace l2
