// `mesh`: a lit triangle mesh (the Stanford bunny by default) turning about the vertical axis.
#include <algorithm>
#include <cmath>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <map>
#include <unordered_map>
#include <utility>

#include "scene_common.hpp"

namespace l2::detail {

namespace {

constexpr int kCells = 3;  // batches: the mesh's box cut into kCells^3 cells by centroid
constexpr glm::vec3 kDefaultColour{0.86f, 0.80f, 0.68f};  // a model file without colours

// Centre the mesh on the origin and scale it into the unit sphere, so any mesh fits the camera.
// A mesh file may hold any finite float, and coordinates near 3.4e38 overflowed to infinity in
// the box's centre and a vertex's distance from it, which made every vertex NaN (nothing drawn).
// So the mesh is first scaled by the power of two that brings its largest coordinate near 1:
// exact in floating point, so a mesh that did not overflow gets the same floats as before.
void normalise(std::vector<glm::vec3>& positions) {
  float largest = 0;
  for (const auto& p : positions) {
    largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  }
  if (largest > 0) {
    int exponent = 0;
    std::frexp(largest, &exponent);
    for (auto& p : positions)
      p = glm::vec3(std::ldexp(p.x, -exponent), std::ldexp(p.y, -exponent),
                    std::ldexp(p.z, -exponent));
  }
  Box box = Box::empty();
  for (const auto& p : positions) box.extend(p);
  const glm::vec3 centre = (box.lo + box.hi) * 0.5f;
  float r = 1e-6f;
  for (const auto& p : positions) r = std::max(r, glm::length(p - centre));
  for (auto& p : positions) p = (p - centre) / r;
}

// Area-weighted vertex normals: smooth shading for a file without normals.
std::vector<glm::vec3> vertex_normals(const TriangleMesh& m) {
  std::vector<glm::vec3> n(m.positions.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
    const auto a = m.indices[i], b = m.indices[i + 1], c = m.indices[i + 2];
    const glm::vec3 f =
        glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
    n[a] += f;
    n[b] += f;
    n[c] += f;
  }
  for (auto& v : n) v = glm::length(v) > 0 ? glm::normalize(v) : glm::vec3(0, 0, 1);
  return n;
}

// One batch of the mesh, its vertices numbered anew.
struct Part {
  Batch batch;
  std::unordered_map<std::uint32_t, std::uint32_t> remap;  // the mesh's vertex -> the batch's
};

class MeshScene : public Scene {
 public:
  MeshScene(TriangleMesh mesh, bool whole) : whole_(whole) {
    note_ = std::move(mesh.left_out);
    normalise(mesh.positions);
    const auto normals = mesh.normals.empty() ? vertex_normals(mesh) : mesh.normals;
    Box box = Box::empty();
    for (const auto& p : mesh.positions) box.extend(p);
    // By texture (one a draw), then by cell; a map, so the batches come in one order everywhere.
    std::map<std::pair<std::int32_t, std::size_t>, Part> parts;
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const glm::vec3 c = (mesh.positions[mesh.indices[i]] + mesh.positions[mesh.indices[i + 1]] +
                           mesh.positions[mesh.indices[i + 2]]) /
                          3.0f;
      const glm::vec3 t = (c - box.lo) / glm::max(box.hi - box.lo, glm::vec3(1e-6f));
      const auto cell = [](float v) {
        return std::clamp(static_cast<int>(v * kCells), 0, kCells - 1);
      };
      const std::size_t k =
          static_cast<std::size_t>(cell(t.x) + kCells * (cell(t.y) + kCells * cell(t.z)));
      const std::int32_t texture =
          mesh.triangle_textures.empty() ? -1 : mesh.triangle_textures[i / 3];
      Part& part = parts[{texture, k}];
      for (int j = 0; j < 3; ++j) {
        const auto src = mesh.indices[i + static_cast<std::size_t>(j)];
        auto [it, added] =
            part.remap.try_emplace(src, static_cast<std::uint32_t>(part.batch.positions.size()));
        if (added) {
          part.batch.positions.push_back(mesh.positions[src]);
          part.batch.normals.push_back(normals[src]);
          part.batch.colours.push_back(mesh.colours.empty() ? kDefaultColour : mesh.colours[src]);
          if (texture >= 0) part.batch.uvs.push_back(mesh.uvs[src]);
        }
        part.batch.indices.push_back(it->second);
      }
    }
    for (auto& [key, part] : parts) {
      if (key.first >= 0) part.batch.texture = mesh.textures[static_cast<std::size_t>(key.first)];
      part.batch.compute_bounds();
      batches_.push_back(std::move(part.batch));
    }
  }

  const char* name() const override { return "mesh"; }

  // The mesh itself stands still; the camera orbits it (3 degrees a frame unless told).
  void animate(int) override {}
  float default_orbit() const override { return 3.0f; }

 public:
  bool seen_whole() const override { return whole_; }

 private:
  bool whole_;
};

}  // namespace

std::unique_ptr<Scene> make_mesh_scene(const TriangleMesh& mesh, bool whole) {
  return std::make_unique<MeshScene>(mesh, whole);
}

}  // namespace l2::detail
