// `strips`: many small unlit coloured triangle strips scattered through a ball, in the manner of
// WireGL's Hundy. Geometry is built once; frames turn the cloud. `hotspot`: the same strips in a
// small cloud that travels round the view, so the load is concentrated and moving (the load
// balancer's unbalanced case, as the seed paper's zoom to one platform).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/ext/matrix_transform.hpp>
#include <glm/ext/scalar_constants.hpp>
#include <glm/geometric.hpp>
#include <stdexcept>

#include "scene_common.hpp"

namespace l2::detail {

namespace {

constexpr int kStripsPerBatch = 64;
// The hotspot: its cloud's radius, its path's radius (both in scene radii, inside the unit
// sphere the camera frames) and the frames of one round.
constexpr float kHotspotSpread = 0.25f, kHotspotPath = 0.6f;
constexpr int kHotspotRound = 120;

class StripsScene : public Scene {
 public:
  // `hotspot`: the cloud shrunk to kHotspotSpread and moving round kHotspotPath.
  StripsScene(const SceneOptions& o, bool hotspot) : hotspot_(hotspot) {
    if (o.triangles < 1 || o.triangles > kMaxTriangles) {
      throw std::invalid_argument(fmt::format("strips: triangles must be 1..{}", kMaxTriangles));
    }
    if (o.strip_length < 1 || o.strip_length > 4096) {
      throw std::invalid_argument("strips: strip_length must be 1..4096");
    }
    lit_ = false;
    Random rng(0x5eed5751);
    const long strips = (o.triangles + o.strip_length - 1) / o.strip_length;
    // Strip size shrinks as the count grows, so the cloud keeps roughly the same coverage.
    const float size = std::clamp(0.9f / std::cbrt(static_cast<float>(strips)), 0.004f, 0.25f);
    long left = o.triangles;
    for (long s = 0; s < strips; s += kStripsPerBatch) {
      Batch b;
      b.primitive = Primitive::TriangleStrips;
      // Each batch is a loose cluster around its own centre, so bucketing has something to save.
      const glm::vec3 centre = random_in_ball(rng) * (hotspot ? 0.8f * kHotspotSpread : 0.8f);
      for (long k = s; k < std::min(strips, s + kStripsPerBatch); ++k) {
        const int tris = static_cast<int>(std::min<long>(o.strip_length, left));
        left -= tris;
        add_strip(b, rng, centre + random_in_ball(rng) * (hotspot ? 0.2f * kHotspotSpread : 0.2f),
                  hotspot ? size * kHotspotSpread : size, tris);
      }
      b.compute_bounds();
      batches_.push_back(std::move(b));
    }
  }

  const char* name() const override { return hotspot_ ? "hotspot" : "strips"; }

  void animate(int frame) override {
    const float t = static_cast<float>(frame % 360);
    model_ = glm::rotate(glm::mat4(1.0f), glm::radians(2.0f * t), glm::vec3(0.3f, 1.0f, 0.1f));
    if (!hotspot_) return;
    // Round the view in the screen's plane, starting at the right.
    const float a = glm::two_pi<float>() * static_cast<float>(frame % kHotspotRound) /
                    static_cast<float>(kHotspotRound);
    const glm::vec3 at(kHotspotPath * std::cos(a), kHotspotPath * std::sin(a), 0.0f);
    model_ = glm::translate(glm::mat4(1.0f), at) * model_;
  }

 private:
  bool hotspot_;

  static glm::vec3 random_in_ball(Random& rng) {
    for (;;) {
      const glm::vec3 p(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      if (glm::dot(p, p) <= 1.0f) return p;
    }
  }

  // A zig-zag ribbon of `tris` triangles with one random colour.
  static void add_strip(Batch& b, Random& rng, glm::vec3 start, float size, int tris) {
    const glm::vec3 along = glm::normalize(random_in_ball(rng) + glm::vec3(1e-3f)) * (size * 0.3f);
    const glm::vec3 across = glm::normalize(random_in_ball(rng) + glm::vec3(0, 1e-3f, 0)) * size;
    const glm::vec3 colour(rng.uniform(0.2f, 1), rng.uniform(0.2f, 1), rng.uniform(0.2f, 1));
    b.strip_first.push_back(static_cast<int>(b.positions.size()));
    b.strip_count.push_back(tris + 2);
    for (int v = 0; v < tris + 2; ++v) {
      const float step = static_cast<float>(v / 2);
      b.positions.push_back(start + along * step + (v % 2 ? across : glm::vec3(0.0f)));
      b.colours.push_back(colour);
    }
  }
};

}  // namespace

std::unique_ptr<Scene> make_strips_scene(const SceneOptions& options) {
  return std::make_unique<StripsScene>(options, false);
}

std::unique_ptr<Scene> make_hotspot_scene(const SceneOptions& options) {
  return std::make_unique<StripsScene>(options, true);
}

}  // namespace l2::detail
