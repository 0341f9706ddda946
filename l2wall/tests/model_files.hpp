// Model files the content tests write: a small glTF 2.0 with a base colour (JSON with the
// buffer inline as base64) and a finely tessellated sphere as binary PLY.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace l2::testing_support {

inline std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t v = static_cast<std::uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<std::uint8_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<std::uint8_t>(bytes[i + 2]);
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[v & 63] : '=';
  }
  return out;
}

template <typename T>
void append_bytes(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// A square of side 2 in the z = 0 plane facing +z, two triangles, base colour `rgb`.
inline void write_gltf_square(const std::filesystem::path& path, const float rgb[3]) {
  std::string buffer;
  for (const float p : {-1.f, -1.f, 0.f, 1.f, -1.f, 0.f, 1.f, 1.f, 0.f, -1.f, 1.f, 0.f})
    append_bytes(buffer, p);
  for (const int i : {0, 1, 2, 0, 2, 3}) append_bytes(buffer, static_cast<std::uint16_t>(i));
  std::ofstream(path) << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
"nodes": [{"mesh": 0}],
"meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
"materials": [{"pbrMetallicRoughness": {"baseColorFactor": [)"
                      << rgb[0] << ", " << rgb[1] << ", " << rgb[2] << R"(, 1.0]}}],
"buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,)"
                      << base64(buffer) << R"("}],
"bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
"accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
               "min": [-1, -1, 0], "max": [1, 1, 0]},
              {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]}
)";
}

// A UV sphere of `stacks` x `slices` quads, two triangles each: 2 x stacks x slices triangles
// (the pole quads are triangles with a repeated corner left out, so slightly fewer).
inline long write_ply_sphere(const std::filesystem::path& path, int stacks, int slices) {
  std::string vertices, faces;
  const double pi = std::acos(-1.0);
  long vertex_count = 0, face_count = 0;
  for (int i = 0; i <= stacks; ++i) {
    const double theta = pi * i / stacks;
    for (int j = 0; j < slices; ++j, ++vertex_count) {
      const double phi = 2 * pi * j / slices;
      for (const double c :
           {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)})
        append_bytes(vertices, static_cast<float>(c));
    }
  }
  const auto at = [&](int i, int j) { return static_cast<std::int32_t>(i * slices + j % slices); };
  const auto triangle = [&](std::int32_t a, std::int32_t b, std::int32_t c) {
    faces += '\3';
    append_bytes(faces, a);
    append_bytes(faces, b);
    append_bytes(faces, c);
    ++face_count;
  };
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      if (i > 0) triangle(at(i, j), at(i + 1, j), at(i, j + 1));
      if (i + 1 < stacks) triangle(at(i, j + 1), at(i + 1, j), at(i + 1, j + 1));
    }
  }
  std::ofstream(path, std::ios::binary)
      << "ply\nformat binary_little_endian 1.0\nelement vertex " << vertex_count
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << face_count
      << "\nproperty list uchar int vertex_indices\nend_header\n"
      << vertices << faces;
  return face_count;
}

}  // namespace l2::testing_support
