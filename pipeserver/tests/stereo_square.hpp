// What the stereo tests (stereo_test.cpp: passive and active; packed_stereo_test.cpp) share: one
// 320x240 display showing a white square at a known depth, the camera they view it with, and
// the parallax the geometry of two parallel eyes with shifted frusta gives, worked out here and
// not from the camera code: a point at distance d from the eyes shows the right eye's picture
// e·f·(1/c − 1/d) pixels right of the left eye's, where e is the eye separation, c the
// convergence distance and f = H / (2·tan(fov/2)) the focal length in pixels of a canvas H
// pixels tall.
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "pipeserver/renderer.hpp"
#include "test_support.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2::stereo_square {

inline constexpr double kSeparation = 0.4, kConvergence = 3.0, kCameraDistance = 3.0, kFov = 40.0;
inline constexpr int kWidth = 320, kHeight = 240;

// One kWidth x kHeight display on its canvas (`mode` "passive": twins, one per eye), cut into
// tile_w x tile_h tiles dealt to two pipeservers with fb_w x fb_h framebuffers.
inline TileLayout square_wall(const std::string& mode, int tile_w, int tile_h, int fb_w, int fb_h) {
  std::string displays;
  for (const char* eye : {"left", "right"}) {
    displays +=
        fmt::format("[[display]]\nwidth = {}\nheight = {}\nx = 0\ny = 0\n", kWidth, kHeight);
    if (mode != "passive") break;
    displays += fmt::format("eye = \"{}\"\n", eye);
  }
  const std::string text = fmt::format(
      "[stereo]\nmode = \"{}\"\neye_separation = {}\nconvergence = {}\n{}"
      "[tiling]\nkind = \"grid\"\ntile_width = {}\ntile_height = {}\n"
      "[pipeservers]\ncount = 2\nframebuffer_width = {}\nframebuffer_height = {}\n",
      mode, kSeparation, kConvergence, displays, tile_w, tile_h, fb_w, fb_h);
  return plan_layout(parse_wall(text, "stereo.toml"));
}

// A white square 0.6 scene units a side facing the eyes, `z` in front of the scene's centre
// (so kCameraDistance − z from the eyes), on black; the camera turning `orbit` degrees a frame.
inline std::unique_ptr<Scene> square_at(float z, float orbit = 0.0f) {
  auto scene = make_own_scene([z](const TileView&) {
    gl().Begin(GL_QUADS);
    gl().Color3f(1.0f, 1.0f, 1.0f);
    gl().Vertex3f(-0.3f, -0.3f, z);
    gl().Vertex3f(0.3f, -0.3f, z);
    gl().Vertex3f(0.3f, 0.3f, z);
    gl().Vertex3f(-0.3f, 0.3f, z);
    gl().End();
  });
  CameraOptions camera;
  camera.distance = static_cast<float>(kCameraDistance);
  camera.fov = static_cast<float>(kFov);
  camera.orbit = orbit;
  scene->set_camera(camera);
  return scene;
}

// In canvas pixels: a point at `distance` from the eyes, right eye less left eye.
inline double expected_parallax(double distance) {
  const double focal = kHeight / (2 * std::tan(kFov / 2 * std::numbers::pi / 180));
  return kSeparation * focal * (1 / kConvergence - 1 / distance);
}

// Frame `frame` through the pipeservers, each display checked against its reference: the
// reassembled displays.
inline std::vector<RgbImage> reassembled(const TileLayout& layout, Scene& scene, int frame) {
  const auto check = test::check_wall(layout, scene, frame);
  EXPECT_EQ(check.reassembly.errors.total(), 0u);
  for (std::size_t d = 0; d < check.diffs.size(); ++d)
    EXPECT_EQ(check.diffs[d].pixels_differing, 0) << "display " << d << ", frame " << frame;
  return check.reassembly.displays;
}

// The mean (x, y) of the lit pixels, and how many there are (-1, -1 when none).
struct Lit {
  double x = -1, y = -1;
  long count = 0;
};
inline Lit lit(const RgbImage& image) {
  Lit l{0, 0, 0};
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (image.at(x, y).r > 128) l.x += x, l.y += y, ++l.count;
  if (l.count == 0) return {};
  l.x /= static_cast<double>(l.count), l.y /= static_cast<double>(l.count);
  return l;
}

}  // namespace l2::stereo_square
