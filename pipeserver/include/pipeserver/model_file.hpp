// Triangle meshes from model files, read with Assimp: glTF 2.0 (.gltf/.glb), OBJ, PLY, STL, FBX
// and the other formats it imports.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "pipeserver/model_texture.hpp"

namespace l2 {

struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;  // three per triangle; polygons are triangulated
  std::vector<glm::vec3> normals;      // per vertex, unit length; empty: the file had none
  std::vector<glm::vec3> colours;      // per vertex base colour 0..1; empty: the file had none
  // The materials' base-colour textures, each drawn multiplied by the colour of its vertices.
  std::vector<std::shared_ptr<const ModelTexture>> textures;
  // Per triangle, the texture it is drawn with (into `textures`), or -1: its colour alone.
  // Empty when there are no textures.
  std::vector<std::int32_t> triangle_textures;
  // Per vertex, where it is on its triangles' texture: (0, 0) the top left of the picture,
  // (1, 1) the bottom right, repeating beyond. Empty when there are no textures.
  std::vector<glm::vec2> uvs;
  // What of the file was left out, one line each, naming the file: its faces that cover
  // nothing ("model.glb: 10419 of 75730 triangles degenerate (a vertex repeated), left out"),
  // textures that cannot be read or mapped ("model.obj: texture 'wood.jpg' left out (cannot
  // read: No such file or directory), drawn in its material's colour"). Empty when nothing was.
  std::string left_out;
};

// The node hierarchy is flattened (each mesh placed by its node's transform) into one mesh.
// Degenerate faces (two corners at one point, or three on one line) are left out and said so in
// `left_out`, and so are textures that cannot be read. Throws std::runtime_error with one line
// naming the file and what is wrong: unreadable or damaged (Assimp's reason), no triangles (none
// at all, or only degenerate ones), a face with fewer than three vertices, an index out of
// range, a vertex index repeated in a row in an ASCII PLY (a face line cut short), a coordinate
// that is not a finite float, or a texture with a side over kMaxTextureSide.
TriangleMesh load_mesh(const std::filesystem::path& path);

// Reads and checks the file as load_mesh does, without building the mesh (Assimp's
// post-processing, most of the time a large model takes; its textures are read): l2wall
// refuses a damaged model with it before starting the pipeservers. Throws as load_mesh does;
// returns load_mesh's `left_out` lines, so that a run says them once, not once per pipeserver.
[[nodiscard]] std::string check_model(const std::filesystem::path& path);

}  // namespace l2
