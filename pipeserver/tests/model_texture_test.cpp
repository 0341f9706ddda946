// Base-colour textures of models (glTF baseColorTexture, OBJ map_Kd): read from a file beside the
// model or embedded in it, drawn on the mesh multiplied by its colour, one texture per material;
// textures that cannot be read left out in one line, textures too large refused in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "image/png_io.hpp"
#include "pipeserver/model_file.hpp"
#include "pipeserver/pipeserver.hpp"
#include "test_support.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

// A folder of the test's own.
fs::path folder() {
  const fs::path dir = fs::temp_directory_path() / "l2_pipeserver_texture_test" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(dir);
  return dir;
}

fs::path write_file(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

std::string bytes_of(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), {}};
}

constexpr Rgb kRed{255, 0, 0}, kGreen{0, 255, 0}, kBlue{0, 0, 255}, kWhite{255, 255, 255};

// 2x2: red, green on top; blue, white below.
RgbImage quarters_picture() {
  RgbImage image(2, 2);
  image.set(0, 0, kRed);
  image.set(1, 0, kGreen);
  image.set(0, 1, kBlue);
  image.set(1, 1, kWhite);
  return image;
}

// A square facing +z, its texture coordinates OBJ's ((0, 0) the picture's bottom left), drawn
// with `material` from `mtl` (written beside it).
fs::path obj_square(const fs::path& dir, const std::string& material, const std::string& mtl) {
  write_file(dir / "square.mtl", mtl);
  return write_file(dir / "square.obj",
                    "mtllib square.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\nusemtl " +
                        material + "\nf 1/1/1 2/2/1 3/3/1 4/4/1\n");
}

// The model rendered face-on (no orbit) on a 64x64 canvas.
RgbImage face_on(const fs::path& model) {
  SceneOptions options;
  options.mesh_file = model;
  options.camera.orbit = 0;
  auto scene = make_scene("mesh", options);
  return render_canvas_rect(Canvas{64, 64}, Rect{0, 0, 64, 64}, *scene, 0);
}

// The box around what was drawn (not black) in `image`.
Rect drawn(const RgbImage& image) {
  int x0 = image.width(), y0 = image.height(), x1 = -1, y1 = -1;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      if (image.at(x, y) == Rgb{}) continue;
      x0 = std::min(x0, x);
      y0 = std::min(y0, y);
      x1 = std::max(x1, x);
      y1 = std::max(y1, y);
    }
  }
  return {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

// The pixels at the middles of the four quarters of `r`: top left, top right, bottom left,
// bottom right.
std::array<Rgb, 4> quarters(const RgbImage& image, const Rect& r) {
  const int left = r.x + r.w / 4, right = r.x + 3 * r.w / 4;
  const int top = r.y + r.h / 4, bottom = r.y + 3 * r.h / 4;
  return {image.at(left, top), image.at(right, top), image.at(left, bottom),
          image.at(right, bottom)};
}

// `texel` lit as the white one was: each channel the white one's share of it, within a level.
void expect_lit(Rgb pixel, Rgb texel, Rgb lit_white, const char* what) {
  const auto near = [](int got, int texel_level, int white) {
    return std::abs(got - texel_level * white / 255) <= 1;
  };
  EXPECT_TRUE(near(pixel.r, texel.r, lit_white.r) && near(pixel.g, texel.g, lit_white.g) &&
              near(pixel.b, texel.b, lit_white.b))
      << what << ": " << int(pixel.r) << "," << int(pixel.g) << "," << int(pixel.b);
}

// OBJ's map_Kd, a PNG beside the model named with a Windows separator (as many OBJ exporters
// write them, and the spider of Debian's assimp-testmodels does): the square shows the picture's
// four colours in their places, not its material's white.
TEST(ModelTexture, ObjMapKdIsDrawnOnTheSquare) {
  const fs::path dir = folder();
  write_png(dir / "quarters.png", quarters_picture());
  const fs::path obj = obj_square(dir, "q", "newmtl q\nKd 1 1 1\nmap_Kd .\\quarters.png\n");
  const TriangleMesh mesh = load_mesh(obj);
  EXPECT_EQ(mesh.left_out, "");
  ASSERT_EQ(mesh.textures.size(), 1u);
  EXPECT_EQ(mesh.textures[0]->image, quarters_picture());
  EXPECT_EQ(mesh.triangle_textures, (std::vector<std::int32_t>{0, 0}));
  ASSERT_EQ(mesh.uvs.size(), 4u);
  EXPECT_EQ(mesh.uvs[0], glm::vec2(0, 1));  // OBJ's (0, 0), the picture's bottom left

  const RgbImage image = face_on(obj);
  const auto [top_left, top_right, bottom_left, bottom_right] = quarters(image, drawn(image));
  // White lit face-on by the key light and the ambient one: bright, grey.
  EXPECT_GT(bottom_right.r, 200);
  EXPECT_TRUE(bottom_right.r == bottom_right.g && bottom_right.g == bottom_right.b);
  expect_lit(top_left, kRed, bottom_right, "top left");
  expect_lit(top_right, kGreen, bottom_right, "top right");
  expect_lit(bottom_left, kBlue, bottom_right, "bottom left");
}

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t v = static_cast<std::uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size())
      v |= static_cast<std::uint32_t>(static_cast<std::uint8_t>(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<std::uint8_t>(bytes[i + 2]);
    for (std::size_t k = 0; k < 4; ++k)
      out += i + k <= bytes.size() ? digits[(v >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

template <class T>
void append(std::string& buffer, std::initializer_list<T> values) {
  for (const T v : values) buffer.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// A glTF 2.0 square facing +z in one file: its buffer and its base-colour texture (the PNG file
// `picture`'s bytes) as data URIs, so the texture is embedded; base colour factor `factor`.
fs::path gltf_square(const fs::path& path, const fs::path& picture, const std::string& factor) {
  std::string buffer;
  append<float>(buffer, {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});  // positions
  append<float>(buffer, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});      // normals
  append<float>(buffer, {0, 1, 1, 1, 1, 0, 0, 0});  // glTF's: (0, 0) the picture's top left
  append<std::uint16_t>(buffer, {0, 1, 2, 0, 2, 3});
  return write_file(path, R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
"nodes": [{"mesh": 0}],
"meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                            "indices": 3, "material": 0}]}],
"materials": [{"pbrMetallicRoughness": {"baseColorFactor": )" +
                              factor + R"(, "baseColorTexture": {"index": 0}}}],
"textures": [{"source": 0}],
"images": [{"uri": "data:image/png;base64,)" +
                              base64(bytes_of(picture)) + R"("}],
"buffers": [{"byteLength": 140, "uri": "data:application/octet-stream;base64,)" +
                              base64(buffer) + R"("}],
"bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                {"buffer": 0, "byteOffset": 96, "byteLength": 32},
                {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
"accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
               "min": [-1, -1, 0], "max": [1, 1, 0]},
              {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
              {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
              {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}]})");
}

// glTF: the picture embedded in the file, multiplied by the base colour factor, as glTF says:
// green at half, so the white quarter is lit magenta-grey and the green one dark green.
TEST(ModelTexture, GltfEmbeddedTextureIsMultipliedByTheBaseColourFactor) {
  const fs::path dir = folder();
  write_png(dir / "quarters.png", quarters_picture());
  const fs::path gltf = gltf_square(dir / "square.gltf", dir / "quarters.png", "[1, 0.5, 1, 1]");
  const TriangleMesh mesh = load_mesh(gltf);
  EXPECT_EQ(mesh.left_out, "");
  ASSERT_EQ(mesh.textures.size(), 1u);
  EXPECT_EQ(mesh.textures[0]->image, quarters_picture());

  const RgbImage image = face_on(gltf);
  const auto [top_left, top_right, bottom_left, bottom_right] = quarters(image, drawn(image));
  EXPECT_GT(bottom_right.r, 200);
  EXPECT_EQ(bottom_right.b, bottom_right.r);
  EXPECT_NEAR(bottom_right.g, bottom_right.r / 2, 1);
  expect_lit(top_left, kRed, bottom_right, "top left");
  expect_lit(top_right, kGreen, bottom_right, "top right");
  expect_lit(bottom_left, kBlue, bottom_right, "bottom left");
}

// Two squares side by side, each of its own material and texture; a third material names the
// first's picture again, which is read once.
TEST(ModelTexture, EveryMaterialDrawsItsOwnTexture) {
  const fs::path dir = folder();
  write_png(dir / "yellow.png", RgbImage(2, 2, {255, 255, 0}));
  write_png(dir / "cyan.png", RgbImage(3, 1, {0, 255, 255}));
  write_file(dir / "two.mtl",
             "newmtl a\nKd 1 1 1\nmap_Kd yellow.png\nnewmtl b\nKd 1 1 1\nmap_Kd cyan.png\n"
             "newmtl c\nKd 1 1 1\nmap_Kd yellow.png\n");
  const fs::path obj = write_file(
      dir / "two.obj",
      "mtllib two.mtl\nv -2 -1 0\nv 0 -1 0\nv 0 1 0\nv -2 1 0\nv 0.5 -1 0\nv 2 -1 0\nv 2 1 0\n"
      "v 0.5 1 0\nv -1 -3 0\nv 1 -3 0\nv 1 -2 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
      "usemtl a\nf 1/1/1 2/2/1 3/3/1 4/4/1\nusemtl b\nf 5/1/1 6/2/1 7/3/1 8/4/1\n"
      "usemtl c\nf 9/1/1 10/2/1 11/3/1\n");
  const TriangleMesh mesh = load_mesh(obj);
  EXPECT_EQ(mesh.left_out, "");
  ASSERT_EQ(mesh.textures.size(), 2u);
  std::set<std::int32_t> used(mesh.triangle_textures.begin(), mesh.triangle_textures.end());
  EXPECT_EQ(used, (std::set<std::int32_t>{0, 1}));

  const RgbImage image = face_on(obj);
  const Rect r = drawn(image);
  const Rgb left = image.at(r.x + r.w / 8, r.y + r.h / 4);
  const Rgb right = image.at(r.x + 7 * r.w / 8, r.y + r.h / 4);
  EXPECT_GT(left.r, 200);
  EXPECT_EQ(left.g, left.r);
  EXPECT_EQ(left.b, 0);
  EXPECT_EQ(right.r, 0);
  EXPECT_GT(right.g, 200);
  EXPECT_EQ(right.b, right.g);
}

// The error load_mesh throws for `model`, or "no error"; check_model must throw the same.
std::string error_of(const fs::path& model) {
  std::string checked = "no error";
  try {
    (void)check_model(model);
  } catch (const std::runtime_error& e) {
    checked = e.what();
  }
  try {
    load_mesh(model);
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(checked, e.what());
    return e.what();
  }
  EXPECT_EQ(checked, "no error");
  return "no error";
}

// A texture file missing or damaged, or a texture on a mesh without texture coordinates: the
// model is drawn, those meshes in their materials' colours, and one line a texture says which
// was left out and why (check_model says the same lines: l2wall says them once for a run).
TEST(ModelTexture, ATextureThatCannotBeUsedIsLeftOutInOneLine) {
  const fs::path dir = folder();
  write_file(dir / "damaged.png", "not a picture at all");
  write_png(dir / "fine.png", RgbImage(2, 2, {9, 9, 9}));
  write_file(dir / "three.mtl",
             "newmtl gone\nKd 0.5 0.25 1\nmap_Kd missing.png\n"
             "newmtl bad\nKd 1 1 1\nmap_Kd damaged.png\n"
             "newmtl flat\nKd 1 1 1\nmap_Kd fine.png\n");
  const fs::path obj = write_file(
      dir / "three.obj",
      "mtllib three.mtl\nv -2 -1 0\nv -1 -1 0\nv -1 1 0\nv -2 1 0\nv 0 -1 0\nv 1 -1 0\n"
      "v 1 1 0\nv 0 1 0\nv 1.5 -1 0\nv 2 -1 0\nv 2 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
      "vn 0 0 1\nusemtl gone\nf 1/1/1 2/2/1 3/3/1 4/4/1\nusemtl bad\nf 5/1/1 6/2/1 7/3/1 8/4/1\n"
      "usemtl flat\nf 9//1 10//1 11//1\n");
  const std::string said = obj.string() + ": texture 'missing.png' left out (cannot read: No " +
                           "such file or directory), drawn in its material's colour\n" +
                           obj.string() + ": texture 'damaged.png' left out (cannot read: " +
                           "Not a PNG file), drawn in its material's colour\n" + obj.string() +
                           ": texture 'fine.png' left out (its mesh has no texture " +
                           "coordinates), drawn in its material's colour";
  EXPECT_EQ(check_model(obj), said);
  const TriangleMesh mesh = load_mesh(obj);
  EXPECT_EQ(mesh.left_out, said);
  EXPECT_TRUE(mesh.textures.empty());
  EXPECT_TRUE(mesh.uvs.empty());
  SceneOptions options;
  options.mesh_file = obj;
  EXPECT_EQ(make_scene("mesh", options)->note(), said);

  // Drawn in the material's colour: the missing texture's square blue-violet.
  const RgbImage image = face_on(obj);
  const Rect r = drawn(image);
  const Rgb gone = image.at(r.x + r.w / 8, r.y + r.h / 2);
  EXPECT_GT(gone.b, 200);
  EXPECT_NEAR(gone.r, gone.b / 2, 1);
  EXPECT_NEAR(gone.g, gone.b / 4, 1);
}

// A PNG header claiming 20000x20000 RGB pixels, followed by one tiny IDAT (image/tests' own).
constexpr unsigned char kHugeClaimPng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
    0x44, 0x52, 0x00, 0x00, 0x4e, 0x20, 0x00, 0x00, 0x4e, 0x20, 0x08, 0x02, 0x00, 0x00,
    0x00, 0x6c, 0x12, 0xd1, 0x6e, 0x00, 0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x78,
    0x9c, 0x63, 0x60, 0x60, 0x60, 0x00, 0x00, 0x00, 0x04, 0x00, 0x01, 0xf6, 0x17, 0x38,
    0x55, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

// A texture with a side over 8192 is refused in one line naming the model and the texture,
// before its pixels are read: a file beside the model, and one embedded in it whose header
// claims 20000x20000 (beyond what any picture may be, and still the texture's bound that
// names it).
TEST(ModelTexture, ATextureTooLargeIsRefusedInOneLine) {
  const fs::path dir = folder();
  write_png(dir / "wide.png", RgbImage(kMaxTextureSide + 1, 1, {1, 2, 3}));
  const fs::path obj = obj_square(dir, "w", "newmtl w\nKd 1 1 1\nmap_Kd wide.png\n");
  EXPECT_EQ(error_of(obj), obj.string() +
                               ": texture 'wide.png' is 8193x1 pixels, larger than a texture may "
                               "be (sides up to 8192)");
  const fs::path huge =
      write_file(dir / "huge.png",
                 std::string(reinterpret_cast<const char*>(kHugeClaimPng), sizeof kHugeClaimPng));
  const fs::path gltf = gltf_square(dir / "huge.gltf", huge, "[1, 1, 1, 1]");
  EXPECT_EQ(error_of(gltf), gltf.string() +
                                ": embedded texture 0 is 20000x20000 pixels, larger than a "
                                "texture may be (sides up to 8192)");
}

// Debian's assimp-testmodels: the Khronos sample BoxTextured, its picture (a logo on grey)
// embedded in the .glb, drawn with it: many colours on the box, where its faces lit in their
// colour alone would show one each.
TEST(ModelTexture, BoxTexturedSampleShowsItsPicture) {
  const fs::path box = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  if (!fs::exists(box)) GTEST_SKIP() << box << " missing: apt-get install assimp-testmodels";
  const TriangleMesh mesh = load_mesh(box);
  EXPECT_EQ(mesh.left_out, "");
  ASSERT_EQ(mesh.textures.size(), 1u);
  SceneOptions options;
  options.mesh_file = box;
  auto scene = make_scene("mesh", options);
  const RgbImage image = render_canvas_rect(Canvas{96, 72}, Rect{0, 0, 96, 72}, *scene, 10);
  std::set<std::tuple<int, int, int>> colours;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const Rgb c = image.at(x, y);
      if (!(c == Rgb{})) colours.insert({c.r, c.g, c.b});
    }
  }
  EXPECT_GT(colours.size(), 20u);
}

// The sample spider (OBJ, JPEG textures named ".\SpiderTex.jpg" and so on): the four its meshes
// use all read (a fifth material is defined and not used).
TEST(ModelTexture, SpiderSampleHasItsTextures) {
  const fs::path spider = "/usr/share/assimp/models/OBJ/spider.obj";
  if (!fs::exists(spider)) GTEST_SKIP() << spider << " missing: apt-get install assimp-testmodels";
  const TriangleMesh mesh = load_mesh(spider);
  EXPECT_EQ(mesh.left_out.find("texture"), std::string::npos) << mesh.left_out;
  EXPECT_EQ(mesh.textures.size(), 4u);
  EXPECT_EQ(mesh.triangle_textures.size(), mesh.indices.size() / 3);
  EXPECT_EQ(std::count(mesh.triangle_textures.begin(), mesh.triangle_textures.end(), -1), 0);
}

// Every pipeserver draws its tiles of a textured model as the reference render draws the
// display: sort-first, and sort-last with an overlay, bit for bit, on a frame the camera has
// turned (the texels then meet the tiles' edges at angles).
class TexturedWall : public ::testing::TestWithParam<std::string> {};

TEST_P(TexturedWall, ReassemblesToTheReference) {
  const fs::path dir = folder();
  RgbImage picture(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      picture.set(x, y,
                  {static_cast<std::uint8_t>(16 * x), static_cast<std::uint8_t>(16 * y),
                   static_cast<std::uint8_t>(255 - 8 * (x + y))});
  write_png(dir / "ramp.png", picture);
  SceneOptions options;
  options.mesh_file = obj_square(dir, "r", "newmtl r\nKd 1 0.8 1\nmap_Kd ramp.png\n");
  auto scene = make_scene("mesh", options);
  const TileLayout layout =
      plan_layout(load_wall(fs::path(L2_SOURCE_DIR) / "walls" / (GetParam() + ".toml")));
  const int frame = 7;
  const auto check = test::check_wall(layout, *scene, frame);
  EXPECT_EQ(check.reassembly.errors.total(), 0u);
  test::ImageDiff all;
  for (const auto& d : check.diffs) all += d;
  EXPECT_EQ(all.pixels_differing, 0) << "max channel diff " << all.max_channel_diff;
}

INSTANTIATE_TEST_SUITE_P(Walls, TexturedWall, ::testing::Values("kd-2x2", "hybrid-2x1"));

}  // namespace
}  // namespace l2
