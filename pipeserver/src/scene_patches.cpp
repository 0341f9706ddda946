// `patches`: a rippling sheet of bicubic Bezier patches, tessellated to a configurable number of
// segments per edge and lit, like WireGL's Nurbs. One patch is one batch.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <stdexcept>

#include "scene_common.hpp"

namespace l2::detail {

namespace {

using ControlNet = std::array<std::array<glm::vec3, 4>, 4>;

// Bernstein basis of degree 3 and its derivative at t.
std::array<float, 4> bernstein(float t) {
  const float s = 1 - t;
  return {s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t};
}
std::array<float, 4> bernstein_d(float t) {
  const float s = 1 - t;
  return {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t};
}

class PatchesScene : public Scene {
 public:
  explicit PatchesScene(const SceneOptions& o) : n_(o.tessellation), patches_(o.patches) {
    if (n_ < 1 || n_ > 1024) throw std::invalid_argument("patches: tessellation must be 1..1024");
    if (patches_ < 1 || patches_ > 64)
      throw std::invalid_argument("patches: patches must be 1..64");
    // Each range alone is fine; together 64 x 1024 asked for 8.6 G triangles (bad_alloc). The
    // same ceiling as the strips scene's --triangles.
    const long long triangles = 2LL * patches_ * patches_ * n_ * n_;
    if (triangles > kMaxTriangles) {
      throw std::invalid_argument(fmt::format(
          "patches: {} patches per side with tessellation {} make {} triangles, more than {}",
          patches_, n_, triangles, kMaxTriangles));
    }
  }

  const char* name() const override { return "patches"; }

  void animate(int frame) override {
    const float t = static_cast<float>(frame) * 0.12f;
    // Tip the sheet towards the camera so the ripples read as relief.
    model_ = glm::rotate(glm::mat4(1.0f), glm::radians(-55.0f), glm::vec3(1, 0, 0));
    batches_.clear();
    const int cps = 3 * patches_ + 1;  // control points per side, shared along patch edges
    const auto control = [&](int i, int j) {
      const float u = -0.85f + 1.7f * static_cast<float>(i) / static_cast<float>(cps - 1);
      const float v = -0.85f + 1.7f * static_cast<float>(j) / static_cast<float>(cps - 1);
      const float h = 0.18f * std::sin(4.0f * u + t) * std::cos(3.0f * v - 0.7f * t);
      return glm::vec3(u, v, h);
    };
    for (int pj = 0; pj < patches_; ++pj)
      for (int pi = 0; pi < patches_; ++pi) {
        ControlNet net;
        for (int a = 0; a < 4; ++a)
          for (int c = 0; c < 4; ++c) net[a][c] = control(3 * pi + a, 3 * pj + c);
        const glm::vec3 colour =
            (pi + pj) % 2 ? glm::vec3(0.9f, 0.55f, 0.25f) : glm::vec3(0.3f, 0.75f, 0.45f);
        batches_.push_back(tessellate(net, colour));
      }
  }

 private:
  Batch tessellate(const ControlNet& net, glm::vec3 colour) const {
    Batch b;
    for (int j = 0; j <= n_; ++j)
      for (int i = 0; i <= n_; ++i) {
        const float u = static_cast<float>(i) / static_cast<float>(n_);
        const float v = static_cast<float>(j) / static_cast<float>(n_);
        const auto bu = bernstein(u), bv = bernstein(v);
        const auto du = bernstein_d(u), dv = bernstein_d(v);
        glm::vec3 p(0.0f), pu(0.0f), pv(0.0f);
        for (int a = 0; a < 4; ++a)
          for (int c = 0; c < 4; ++c) {
            p += bu[a] * bv[c] * net[a][c];
            pu += du[a] * bv[c] * net[a][c];
            pv += bu[a] * dv[c] * net[a][c];
          }
        b.positions.push_back(p);
        const glm::vec3 nrm = glm::cross(pu, pv);
        b.normals.push_back(glm::length(nrm) > 0 ? glm::normalize(nrm) : glm::vec3(0, 0, 1));
        b.colours.push_back(colour);
      }
    const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (n_ + 1) + i); };
    for (int j = 0; j < n_; ++j)
      for (int i = 0; i < n_; ++i) {
        b.indices.insert(b.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        b.indices.insert(b.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    b.compute_bounds();
    return b;
  }

  int n_, patches_;
};

}  // namespace

std::unique_ptr<Scene> make_patches_scene(const SceneOptions& options) {
  return std::make_unique<PatchesScene>(options);
}

}  // namespace l2::detail
