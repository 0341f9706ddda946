// Triangle meshes from model files, read with Assimp: glTF 2.0 (.gltf/.glb), OBJ, PLY, STL, FBX
// and the other formats it imports.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace l2 {

struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;  // three per triangle; polygons are triangulated
  std::vector<glm::vec3> normals;      // per vertex, unit length; empty: the file had none
  std::vector<glm::vec3> colours;      // per vertex base colour 0..1; empty: the file had none
  // The file's faces that cover nothing, left out, in one line naming the file
  // ("model.glb: 10419 of 75730 triangles degenerate (a vertex repeated), left out"); empty
  // when there were none.
  std::string left_out;
};

// The node hierarchy is flattened (each mesh placed by its node's transform) into one mesh.
// Degenerate faces (two corners at one point, or three on one line) are left out and said so in
// `left_out`. Throws std::runtime_error with one line naming the file and what is wrong:
// unreadable or damaged (Assimp's reason), no triangles (none at all, or only degenerate ones),
// a face with fewer than three vertices, an index out of range, a vertex index repeated in a
// row in an ASCII PLY (a face line cut short), or a coordinate that is not a finite float.
TriangleMesh load_mesh(const std::filesystem::path& path);

// Reads and checks the file as load_mesh does, without building the mesh (Assimp's
// post-processing, most of the time a large model takes): l2wall refuses a damaged model with
// it before starting the pipeservers. Throws as load_mesh does; returns load_mesh's `left_out`
// line, so that a run says it once, not once per pipeserver.
[[nodiscard]] std::string check_model(const std::filesystem::path& path);

}  // namespace l2
