#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "pipeserver/scene.hpp"
#include "test_support.hpp"

namespace l2 {
namespace {

std::vector<glm::vec3> all_positions(const Scene& s) {
  std::vector<glm::vec3> out;
  for (const auto& b : s.batches()) out.insert(out.end(), b.positions.begin(), b.positions.end());
  return out;
}

class EveryScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryScene, SameFrameSameGeometryAcrossInstances) {
  auto a = make_scene(GetParam(), test::small_options());
  auto b = make_scene(GetParam(), test::small_options());
  a->set_frame(5);
  b->set_frame(9);
  b->set_frame(5);
  EXPECT_EQ(all_positions(*a), all_positions(*b));
  EXPECT_EQ(a->model(), b->model());
}

TEST_P(EveryScene, AnimatesOverFrames) {
  auto s = make_scene(GetParam(), test::small_options());
  s->set_frame(1);
  const auto p1 = all_positions(*s);
  const auto m1 = s->model();
  s->set_frame(2);
  EXPECT_TRUE(p1 != all_positions(*s) || m1 != s->model());
}

TEST_P(EveryScene, BatchBoundsHoldTheirGeometry) {
  auto s = make_scene(GetParam(), test::small_options());
  ASSERT_GT(s->batches().size(), 1u);
  for (const auto& b : s->batches()) {
    for (const auto& p : b.positions) {
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, b.bounds.lo)) &&
                  glm::all(glm::lessThanEqual(p, b.bounds.hi)));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(All, EveryScene,
                         ::testing::Values("mesh", "strips", "isosurface", "patches"));

TEST(Scenes, StripsHonourTheTriangleCount) {
  SceneOptions o;
  o.triangles = 12345;
  o.strip_length = 10;
  auto s = make_scene("strips", o);
  EXPECT_EQ(s->triangle_count(), 12345u);
  EXPECT_FALSE(s->lit());
}

TEST(Scenes, PatchTessellationSetsTriangleCount) {
  SceneOptions o;
  o.patches = 2;
  o.tessellation = 5;
  EXPECT_EQ(make_scene("patches", o)->triangle_count(), 2u * 2u * 5u * 5u * 2u);
}

TEST(Scenes, PatchesBeyondFiftyMillionTrianglesAreRefused) {
  // 64 patches per side x 1024 segments per edge, each in range: 8.6 G triangles, bad_alloc.
  SceneOptions o;
  o.patches = 64;
  o.tessellation = 1024;
  try {
    make_scene("patches", o);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "patches: 64 patches per side with tessellation 1024 make 8589934592 triangles, "
                 "more than 50000000");
  }
  o.patches = 25;  // 2 x 25^2 x 201^2, just above 2 x 25^2 x 200^2 = 50 000 000
  o.tessellation = 201;
  EXPECT_THROW(make_scene("patches", o), std::invalid_argument);
}

TEST(Scenes, UnknownNameIsAClearError) {
  try {
    make_scene("teapot");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "unknown scene 'teapot' (expected mesh, strips, hotspot, isosurface, patches, "
                 "swap, picture, movie, session or vnc)");
  }
}

// The distance from the origin of the farthest vertex of a mesh scene made from an OBJ text;
// fails the test on a vertex that is not finite.
float farthest_vertex(const std::string& obj) {
  const auto file = std::filesystem::temp_directory_path() / "l2-scene-test.obj";
  std::ofstream(file) << obj;
  SceneOptions options;
  options.mesh_file = file;
  auto s = make_scene("mesh", options);
  std::filesystem::remove(file);
  s->set_frame(0);
  float farthest = 0;
  for (const auto& p : all_positions(*s)) {
    EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    farthest = std::max(farthest, glm::length(p));
  }
  return farthest;
}

// A mesh file may hold any finite float. Coordinates near the float limit overflowed while the
// mesh was centred and scaled, and every vertex became NaN: nothing was drawn. Tiny ones were
// scaled against a radius of at least 1e-6 and stayed a dot.
TEST(Scenes, MeshesOfHugeOrTinyCoordinatesFitTheUnitSphere) {
  EXPECT_NEAR(farthest_vertex("v 3.0e38 3.0e38 -3.0e38\nv 3.3e38 -3.3e38 3.0e38\n"
                              "v -3.3e38 3.0e38 3.3e38\nf 1 2 3\n"),
              1.0f, 1e-5f);
  EXPECT_NEAR(farthest_vertex("v 3e-30 0 0\nv 0 2e-30 0\nv 0 0 1e-30\nf 1 2 3\n"), 1.0f, 1e-5f);
}

TEST(Scenes, BunnyIsTheDefaultMesh) {
  EXPECT_EQ(make_scene("mesh")->triangle_count(), 3674u);
}

}  // namespace
}  // namespace l2
