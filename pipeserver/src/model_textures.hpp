// The base-colour textures of a model's materials (glTF baseColorTexture, OBJ map_Kd, FBX's
// diffuse map), as Assimp gives them: embedded in the file (compressed picture bytes or raw
// texels) or in a picture file beside it. Read once each, however many meshes use them.
#pragma once

#include <assimp/scene.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "pipeserver/model_texture.hpp"

namespace l2::detail {

struct MeshTexture {
  std::int32_t texture = -1;  // into ModelTextures::textures; -1: the mesh's colour only
  unsigned channel = 0;       // the mesh's texture coordinates it is mapped with
};

struct ModelTextures {
  std::vector<std::shared_ptr<const ModelTexture>> textures;
  std::vector<MeshTexture> of_mesh;  // per mesh of the scene
  // One line per texture left out, naming the model and the texture: a file missing or damaged,
  // or a mesh without texture coordinates. The mesh is drawn in its material's colour.
  std::vector<std::string> left_out;
};

// Throws std::runtime_error naming the model and the texture when a texture has a side over
// kMaxTextureSide (checked on the picture's header, before its pixels are read).
ModelTextures read_textures(const std::filesystem::path& model, const aiScene& scene);

}  // namespace l2::detail
