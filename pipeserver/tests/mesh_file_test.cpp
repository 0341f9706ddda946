#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "pipeserver/mesh_file.hpp"
#include "pipeserver/scene.hpp"

namespace l2 {
namespace {

namespace fs = std::filesystem;

fs::path write_file(const std::string& name, const std::string& bytes) {
  const fs::path dir = fs::temp_directory_path() / "l2_pipeserver_mesh_test";
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << bytes;
  return dir / name;
}

std::string error_of(const fs::path& p) {
  try {
    load_mesh(p);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(MeshFile, AsciiPlyQuadIsFanned) {
  const auto p = write_file("quad.ply",
                            "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                            "property float y\nproperty float z\nproperty uchar red\n"
                            "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                            "0 0 0 9\n1 0 0 9\n1 1 0 9\n0 1 0.5 9\n4 0 1 2 3\n");
  const auto m = load_mesh(p);
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.positions[3], glm::vec3(0, 1, 0.5f));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
}

TEST(MeshFile, BinaryLittleEndianPly) {
  std::string body;
  const auto put = [&](const void* p, std::size_t n) {
    body.append(static_cast<const char*>(p), n);
  };
  const float v[3][3] = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}};
  for (const auto& vert : v) put(vert, sizeof vert);
  const unsigned char n = 3;
  const std::int32_t idx[3] = {2, 1, 0};
  put(&n, 1);
  put(idx, sizeof idx);
  const auto p = write_file("tri.ply",
                            "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                            "property float x\nproperty float y\nproperty float z\n"
                            "element face 1\nproperty list uchar int vertex_indices\nend_header\n" +
                                body);
  const auto m = load_mesh(p);
  EXPECT_EQ(m.positions[2], glm::vec3(0, 3, 0));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{2, 1, 0}));
}

TEST(MeshFile, ObjWithSlashesAndNegativeIndices) {
  const auto p =
      write_file("tri.obj", "# tri\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 -1//1\n");
  const auto m = load_mesh(p);
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(MeshFile, ErrorsNameFileLineAndProblem) {
  const auto obj = write_file("bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
  EXPECT_EQ(error_of(obj), obj.string() + ":3: face refers to vertex 7 of 2");
  const auto ply = write_file("bad.ply",
                              "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                              "property float y\nproperty float z\nend_header\n1 2\n");
  // Two values in 4 bytes: too short for three, refused before reading (see below).
  EXPECT_EQ(error_of(ply), ply.string() +
                               ":3: element 'vertex' declares 1 entries, more than the rest of the "
                               "file can hold");
  const auto word = write_file("word.ply",
                               "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                               "property float y\nproperty float z\nend_header\n1 2 z\n");
  EXPECT_EQ(error_of(word), word.string() + ": PLY body ends early or holds a non-number");
  const auto range = write_file("range.ply",
                                "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                "property float y\nproperty float z\nelement face 1\n"
                                "property list uchar int vertex_indices\nend_header\n"
                                "0 0 0\n3 0 0 5\n");
  EXPECT_EQ(error_of(range), range.string() + ": face refers to vertex 5 of 1");
  EXPECT_EQ(error_of(write_file("x.stl", "solid")),
            (fs::temp_directory_path() / "l2_pipeserver_mesh_test" / "x.stl").string() +
                ": unknown mesh format (expected .ply or .obj)");
  EXPECT_NE(error_of("/nonexistent/bunny.ply").find("cannot open"), std::string::npos);
}

// An element without properties takes no bytes, whatever its count: skipped, not looped over
// (a count of 9e18 spun for hours). One with properties may not declare more entries than the
// rest of the file can hold: in ASCII each value takes at least a character and a separator
// (the last one none), in binary its type's size; a list may be empty.
TEST(MeshFile, PlyElementCountsAreBoundedByTheFile) {
  const auto header = [](int vertices) {
    return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\n"
           "element junk 9000000000000000000\nelement face 1\n"
           "property list uchar int vertex_indices\nend_header\n";
  };
  const auto m = load_mesh(write_file("junk.ply", header(3) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));
  // 13 values in the fewest bytes, 25: still enough.
  EXPECT_EQ(load_mesh(write_file("tight.ply", header(3) + "0 0 0 1 0 0 0 1 0 3 0 1 2")).indices,
            (std::vector<std::uint32_t>{0, 1, 2}));
  // 5 vertices need at least 30 bytes.
  const auto five = write_file("five.ply", header(5) + "0 0 0 1 0 0 0 1 0 3 0 1 2\n");
  EXPECT_EQ(error_of(five), five.string() +
                                ":3: element 'vertex' declares 5 entries, more than the rest of "
                                "the file can hold");
  const auto huge =
      write_file("huge.ply",
                 "ply\nformat binary_little_endian 1.0\nelement vertex 9000000000000000000\n"
                 "property float x\nproperty float y\nproperty float z\nend_header\n" +
                     std::string(12 * 1000, '\0'));
  EXPECT_EQ(error_of(huge), huge.string() +
                                ":3: element 'vertex' declares 9000000000000000000 entries, more "
                                "than the rest of the file can hold");
}

// A vertex index is an integer 0..2^32-1 whatever the list's type: 4294967296 used to wrap to
// vertex 0, 1.5 in a float list to be cut to 1, -1 to be converted with undefined behaviour.
TEST(MeshFile, PlyFaceIndicesMustBeWholeAndFitUint32) {
  const auto ascii = [](const std::string& index, const std::string& count_type) {
    return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
           "property float z\nelement face 2\nproperty list " +
           count_type + " int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1\n  " +
           index + "\n";
  };
  const auto wraps = write_file("wraps.ply", ascii("4294967296", "uchar"));
  EXPECT_EQ(
      error_of(wraps),
      wraps.string() + ":15: face 1: vertex index 4294967296 is not an integer 0..4294967295");
  const auto negative = write_file("negative.ply", ascii("-1", "uchar"));
  EXPECT_EQ(error_of(negative),
            negative.string() + ":15: face 1: vertex index -1 is not an integer 0..4294967295");
  EXPECT_EQ(load_mesh(write_file("fits.ply", ascii("2", "uchar"))).indices,
            (std::vector<std::uint32_t>{0, 1, 2, 0, 1, 2}));
  // A list length is a whole number too: 3.5 used to read three indices.
  const auto length = write_file("length.ply", ascii("2", "float"));
  std::string text = ascii("2", "float");
  text.replace(text.rfind("3 0 1\n"), 1, "3.5");
  const auto half = write_file("half.ply", text);
  EXPECT_EQ(error_of(half), half.string() + ":14: face 1: bad list length 3.5");
  EXPECT_EQ(load_mesh(length).indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 1, 2}));

  std::string body;
  const float v[3][3] = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}};
  body.append(reinterpret_cast<const char*>(v), sizeof v);
  const unsigned char n = 3;
  const float idx[3] = {2, 1.5f, 0};
  body.append(reinterpret_cast<const char*>(&n), 1);
  body.append(reinterpret_cast<const char*>(idx), sizeof idx);
  const auto binary =
      write_file("float_index.ply",
                 "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 "element face 1\nproperty list uchar float vertex_indices\nend_header\n" +
                     body);
  EXPECT_EQ(error_of(binary),
            binary.string() + ": face 0: vertex index 1.5 is not an integer 0..4294967295");
}

// A coordinate that is not a finite float (NaN, infinity, or beyond 3.4e38, which becomes
// infinity as a float) used to load; normalising the mesh then made every vertex NaN and the
// scene rendered nothing.
TEST(MeshFile, CoordinatesMustBeFiniteFloats) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const auto ascii = write_file("inf.ply", header + "0 0 0\n1e39 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(error_of(ascii), ascii.string() + ":11: vertex 1: x = 1e+39 is not a finite float");

  const auto binary = [](const std::string& type, const std::string& vertices) {
    return "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty " + type +
           " x\nproperty " + type + " y\nproperty " + type +
           " z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n" + vertices +
           std::string(1, '\3') + std::string("\0\0\0\0\1\0\0\0\2\0\0\0", 12);
  };
  const auto bytes = [](const auto& values) {
    return std::string(reinterpret_cast<const char*>(values), sizeof values);
  };
  const float nan[9] = {0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0};
  const auto f = write_file("nan.ply", binary("float", bytes(nan)));
  EXPECT_EQ(error_of(f), f.string() + ": vertex 2: y = nan is not a finite float");
  const double big[9] = {0, 0, 0, 1, 0, 0, 0, 1, 1e300};
  const auto d = write_file("big.ply", binary("double", bytes(big)));
  EXPECT_EQ(error_of(d), d.string() + ": vertex 2: z = 1e+300 is not a finite float");
  const double fine[9] = {0, 0, 0, 1, 0, 0, 0, 1, 3e38};
  EXPECT_EQ(load_mesh(write_file("fine.ply", binary("double", bytes(fine)))).positions[2].z, 3e38f);

  const auto obj = write_file("inf.obj", "v 0 0 0\nv 1 1e39 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(error_of(obj), obj.string() + ":2: vertex 2: y = 1e+39 is not a finite float");
  const auto word = write_file("word.obj", "v 0 0 0\nv 1 nan 0\n");
  EXPECT_EQ(error_of(word), word.string() + ":2: vertex needs three numbers");
}

TEST(MeshFile, BundledBunnyLoads) {
  const auto m = load_mesh(default_mesh_file());
  EXPECT_EQ(m.positions.size(), 1839u);
  EXPECT_EQ(m.indices.size(), 3u * 3674u);
}

}  // namespace
}  // namespace l2
