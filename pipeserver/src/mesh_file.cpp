#include "pipeserver/mesh_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace l2 {

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, int line, const std::string& what) {
  if (line > 0) throw std::runtime_error(fmt::format("{}:{}: {}", path.string(), line, what));
  throw std::runtime_error(fmt::format("{}: {}", path.string(), what));
}

// ---- PLY ------------------------------------------------------------------------------------

enum class PlyType { I8, U8, I16, U16, I32, U32, F32, F64 };

std::optional<PlyType> ply_type(const std::string& s) {
  if (s == "char" || s == "int8") return PlyType::I8;
  if (s == "uchar" || s == "uint8") return PlyType::U8;
  if (s == "short" || s == "int16") return PlyType::I16;
  if (s == "ushort" || s == "uint16") return PlyType::U16;
  if (s == "int" || s == "int32") return PlyType::I32;
  if (s == "uint" || s == "uint32") return PlyType::U32;
  if (s == "float" || s == "float32") return PlyType::F32;
  if (s == "double" || s == "float64") return PlyType::F64;
  return std::nullopt;
}

int ply_size(PlyType t) {
  switch (t) {
    case PlyType::I8:
    case PlyType::U8:
      return 1;
    case PlyType::I16:
    case PlyType::U16:
      return 2;
    case PlyType::I32:
    case PlyType::U32:
    case PlyType::F32:
      return 4;
    case PlyType::F64:
      return 8;
  }
  return 1;
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::F32;
  bool is_list = false;
  PlyType count_type = PlyType::U8;
};

struct PlyElement {
  std::string name;
  long count = 0;
  std::vector<PlyProperty> properties;
  int line = 0;  // of its `element` line in the header
};

// The fewest bytes one entry of `e` can take: in binary its types' sizes, a list empty; in ASCII
// a character and a separator for each value.
std::uint64_t min_entry_bytes(const PlyElement& e, bool binary) {
  std::uint64_t bytes = 0;
  for (const PlyProperty& p : e.properties) {
    bytes += binary ? static_cast<std::uint64_t>(ply_size(p.is_list ? p.count_type : p.type)) : 2;
  }
  return bytes;
}

// Refuses an element that declares more entries than the bytes after the header can hold, before
// reading a value: a made-up count fails here and not after billions of reads.
void check_counts_fit(const std::vector<PlyElement>& elements, std::istream& in, bool binary,
                      const std::filesystem::path& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  const std::streamoff body = in.tellg();
  if (error || body < 0 || static_cast<std::uintmax_t>(body) > size) return;
  // In ASCII the last value of the file needs no separator after it.
  std::uint64_t left = size - static_cast<std::uintmax_t>(body) + (binary ? 0 : 1);
  for (const PlyElement& e : elements) {
    const std::uint64_t per_entry = min_entry_bytes(e, binary);
    if (per_entry == 0) continue;
    if (static_cast<std::uint64_t>(e.count) > left / per_entry) {
      fail(path, e.line,
           fmt::format("element '{}' declares {} entries, more than the rest of the file can hold",
                       e.name, e.count));
    }
    left -= static_cast<std::uint64_t>(e.count) * per_entry;
  }
}

// Reads values from the body, either as text tokens or as little-endian binary.
class PlyReader {
 public:
  // `first_line`: the line the body starts on, for messages about ASCII values.
  PlyReader(std::istream& in, bool binary, const std::filesystem::path& path, int first_line)
      : in_(in), binary_(binary), path_(path), line_(first_line) {}

  // The line of the value read last in an ASCII body; 0 (none) in a binary one.
  int line() const { return binary_ ? 0 : line_; }

  double read(PlyType t) {
    if (!binary_) {
      for (int c = in_.peek(); c != std::char_traits<char>::eof() && std::isspace(c);
           c = in_.peek()) {
        if (in_.get() == '\n') ++line_;
      }
      double v = 0;
      if (!(in_ >> v)) fail(path_, 0, fmt::format("PLY body ends early or holds a non-number"));
      return v;
    }
    unsigned char b[8] = {};
    in_.read(reinterpret_cast<char*>(b), ply_size(t));
    if (!in_) fail(path_, 0, "PLY binary body ends early");
    switch (t) {
      case PlyType::I8:
        return static_cast<std::int8_t>(b[0]);
      case PlyType::U8:
        return b[0];
      case PlyType::I16:
        return as<std::int16_t>(b);
      case PlyType::U16:
        return as<std::uint16_t>(b);
      case PlyType::I32:
        return as<std::int32_t>(b);
      case PlyType::U32:
        return as<std::uint32_t>(b);
      case PlyType::F32:
        return as<float>(b);
      case PlyType::F64:
        return as<double>(b);
    }
    return 0;
  }

 private:
  template <class T>
  static double as(const unsigned char* b) {
    T v;
    std::memcpy(&v, b, sizeof v);  // the host is little-endian (x86-64, aarch64)
    return static_cast<double>(v);
  }
  std::istream& in_;
  bool binary_;
  const std::filesystem::path& path_;
  int line_;
};

// Whether `v` is a whole number in lo..hi (NaN is not): a list length or a vertex index, which
// a float-typed list can hold as 1.5 or 1e10.
bool whole_in(double v, double lo, double hi) {
  return v >= lo && v <= hi && v == std::floor(v);
}

// A vertex coordinate as a float, or nullopt when it is not a finite float (NaN, infinity, or
// beyond 3.4e38, which would become infinity): normalising a mesh with such a vertex makes every
// vertex NaN, and the scene renders nothing.
std::optional<float> finite_float(double v) {
  if (!std::isfinite(v) || std::fabs(v) > std::numeric_limits<float>::max()) return std::nullopt;
  return static_cast<float>(v);
}

std::string not_finite(long vertex, char axis, double value) {
  return fmt::format("vertex {}: {} = {} is not a finite float", vertex, axis, value);
}

std::vector<PlyElement> read_ply_header(std::istream& in, const std::filesystem::path& path,
                                        bool& binary, int& line) {
  std::string text;
  std::getline(in, text);
  line = 1;
  if (text.rfind("ply", 0) != 0) fail(path, 1, "not a PLY file (first line is not 'ply')");
  std::vector<PlyElement> elements;
  bool have_format = false;
  while (std::getline(in, text)) {
    ++line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    std::istringstream words(text);
    std::string word;
    words >> word;
    if (word == "end_header") {
      if (!have_format) fail(path, line, "PLY header has no format line");
      return elements;
    }
    if (word == "format") {
      std::string f;
      words >> f;
      if (f == "ascii")
        binary = false;
      else if (f == "binary_little_endian")
        binary = true;
      else
        fail(path, line, fmt::format("unsupported PLY format '{}'", f));
      have_format = true;
    } else if (word == "element") {
      PlyElement e;
      if (!(words >> e.name >> e.count) || e.count < 0) fail(path, line, "bad element line");
      e.line = line;
      elements.push_back(e);
    } else if (word == "property") {
      if (elements.empty()) fail(path, line, "property before any element");
      PlyProperty p;
      std::string t;
      words >> t;
      if (t == "list") {
        std::string ct, it;
        words >> ct >> it >> p.name;
        const auto c = ply_type(ct), i = ply_type(it);
        if (!c || !i) fail(path, line, "bad list property types");
        p.is_list = true;
        p.count_type = *c;
        p.type = *i;
      } else {
        const auto ty = ply_type(t);
        if (!ty) fail(path, line, fmt::format("unknown property type '{}'", t));
        p.type = *ty;
        words >> p.name;
      }
      elements.back().properties.push_back(p);
    }
  }
  fail(path, line, "PLY header has no end_header");
}

TriangleMesh load_ply(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, 0, "cannot open");
  bool binary = false;
  int line = 0;
  const auto elements = read_ply_header(in, path, binary, line);
  check_counts_fit(elements, in, binary, path);
  PlyReader reader(in, binary, path, line + 1);
  TriangleMesh mesh;
  for (const auto& e : elements) {
    const auto find = [&](const char* n) {
      const auto it = std::find_if(e.properties.begin(), e.properties.end(),
                                   [&](const PlyProperty& p) { return p.name == n; });
      return static_cast<int>(it - e.properties.begin());
    };
    const int ix = find("x"), iy = find("y"), iz = find("z");
    const int ifaces = std::min(find("vertex_indices"), find("vertex_index"));
    const bool is_vertex = e.name == "vertex";
    const bool is_face = e.name == "face";
    if (is_vertex && (ix >= static_cast<int>(e.properties.size()) ||
                      iy >= static_cast<int>(e.properties.size()) ||
                      iz >= static_cast<int>(e.properties.size()))) {
      fail(path, 0, "PLY vertex element lacks x, y or z");
    }
    if (e.properties.empty()) continue;  // no bytes in the body, whatever its count
    for (long n = 0; n < e.count; ++n) {
      glm::vec3 v{0.0f};
      std::vector<std::uint32_t> poly;
      for (int pi = 0; pi < static_cast<int>(e.properties.size()); ++pi) {
        const auto& p = e.properties[pi];
        if (p.is_list) {
          const double count = reader.read(p.count_type);
          if (!whole_in(count, 0, 1000)) {
            fail(path, reader.line(), fmt::format("{} {}: bad list length {}", e.name, n, count));
          }
          for (int k = 0; k < static_cast<int>(count); ++k) {
            const double idx = reader.read(p.type);
            if (!is_face || pi != ifaces) continue;
            if (!whole_in(idx, 0, std::numeric_limits<std::uint32_t>::max())) {
              fail(path, reader.line(),
                   fmt::format("face {}: vertex index {} is not an integer 0..{}", n, idx,
                               std::numeric_limits<std::uint32_t>::max()));
            }
            poly.push_back(static_cast<std::uint32_t>(idx));
          }
        } else {
          const double value = reader.read(p.type);
          if (!is_vertex || (pi != ix && pi != iy && pi != iz)) continue;
          const char axis = pi == ix ? 'x' : pi == iy ? 'y' : 'z';
          const auto f = finite_float(value);
          if (!f) fail(path, reader.line(), not_finite(n, axis, value));
          v[axis - 'x'] = *f;
        }
      }
      if (is_vertex) mesh.positions.push_back(v);
      for (std::size_t k = 2; k < poly.size(); ++k) {
        mesh.indices.insert(mesh.indices.end(), {poly[0], poly[k - 1], poly[k]});
      }
    }
  }
  for (const auto idx : mesh.indices) {
    if (idx >= mesh.positions.size()) {
      fail(path, 0, fmt::format("face refers to vertex {} of {}", idx, mesh.positions.size()));
    }
  }
  return mesh;
}

// ---- OBJ ------------------------------------------------------------------------------------

TriangleMesh load_obj(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) fail(path, 0, "cannot open");
  TriangleMesh mesh;
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    std::istringstream words(text);
    std::string kind;
    words >> kind;
    if (kind == "v") {
      double xyz[3];
      if (!(words >> xyz[0] >> xyz[1] >> xyz[2])) fail(path, line, "vertex needs three numbers");
      glm::vec3 v;
      for (int a = 0; a < 3; ++a) {
        const auto f = finite_float(xyz[a]);
        // Numbered from 1, as the face lines number them.
        const long vertex = static_cast<long>(mesh.positions.size()) + 1;
        if (!f) fail(path, line, not_finite(vertex, static_cast<char>('x' + a), xyz[a]));
        v[a] = *f;
      }
      mesh.positions.push_back(v);
    } else if (kind == "f") {
      std::vector<std::uint32_t> poly;
      std::string corner;
      while (words >> corner) {
        long idx = 0;
        try {
          idx = std::stol(corner.substr(0, corner.find('/')));
        } catch (const std::exception&) {
          fail(path, line, fmt::format("bad face corner '{}'", corner));
        }
        // Negative indices count back from the latest vertex.
        if (idx < 0) idx += static_cast<long>(mesh.positions.size()) + 1;
        if (idx < 1 || idx > static_cast<long>(mesh.positions.size())) {
          fail(path, line,
               fmt::format("face refers to vertex {} of {}", idx, mesh.positions.size()));
        }
        poly.push_back(static_cast<std::uint32_t>(idx - 1));
      }
      if (poly.size() < 3) fail(path, line, "face needs at least three corners");
      for (std::size_t k = 2; k < poly.size(); ++k) {
        mesh.indices.insert(mesh.indices.end(), {poly[0], poly[k - 1], poly[k]});
      }
    }
  }
  return mesh;
}

}  // namespace

TriangleMesh load_mesh(const std::filesystem::path& path) {
  auto ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  TriangleMesh mesh;
  if (ext == ".ply")
    mesh = load_ply(path);
  else if (ext == ".obj")
    mesh = load_obj(path);
  else
    fail(path, 0, "unknown mesh format (expected .ply or .obj)");
  if (mesh.indices.empty()) fail(path, 0, "mesh has no triangles");
  return mesh;
}

}  // namespace l2
