// load_mesh with Assimp. Assimp accepts some damaged files without an error (a PLY face line
// cut short comes out with a vertex repeated, a coordinate can be NaN or infinite), so its
// validation step runs and the faces and vertices are checked again here before anything else
// sees them: every bad file is refused with one line naming it. Faces that cover nothing (a
// vertex repeated, zero area: common in glTF and OBJ files) are left out and counted. The
// materials' textures are read by model_textures.cpp.
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>
#include <assimp/Importer.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "gltf_check.hpp"
#include "model_textures.hpp"
#include "nesting_check.hpp"
#include "off_counts.hpp"
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

// The faces of a file as imported, and those that cover nothing, left out.
struct LeftOut {
  std::size_t faces = 0;
  std::size_t repeated = 0;   // two corners at one point (the same vertex, or two at one place)
  std::size_t zero_area = 0;  // three distinct corners on one line
  bool polygons = false;      // a face of more than three corners: "faces", not "triangles"
  std::size_t count() const { return repeated + zero_area; }
};

std::string reasons(const LeftOut& n) {
  if (n.zero_area == 0) return "a vertex repeated";
  if (n.repeated == 0) return "zero area";
  return fmt::format("{} with a vertex repeated, {} of zero area", n.repeated, n.zero_area);
}

// "model.glb: 10419 of 75730 triangles degenerate (a vertex repeated), left out"; empty: none.
// `what`: what became of them.
std::string describe(const std::filesystem::path& path, const LeftOut& n,
                     std::string_view what = "left out") {
  if (n.count() == 0) return {};
  const char* noun =
      n.polygons ? (n.faces == 1 ? "face" : "faces") : (n.faces == 1 ? "triangle" : "triangles");
  return fmt::format("{}: {} of {} {} degenerate ({}), {}", path.string(), n.count(), n.faces, noun,
                     reasons(n), what);
}

// Three corners on one line (or at one point): the cross product of two edges, in double from
// the floats, is exactly zero.
bool zero_area(const aiVector3D& a, const aiVector3D& b, const aiVector3D& c) {
  const double u[3] = {double(b.x) - a.x, double(b.y) - a.y, double(b.z) - a.z};
  const double v[3] = {double(c.x) - a.x, double(c.y) - a.y, double(c.z) - a.z};
  return u[1] * v[2] - u[2] * v[1] == 0 && u[2] * v[0] - u[0] * v[2] == 0 &&
         u[0] * v[1] - u[1] * v[0] == 0;
}

// Leaves out a face's corners at the same point as the corner before it (cyclically): what is
// left has a surface if it has three corners or more. Returns false when it has not.
bool drop_repeated_corners(const aiMesh& m, aiFace& face) {
  unsigned n = 0;
  for (unsigned j = 0; j < face.mNumIndices; ++j) {
    const unsigned index = face.mIndices[j];
    if (n > 0 && m.mVertices[index] == m.mVertices[face.mIndices[n - 1]]) continue;
    face.mIndices[n++] = index;
  }
  while (n > 1 && m.mVertices[face.mIndices[n - 1]] == m.mVertices[face.mIndices[0]]) --n;
  face.mNumIndices = n;
  return n >= 3;
}

// The faces and vertices as imported, before any post-processing step sees them. Faces that
// cover nothing are left out of the scene here (glTF and OBJ files from modelling tools have
// them: a vertex repeated, or zero area), and counted; a polygon with a corner repeated in a row
// loses the repeat. In an ASCII PLY a vertex index repeated in a row is refused instead: Assimp
// reads its faces line by line, and one cut short or spread over two lines comes out so.
LeftOut check_raw(const std::filesystem::path& path, aiScene& scene, bool ascii_ply) {
  LeftOut left;
  for (unsigned i = 0; i < scene.mNumMeshes; ++i) {
    aiMesh& m = *scene.mMeshes[i];
    for (unsigned v = 0; v < m.mNumVertices; ++v) check_finite(path, v, m.mVertices[v]);
    unsigned kept = 0;
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      aiFace& face = m.mFaces[f];
      const std::size_t number = left.faces + f;
      if (face.mNumIndices < 3) {
        fail(path, fmt::format("face {} has {} vertices, a surface needs at least 3", number,
                               face.mNumIndices));
      }
      left.polygons = left.polygons || face.mNumIndices > 3;
      for (unsigned j = 0; j < face.mNumIndices; ++j) {
        if (face.mIndices[j] >= m.mNumVertices) {
          fail(path, fmt::format("face {} refers to vertex {} of {}", number, face.mIndices[j],
                                 m.mNumVertices));
        }
        if (ascii_ply && face.mIndices[j] == face.mIndices[(j + 1) % face.mNumIndices]) {
          fail(path, fmt::format("face {} has vertex {} twice in a row (a face line cut short?)",
                                 number, face.mIndices[j]));
        }
      }
      if (!drop_repeated_corners(m, face)) {
        ++left.repeated;
      } else if (face.mNumIndices == 3 &&
                 zero_area(m.mVertices[face.mIndices[0]], m.mVertices[face.mIndices[1]],
                           m.mVertices[face.mIndices[2]])) {
        ++left.zero_area;
      } else {
        // Kept: moved down over the faces left out (their index arrays go to the end, where
        // the mesh's delete[] of its faces still frees them).
        std::swap(m.mFaces[kept].mNumIndices, face.mNumIndices);
        std::swap(m.mFaces[kept].mIndices, face.mIndices);
        ++kept;
      }
    }
    left.faces += m.mNumFaces;
    m.mNumFaces = kept;
  }
  if (left.faces == 0) fail(path, "no triangles");
  if (left.count() == left.faces)
    throw std::runtime_error(describe(path, left, "nothing left to draw"));
  return left;
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

// Where vertex v is on its mesh's texture, (0, 0) the picture's top left (Assimp's (0, 0) is
// OpenGL's, the bottom left). A coordinate that is not finite is 0: GL samples no defined texel
// for it.
glm::vec2 uv_of(const aiMesh& m, const detail::MeshTexture& t, unsigned v) {
  if (t.texture < 0) return {0, 0};
  const aiVector3D& c = m.mTextureCoords[t.channel][v];
  const auto finite = [](float x) { return std::isfinite(x) ? x : 0.0f; };
  return {finite(c.x), 1.0f - finite(c.y)};
}

// Appends one Assimp mesh, its indices offset by the vertices already there. `textured`: the
// model has textures, so every vertex gets texture coordinates and every triangle a texture.
void append(const std::filesystem::path& path, const aiScene& scene, const aiMesh& m,
            const Counts& n, const detail::MeshTexture& t, bool textured, TriangleMesh& out) {
  const auto base = static_cast<std::uint32_t>(out.positions.size());
  glm::vec3 colour{0.86f, 0.80f, 0.68f};
  // A texture with no colour to multiply is drawn as it is.
  if (!material_colour(*scene.mMaterials[m.mMaterialIndex], colour) && t.texture >= 0)
    colour = glm::vec3(1.0f);
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
    if (textured) out.uvs.push_back(uv_of(m, t, v));
  }
  for (unsigned f = 0; f < m.mNumFaces; ++f) {
    const aiFace& face = m.mFaces[f];
    for (unsigned j = 0; j < face.mNumIndices; ++j) out.indices.push_back(base + face.mIndices[j]);
    if (textured) out.triangle_textures.push_back(t.texture);
  }
}

// The faces' line and the textures' lines, one a line.
std::string lines(std::string faces, const std::vector<std::string>& textures) {
  for (const std::string& line : textures) {
    if (!faces.empty()) faces += '\n';
    faces += line;
  }
  return faces;
}

// Imported, checked and its degenerate faces left out (the line saying so returned), not yet
// post-processed.
std::string read_checked(Assimp::Importer& importer, const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) fail(path, "cannot open: no such file");
  // What Assimp would take on trust (sizes a header declares, nesting it walks recursively) is
  // checked against the file first: one line naming the file, not a crash, a hang or gigabytes.
  detail::check_gltf(path);
  detail::check_nesting(path);
  detail::check_off_counts(path);
  const bool ascii_ply = detail::check_ply_counts(path) == detail::PlyFormat::ascii;
  const aiScene* scene = importer.ReadFile(path.string(), kRead);
  if (scene == nullptr) fail(path, importer.GetErrorString());
  if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0) fail(path, "no triangles");
  // The importer's own scene, which it hands out read-only: faces are left out of it in place
  // before the post-processing steps run on it.
  return describe(path, check_raw(path, const_cast<aiScene&>(*scene), ascii_ply));
}

}  // namespace

std::string check_model(const std::filesystem::path& path) {
  Assimp::Importer importer;
  std::string left_out = read_checked(importer, path);
  return lines(std::move(left_out), detail::read_textures(path, *importer.GetScene()).left_out);
}

TriangleMesh load_mesh(const std::filesystem::path& path) {
  Assimp::Importer importer;
  std::string left_out = read_checked(importer, path);
  const aiScene* scene = importer.ApplyPostProcessing(kSteps);
  if (scene == nullptr) fail(path, importer.GetErrorString());
  Counts n = count(path, *scene);
  detail::ModelTextures textures = detail::read_textures(path, *scene);
  const bool textured = !textures.textures.empty();
  n.colours = n.colours || textured;
  TriangleMesh out;
  out.left_out = lines(std::move(left_out), textures.left_out);
  out.textures = std::move(textures.textures);
  out.positions.reserve(n.vertices);
  out.indices.reserve(3 * n.triangles);
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    append(path, *scene, *scene->mMeshes[i], n, textures.of_mesh[i], textured, out);
  }
  return out;
}

}  // namespace l2
