// A passive stereo wall (docs/wall-file.md, "Stereo walls"): each eye's displays reassemble to
// their own eye's reference, and a square at a known depth lies apart between the eyes by the
// parallax the eye separation gives, worked out here from the geometry of two parallel eyes with
// shifted frusta, not from the camera code: a point at distance d from the eyes shows the right
// eye's picture e·f·(1/c − 1/d) pixels right of the left eye's, where e is the eye separation,
// c the convergence distance and f = H / (2·tan(fov/2)) the focal length in pixels of a canvas
// H pixels tall. An active wall shows the same two eyes in consecutive eye frames of one display.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "pipeserver/pipeserver.hpp"
#include "pipeserver/renderer.hpp"
#include "test_support.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2::stereo_test {
namespace {

constexpr double kSeparation = 0.4, kConvergence = 3.0, kCameraDistance = 3.0, kFov = 40.0;
constexpr int kWidth = 320, kHeight = 240;

// Passive: one projector per eye on one 320x240 canvas rectangle. Active: one projector showing
// both eyes. Its tiles dealt to two pipeservers.
TileLayout stereo_layout(const std::string& mode = "passive") {
  const bool passive = mode == "passive";
  std::string displays;
  for (const char* eye : {"left", "right"}) {
    displays +=
        fmt::format("[[display]]\nwidth = {}\nheight = {}\nx = 0\ny = 0\n", kWidth, kHeight);
    if (!passive) break;
    displays += fmt::format("eye = \"{}\"\n", eye);
  }
  const std::string text = fmt::format(
      "[stereo]\nmode = \"{}\"\neye_separation = {}\nconvergence = {}\n{}"
      "[tiling]\nkind = \"grid\"\ntile_width = 80\ntile_height = 60\n"
      "[pipeservers]\ncount = 2\nframebuffer_width = 340\nframebuffer_height = 260\n",
      mode, kSeparation, kConvergence, displays);
  return plan_layout(parse_wall(text, "stereo.toml"));
}

// A white square 0.6 scene units a side facing the eyes, `z` in front of the scene's centre
// (so kCameraDistance − z from the eyes), on black.
std::unique_ptr<Scene> square_at(float z, float orbit = 0.0f) {
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

// The mean x of the lit pixels, and how many there are.
std::pair<double, long> centre_x(const RgbImage& image) {
  double sum = 0;
  long count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (image.at(x, y).r > 128) sum += x, ++count;
  return {count > 0 ? sum / static_cast<double>(count) : -1.0, count};
}

double expected_parallax(double distance) {
  const double focal = kHeight / (2 * std::tan(kFov / 2 * std::numbers::pi / 180));
  return kSeparation * focal * (1 / kConvergence - 1 / distance);
}

// Frame `frame` through the pipeservers, each display checked against its reference: the
// reassembled displays.
std::vector<RgbImage> reassembled(const TileLayout& layout, Scene& scene, int frame) {
  const auto check = test::check_wall(layout, scene, frame);
  EXPECT_EQ(check.reassembly.errors.total(), 0u);
  for (std::size_t d = 0; d < check.diffs.size(); ++d)
    EXPECT_EQ(check.diffs[d].pixels_differing, 0) << "display " << d << ", frame " << frame;
  return check.reassembly.displays;
}

// Both eyes through the pipeservers: a passive wall's twins in frame 0, or an active wall's one
// display in eye frames 2 and 3 (application frame 1's left and right eye). Returns the right
// eye's square centre less the left eye's, in pixels.
double measured_parallax(float z, const std::string& mode = "passive") {
  const TileLayout layout = stereo_layout(mode);
  auto scene = square_at(z);
  const bool passive = mode == "passive";
  const std::vector<RgbImage> first = reassembled(layout, *scene, passive ? 0 : 2);
  const RgbImage& left_eye = first[0];
  const RgbImage right_eye = passive ? first[1] : reassembled(layout, *scene, 3)[0];
  const auto [left, left_count] = centre_x(left_eye);
  const auto [right, right_count] = centre_x(right_eye);
  // A square some 60 pixels a side or more, whole in both eyes.
  EXPECT_GT(left_count, 2000);
  EXPECT_GT(right_count, 2000);
  return right - left;
}

TEST(PassiveStereo, ASquareAtTheConvergenceDistanceShowsNoParallax) {
  EXPECT_NEAR(measured_parallax(0.0f), 0.0, 0.5);
}

TEST(PassiveStereo, ANearerSquareShowsTheParallaxOfTheEyeSeparation) {
  // One scene unit nearer: two from the eyes. Crossed: the right eye sees it further left.
  const double want = expected_parallax(kCameraDistance - 1);
  EXPECT_NEAR(want, -21.98, 0.01);  // the formula's figure, for a reader checking it by hand
  EXPECT_NEAR(measured_parallax(1.0f), want, 0.5);
}

TEST(PassiveStereo, AFartherSquareShowsUncrossedParallax) {
  const double want = expected_parallax(kCameraDistance + 1);
  EXPECT_GT(want, 5.0);
  EXPECT_NEAR(measured_parallax(-1.0f), want, 0.5);
}

// An active wall's frames are eye frames: 2k the left eye of application frame k, 2k+1 its right.
TEST(ActiveStereo, ConsecutiveEyeFramesShowTheParallaxOfTheEyeSeparation) {
  EXPECT_NEAR(measured_parallax(1.0f, "active"), expected_parallax(kCameraDistance - 1), 0.5);
  EXPECT_NEAR(measured_parallax(-1.0f, "active"), expected_parallax(kCameraDistance + 1), 0.5);
  EXPECT_NEAR(measured_parallax(0.0f, "active"), 0.0, 0.5);
}

// The square turning 20 degrees a frame: eye frames 4 and 5 are frame 2 as a passive wall's
// twins show it, byte for byte, and not frame 3 (eye frame 6 is).
TEST(ActiveStereo, EyeFramesAreTheEyesOfTheirApplicationFrame) {
  auto scene = square_at(1.0f, 20.0f);
  const std::vector<RgbImage> passive2 = reassembled(stereo_layout(), *scene, 2);
  const std::vector<RgbImage> passive3 = reassembled(stereo_layout(), *scene, 3);
  const TileLayout active = stereo_layout("active");
  EXPECT_TRUE(reassembled(active, *scene, 4)[0] == passive2[0]);
  EXPECT_TRUE(reassembled(active, *scene, 5)[0] == passive2[1]);
  EXPECT_TRUE(reassembled(active, *scene, 6)[0] == passive3[0]);
  EXPECT_FALSE(passive2[0] == passive3[0]);
}

TEST(PassiveStereo, TheEyesDifferAndMonoIsTheCameraItself) {
  const Camera mono = frame_sphere({kWidth, kHeight}, glm::vec3(0.0f), 1.0f);
  const Camera same = eye_camera(mono, {}, glm::vec3(0.0f));
  EXPECT_EQ(same.view, mono.view);
  EXPECT_EQ(same.projection, mono.projection);
  StereoSpec stereo;
  stereo.mode = StereoMode::Passive;
  const Camera left = eye_camera(mono, {Eye::Left, stereo}, glm::vec3(0.0f));
  const Camera right = eye_camera(mono, {Eye::Right, stereo}, glm::vec3(0.0f));
  EXPECT_NE(left.view, right.view);
  EXPECT_NE(left.projection, right.projection);
}

}  // namespace
}  // namespace l2::stereo_test
