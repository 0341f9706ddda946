// `isosurface`: the level set of a time-varying scalar field (moving metaballs), extracted by
// marching cubes on a regular grid, like WireGL's March. Each cube is cut into six tetrahedra
// along its main diagonal (marching tetrahedra): the surface is watertight with no ambiguous
// cases and no 256-entry table to get wrong. Lit, normals from the field's gradient.
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>

#include "scene_common.hpp"

namespace l2::detail {

namespace {

constexpr int kBlock = 8;       // batches: blocks of kBlock^3 cells
constexpr float kLevel = 1.0f;  // the iso level
constexpr int kBalls = 5;

struct Field {
  std::array<glm::vec3, kBalls> centre;
  std::array<float, kBalls> weight;

  float value(glm::vec3 p) const {
    float f = 0;
    for (int i = 0; i < kBalls; ++i) {
      const glm::vec3 d = p - centre[i];
      f += weight[i] / (glm::dot(d, d) + 1e-4f);
    }
    return f;
  }
  glm::vec3 gradient(glm::vec3 p) const {
    glm::vec3 g(0.0f);
    for (int i = 0; i < kBalls; ++i) {
      const glm::vec3 d = p - centre[i];
      const float q = glm::dot(d, d) + 1e-4f;
      g += -2.0f * weight[i] * d / (q * q);
    }
    return g;
  }
};

Field field_at(int frame) {
  Field f;
  const float t = static_cast<float>(frame) * 0.05f;
  for (int i = 0; i < kBalls; ++i) {
    const float k = static_cast<float>(i);
    f.centre[i] = 0.45f * glm::vec3(std::sin(t * (1.0f + 0.3f * k) + k),
                                    std::cos(t * (0.7f + 0.2f * k) + 2.0f * k),
                                    std::sin(t * (0.5f + 0.4f * k) + 3.0f * k));
    f.weight[i] = 0.05f + 0.012f * k;
  }
  return f;
}

// Cube corners (bit 0 = x, bit 1 = y, bit 2 = z) and the six tetrahedra around diagonal 0-7.
constexpr std::array<std::array<int, 4>, 6> kTets{
    {{0, 7, 1, 3}, {0, 7, 3, 2}, {0, 7, 2, 6}, {0, 7, 6, 4}, {0, 7, 4, 5}, {0, 7, 5, 1}}};

class IsosurfaceScene : public Scene {
 public:
  explicit IsosurfaceScene(const SceneOptions& o) : n_(o.grid) {
    if (n_ < 2 || n_ > 256) throw std::invalid_argument("isosurface: grid must be 2..256");
  }

  const char* name() const override { return "isosurface"; }

  void animate(int frame) override {
    const Field field = field_at(frame);
    const int samples = n_ + 1;
    values_.resize(static_cast<std::size_t>(samples) * samples * samples);
    for (int z = 0; z < samples; ++z)
      for (int y = 0; y < samples; ++y)
        for (int x = 0; x < samples; ++x) values_[index(x, y, z)] = field.value(point(x, y, z));
    batches_.clear();
    for (int bz = 0; bz < n_; bz += kBlock)
      for (int by = 0; by < n_; by += kBlock)
        for (int bx = 0; bx < n_; bx += kBlock) {
          Batch b;
          for (int z = bz; z < std::min(n_, bz + kBlock); ++z)
            for (int y = by; y < std::min(n_, by + kBlock); ++y)
              for (int x = bx; x < std::min(n_, bx + kBlock); ++x) march_cube(field, x, y, z, b);
          if (b.positions.empty()) continue;
          b.compute_bounds();
          batches_.push_back(std::move(b));
        }
  }

 private:
  std::size_t index(int x, int y, int z) const {
    const std::size_t s = static_cast<std::size_t>(n_) + 1;
    return (static_cast<std::size_t>(z) * s + static_cast<std::size_t>(y)) * s +
           static_cast<std::size_t>(x);
  }
  glm::vec3 point(int x, int y, int z) const {
    const float step = 1.8f / static_cast<float>(n_);
    return glm::vec3(-0.9f) + step * glm::vec3(x, y, z);
  }

  void march_cube(const Field& field, int x, int y, int z, Batch& b) const {
    std::array<glm::vec3, 8> p;
    std::array<float, 8> v;
    for (int c = 0; c < 8; ++c) {
      const int cx = x + (c & 1), cy = y + (c >> 1 & 1), cz = z + (c >> 2 & 1);
      p[c] = point(cx, cy, cz);
      v[c] = values_[index(cx, cy, cz)];
    }
    for (const auto& t : kTets)
      march_tet(field, {p[t[0]], p[t[1]], p[t[2]], p[t[3]]}, {v[t[0]], v[t[1]], v[t[2]], v[t[3]]},
                b);
  }

  static void march_tet(const Field& field, const std::array<glm::vec3, 4>& p,
                        const std::array<float, 4>& v, Batch& b) {
    std::array<int, 4> in{}, out{};
    int n_in = 0, n_out = 0;
    for (int i = 0; i < 4; ++i) {
      if (v[i] > kLevel)
        in[n_in++] = i;
      else
        out[n_out++] = i;
    }
    const auto cut = [&](int a, int c) {
      const float t = (kLevel - v[a]) / (v[c] - v[a]);
      return p[a] + t * (p[c] - p[a]);
    };
    if (n_in == 1 || n_in == 3) {
      const int apex = n_in == 1 ? in[0] : out[0];
      const auto& others = n_in == 1 ? out : in;
      emit(field, b, cut(apex, others[0]), cut(apex, others[1]), cut(apex, others[2]));
    } else if (n_in == 2) {
      const glm::vec3 q0 = cut(in[0], out[0]), q1 = cut(in[0], out[1]);
      const glm::vec3 q2 = cut(in[1], out[1]), q3 = cut(in[1], out[0]);
      emit(field, b, q0, q1, q2);
      emit(field, b, q0, q2, q3);
    }
  }

  // One-sided lighting uses the given normal for either winding, so winding need not agree.
  static void emit(const Field& field, Batch& b, glm::vec3 a, glm::vec3 c, glm::vec3 d) {
    for (const glm::vec3& q : {a, c, d}) {
      b.positions.push_back(q);
      const glm::vec3 g = field.gradient(q);
      b.normals.push_back(glm::length(g) > 0 ? -glm::normalize(g) : glm::vec3(0, 0, 1));
      b.colours.push_back(glm::vec3(0.35f, 0.55f, 0.9f) + 0.3f * glm::vec3(q.y, 0.0f, -q.y));
    }
  }

  int n_;
  std::vector<float> values_;
};

}  // namespace

std::unique_ptr<Scene> make_isosurface_scene(const SceneOptions& options) {
  return std::make_unique<IsosurfaceScene>(options);
}

}  // namespace l2::detail
