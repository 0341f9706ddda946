// Model and picture files made to hurt a reader that trusts them: nested past any real scene,
// declaring sizes the file cannot hold, cut short, or not what their names say. Each is small;
// what it claims is not. Written by the tests that need them (unit and process tests). The
// pictures are in hostile_pictures.hpp (and hostile_png.hpp), the models here.
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pipeserver/hostile_pictures.hpp"

namespace l2::hostile {

inline void write(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// A glTF 2.0 triangle (its buffer inline) under `nodes`, a JSON array of node objects (node 0
// the scene's root), with `extra` members added to the document.
inline std::string gltf(const std::string& nodes, const std::string& extra = "") {
  // Three vertices (0,0,0) (1,0,0) (0,1,0) as 36 bytes of little-endian floats, in base64.
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": )" +
         nodes + R"(, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
"buffers": [{"byteLength": 36,
  "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
"bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
"accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
  "min": [0, 0, 0], "max": [1, 1, 0]}])" +
         extra + "}";
}

// Nodes 0..n-1, each the only child of the one before; the last holds the mesh.
inline std::string node_chain(int n) {
  std::string nodes = "[";
  for (int i = 0; i + 1 < n; ++i) nodes += R"({"children": [)" + std::to_string(i + 1) + "]},";
  return nodes + R"({"mesh": 0}])";
}

// Nodes 0..levels, each listing the next twice: 2^levels paths to the last.
inline std::string node_diamonds(int levels) {
  std::string nodes = "[";
  for (int i = 0; i < levels; ++i) {
    nodes += R"({"children": [)" + std::to_string(i + 1) + "," + std::to_string(i + 1) + "]},";
  }
  return nodes + R"({"mesh": 0}])";
}

// A Collada file of one triangle in `n` nodes nested one in another, the last holding it, one a
// line: COLLADA is element level 1 (line 2), the two scene elements 2 and 3 (line 3), so the node
// opened on line k is level k.
inline std::string collada_chain(int n) {
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
      "<library_visual_scenes><visual_scene id=\"s\">\n";
  for (int i = 0; i < n; ++i) out += "<node id=\"n" + std::to_string(i) + "\">\n";
  out += "<instance_geometry url=\"#g\"/>";
  for (int i = 0; i < n; ++i) out += "</node>";
  return out +
         "\n</visual_scene></library_visual_scenes>\n"
         "<library_geometries><geometry id=\"g\"><mesh>"
         "<source id=\"p\"><float_array id=\"pa\" count=\"9\">0 0 0 1 0 0 0 1 0</float_array>"
         "<technique_common><accessor source=\"#pa\" count=\"3\" stride=\"3\">"
         "<param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/>"
         "<param name=\"Z\" type=\"float\"/></accessor></technique_common></source>"
         "<vertices id=\"v\"><input semantic=\"POSITION\" source=\"#p\"/></vertices>"
         "<triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#v\" offset=\"0\"/>"
         "<p>0 1 2</p></triangles></mesh></geometry></library_geometries>\n"
         "<scene><instance_visual_scene url=\"#s\"/></scene>\n</COLLADA>\n";
}

// A DirectX text file of `n` frames nested one in another, one a line.
inline std::string x_frame_chain(int n) {
  std::string out = "xof 0302txt 0064\n";
  for (int i = 0; i < n; ++i) out += "Frame f" + std::to_string(i) + " {\n";
  return out + std::string(static_cast<std::size_t>(n), '}') + "\n";
}

// `depth` arrays nested in one another.
inline std::string nested_arrays(int depth) {
  return std::string(static_cast<std::size_t>(depth), '[') +
         std::string(static_cast<std::size_t>(depth), ']');
}

// A binary glTF (2.0) whose JSON chunk declares `declared` bytes; it holds a small document.
inline std::string glb(std::uint32_t declared) {
  const std::string json = R"({"asset": {"version": "2.0"}})";
  std::string out = "glTF" + bytes_of(std::uint32_t{2}) +
                    bytes_of(static_cast<std::uint32_t>(12 + 8 + json.size())) +
                    bytes_of(declared) + "JSON" + json;
  return out;
}

// A PLY triangle's header (`format`: ascii or binary_little_endian; `count_type` the faces'
// list length's type) and an ASCII body.
inline std::string ply_header(const std::string& format, const std::string& count_type = "uchar") {
  return "ply\nformat " + format +
         " 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 1\nproperty list " +
         count_type + " int vertex_indices\nend_header\n";
}
inline const std::string kPlyAsciiBody = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

// A binary PLY triangle whose face declares `length` indices (its list length a uint) and holds
// three.
inline std::string binary_ply_list(std::uint32_t length) {
  std::string body;
  for (const float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) body += bytes_of(c);
  body += bytes_of(length);
  for (const std::int32_t i : {0, 1, 2}) body += bytes_of(i);
  return ply_header("binary_little_endian", "uint") + body;
}

}  // namespace l2::hostile
