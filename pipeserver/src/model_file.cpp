// load_mesh with Assimp. Assimp accepts some damaged files without an error (a PLY face line
// cut short comes out with a vertex repeated, a coordinate can be NaN or infinite), so its
// validation step runs and the faces and vertices are checked again here before anything else
// sees them: every bad file is refused with one line naming it.
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>
#include <assimp/Importer.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "pipeserver/model_file.hpp"
#include "ply_counts.hpp"

namespace l2 {

namespace {

// Read with validation only; after the checks of the raw faces, Triangulate (polygons to
// triangles), PreTransformVertices (every mesh moved by its node's transform into one space:
// glTF and FBX scenes are hierarchies) and JoinIdenticalVertices (the importers that emit one
// vertex per face corner, PLY and STL, share them again, so normals are smooth). The checks come
// first because Assimp's post-processing asserts (aborting the process) on some faces its
// importers produce. Normals are not generated here: the scene computes area-weighted ones
// where a file has none.
constexpr unsigned kRead = aiProcess_ValidateDataStructure;
constexpr unsigned kSteps =
    aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_JoinIdenticalVertices;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
  throw std::runtime_error(fmt::format("{}: {}", path.string(), why));
}

// A material's colour counts only when the file gave one. glTF's base colour always does; a
// diffuse colour only in a material of the file's own: Assimp adds a grey one, unnamed or named
// AI_DEFAULT_MATERIAL_NAME, to files without materials (PLY, STL, OBJ without .mtl).
bool material_colour(const aiMaterial& m, glm::vec3& out) {
  aiColor4D c;
  const aiString name = m.GetName();
  const bool own = name.length > 0 && name != aiString(AI_DEFAULT_MATERIAL_NAME);
  if (m.Get(AI_MATKEY_BASE_COLOR, c) != AI_SUCCESS &&
      !(own && m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS))
    return false;
  out = {c.r, c.g, c.b};
  return true;
}

void check_finite(const std::filesystem::path& path, std::size_t vertex, const aiVector3D& v) {
  const float xyz[3] = {v.x, v.y, v.z};
  for (int axis = 0; axis < 3; ++axis) {
    if (std::isfinite(xyz[axis])) continue;
    fail(path,
         fmt::format("vertex {}: {} = {} is not a finite float", vertex, "xyz"[axis], xyz[axis]));
  }
}

// The faces and vertices as imported, before any post-processing step sees them.
void check_raw(const std::filesystem::path& path, const aiScene& scene) {
  std::size_t faces = 0;
  for (unsigned i = 0; i < scene.mNumMeshes; ++i) {
    const aiMesh& m = *scene.mMeshes[i];
    for (unsigned v = 0; v < m.mNumVertices; ++v) check_finite(path, v, m.mVertices[v]);
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      const aiFace& face = m.mFaces[f];
      if (face.mNumIndices < 3) {
        fail(path, fmt::format("face {} has {} vertices, a surface needs at least 3", faces + f,
                               face.mNumIndices));
      }
      for (unsigned j = 0; j < face.mNumIndices; ++j) {
        if (face.mIndices[j] >= m.mNumVertices) {
          fail(path, fmt::format("face {} refers to vertex {} of {}", faces + f, face.mIndices[j],
                                 m.mNumVertices));
        }
        // Assimp reads an ASCII PLY face line by line: one cut short or spread over two lines
        // comes out with a vertex repeated, not as an error.
        if (face.mIndices[j] == face.mIndices[(j + 1) % face.mNumIndices]) {
          fail(path, fmt::format("face {} has vertex {} twice in a row (a face line cut short?)",
                                 faces + f, face.mIndices[j]));
        }
      }
    }
    faces += m.mNumFaces;
  }
  if (faces == 0) fail(path, "no triangles");
}

struct Counts {
  std::size_t vertices = 0, triangles = 0;
  bool normals = true, colours = false;
};

Counts count(const std::filesystem::path& path, const aiScene& scene) {
  Counts n;
  for (unsigned i = 0; i < scene.mNumMeshes; ++i) {
    const aiMesh& m = *scene.mMeshes[i];
    n.vertices += m.mNumVertices;
    n.triangles += m.mNumFaces;
    n.normals = n.normals && m.HasNormals();
    glm::vec3 unused;
    n.colours = n.colours || m.HasVertexColors(0) ||
                material_colour(*scene.mMaterials[m.mMaterialIndex], unused);
  }
  if (n.triangles == 0) fail(path, "no triangles");
  if (n.vertices > std::numeric_limits<std::uint32_t>::max())
    fail(path, fmt::format("{} vertices, more than 2^32", n.vertices));
  return n;
}

// Appends one Assimp mesh, its indices offset by the vertices already there.
void append(const std::filesystem::path& path, const aiScene& scene, const aiMesh& m,
            const Counts& n, TriangleMesh& out) {
  const auto base = static_cast<std::uint32_t>(out.positions.size());
  glm::vec3 colour{0.86f, 0.80f, 0.68f};
  material_colour(*scene.mMaterials[m.mMaterialIndex], colour);
  for (unsigned v = 0; v < m.mNumVertices; ++v) {
    const aiVector3D& p = m.mVertices[v];
    check_finite(path, out.positions.size(), p);  // a node transform can overflow
    out.positions.emplace_back(p.x, p.y, p.z);
    if (n.normals) {
      const aiVector3D& q = m.mNormals[v];
      const glm::vec3 normal(q.x, q.y, q.z);
      const float length =
          std::sqrt(normal.x * normal.x + normal.y * normal.y + normal.z * normal.z);
      out.normals.push_back(std::isfinite(length) && length > 0 ? normal / length
                                                                : glm::vec3(0, 0, 1));
    }
    if (n.colours) {
      if (m.HasVertexColors(0)) {
        const aiColor4D& c = m.mColors[0][v];
        out.colours.emplace_back(c.r, c.g, c.b);
      } else {
        out.colours.push_back(colour);
      }
    }
  }
  for (unsigned f = 0; f < m.mNumFaces; ++f) {
    const aiFace& face = m.mFaces[f];
    for (unsigned j = 0; j < face.mNumIndices; ++j) out.indices.push_back(base + face.mIndices[j]);
  }
}

// Imported and checked, not yet post-processed.
const aiScene& read_checked(Assimp::Importer& importer, const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) fail(path, "cannot open: no such file");
  detail::check_ply_counts(path);
  const aiScene* scene = importer.ReadFile(path.string(), kRead);
  if (scene == nullptr) fail(path, importer.GetErrorString());
  if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0) fail(path, "no triangles");
  check_raw(path, *scene);
  return *scene;
}

}  // namespace

void check_model(const std::filesystem::path& path) {
  Assimp::Importer importer;
  read_checked(importer, path);
}

TriangleMesh load_mesh(const std::filesystem::path& path) {
  Assimp::Importer importer;
  read_checked(importer, path);
  const aiScene* scene = importer.ApplyPostProcessing(kSteps);
  if (scene == nullptr) fail(path, importer.GetErrorString());
  const Counts n = count(path, *scene);
  TriangleMesh out;
  out.positions.reserve(n.vertices);
  out.indices.reserve(3 * n.triangles);
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) append(path, *scene, *scene->mMeshes[i], n, out);
  return out;
}

}  // namespace l2
