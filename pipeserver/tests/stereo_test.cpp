// A passive stereo wall (docs/wall-file.md, "Stereo walls"): each eye's displays reassemble to
// their own eye's reference, and a square at a known depth lies apart between the eyes by the
// parallax the eye separation gives (stereo_square.hpp works it out from the geometry). An
// active wall shows the same two eyes in consecutive eye frames of one display.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "pipeserver/pipeserver.hpp"
#include "pipeserver/renderer.hpp"
#include "stereo_square.hpp"
#include "test_support.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2::stereo_test {
namespace {

using namespace stereo_square;

// Passive: one projector per eye on one 320x240 canvas rectangle. Active: one projector showing
// both eyes. Its tiles dealt to two pipeservers.
TileLayout stereo_layout(const std::string& mode = "passive") {
  return square_wall(mode, 80, 60, 340, 260);
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
  const Lit left = lit(left_eye), right = lit(right_eye);
  // A square some 60 pixels a side or more, whole in both eyes.
  EXPECT_GT(left.count, 2000);
  EXPECT_GT(right.count, 2000);
  return right.x - left.x;
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
