#include "gltf_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace l2::detail {

namespace {

using json = nlohmann::json;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
  throw std::runtime_error(fmt::format("{}: {}", path.string(), why));
}

// A node as the file names it (glTF 2.0: its index; 1.0: its key) and its children's names.
struct Node {
  std::string name;
  std::vector<std::string> children;
};

// The node tree, read with nlohmann's parser, which is not recursive, through its SAX events:
// nothing else of the document is kept. Depths count the containers open: 1 the root object, 2
// its "nodes" (an array in 2.0, an object in 1.0), 3 a node, 4 a node's "children".
struct NodeReader {
  std::vector<Node> nodes;
  bool by_index = true;  // "nodes" is an array (2.0): a node's name is its index
  bool too_deep = false;

  bool start_object(std::size_t) { return open(false); }
  bool start_array(std::size_t) { return open(true); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(std::string& k) {
    keys_[static_cast<std::size_t>(depth_)] = k;
    return true;
  }
  bool number_unsigned(std::uint64_t v) { return child(std::to_string(v)); }
  bool string(std::string& s) { return child(s); }
  bool number_integer(std::int64_t) { return child("-"); }  // no node's name
  bool number_float(double, const std::string&) { return child("-"); }
  bool null() { return true; }
  bool boolean(bool) { return true; }
  bool binary(json::binary_t&) { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) {
    return false;
  }

 private:
  bool in_nodes() const { return keys_[1] == "nodes" && !arrays_[1]; }
  bool open(bool array) {
    if (++depth_ > kMaxJsonDepth) {
      too_deep = true;
      return false;
    }
    arrays_[static_cast<std::size_t>(depth_)] = array;
    keys_[static_cast<std::size_t>(depth_)].clear();
    if (depth_ == 2 && in_nodes()) by_index = array;
    if (depth_ == 3 && in_nodes()) {
      nodes.push_back({by_index ? std::to_string(nodes.size()) : keys_[2], {}});
    }
    return true;
  }
  bool close() {
    --depth_;
    return true;
  }
  bool child(const std::string& name) {
    if (depth_ == 4 && in_nodes() && arrays_[4] && keys_[3] == "children" && !nodes.empty()) {
      nodes.back().children.push_back(name);
    }
    return true;
  }

  int depth_ = 0;
  std::string keys_[kMaxJsonDepth + 1];
  bool arrays_[kMaxJsonDepth + 1] = {};
};

// Up to `count` bytes of the file from `offset`.
std::string file_bytes(const std::filesystem::path& path, std::size_t offset, std::size_t count) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(offset));
  std::string bytes(count, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(count));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

std::uint32_t u32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = v << 8 | static_cast<std::uint8_t>(bytes[at + i]);
  return v;
}

// The JSON of a binary glTF (1.0: after a 20-byte header; 2.0: the first chunk), its length
// checked against the file's size first: Assimp allocates what the header declares.
std::string glb_json(const std::filesystem::path& path, std::uintmax_t size) {
  const std::string header = file_bytes(path, 0, 20);
  if (header.size() < 20) return {};  // Assimp says the header is cut short
  const std::uint32_t length = u32(header, 12);
  if (length > size - 20) {
    fail(path,
         fmt::format("its JSON chunk declares {} bytes, more than the file's {}", length, size));
  }
  return file_bytes(path, 20, length);
}

// "node 3" (2.0) or "node 'arm'" (1.0).
std::string named(const Node& n, bool by_index) {
  return by_index ? "node " + n.name : "node '" + n.name + "'";
}

// Each node's parent (or -1): a node with two, or listed twice by one, is refused.
std::vector<int> parents(const std::filesystem::path& path, const std::vector<Node>& nodes,
                         bool by_index) {
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < nodes.size(); ++i) index.emplace(nodes[i].name, static_cast<int>(i));
  std::vector<int> parent(nodes.size(), -1);
  for (std::size_t p = 0; p < nodes.size(); ++p) {
    for (const std::string& c : nodes[p].children) {
      const auto found = index.find(c);
      if (found == index.end()) continue;  // not a node: Assimp's error names it
      int& of = parent[static_cast<std::size_t>(found->second)];
      if (of == static_cast<int>(p)) {
        fail(path, fmt::format("{} is a child of {} twice (a glTF node has one parent)",
                               named(nodes[found->second], by_index), named(nodes[p], by_index)));
      }
      if (of >= 0) {
        fail(path, fmt::format("{} is a child of {} and of {} (a glTF node has one parent)",
                               named(nodes[found->second], by_index),
                               named(nodes[static_cast<std::size_t>(of)], by_index),
                               named(nodes[p], by_index)));
      }
      of = static_cast<int>(p);
    }
  }
  return parent;
}

// Each node's depth below its tree's root (1), from its parent's, without recursion: a walk up
// to a node whose depth is known, or to a root, then back down. Nodes on a cycle (no root above
// them) are left to Assimp, which names them.
void check_depth(const std::filesystem::path& path, const std::vector<Node>& nodes,
                 const std::vector<int>& parent, bool by_index) {
  constexpr int kUnknown = 0, kWalking = -1, kOnCycle = -2;
  std::vector<int> depth(nodes.size(), kUnknown);
  for (std::size_t start = 0; start < nodes.size(); ++start) {
    std::vector<std::size_t> walk;
    std::size_t n = start;
    while (depth[n] == kUnknown) {
      depth[n] = kWalking;
      walk.push_back(n);
      if (parent[n] < 0) break;
      n = static_cast<std::size_t>(parent[n]);
    }
    if (walk.empty()) continue;
    int d = depth[n];                                     // above the walk: known, or on a cycle
    if (d == kWalking) d = parent[n] < 0 ? 0 : kOnCycle;  // n is the walk's root, or it came back
    for (auto it = walk.rbegin(); it != walk.rend(); ++it) depth[*it] = d == kOnCycle ? d : ++d;
  }
  const auto deepest = std::max_element(depth.begin(), depth.end());
  if (deepest != depth.end() && *deepest > kMaxNodeDepth) {
    fail(path, fmt::format("nodes nested {} deep ({}), more than the {} levels read here", *deepest,
                           named(nodes[deepest - depth.begin()], by_index), kMaxNodeDepth));
  }
}

}  // namespace

void check_gltf(const std::filesystem::path& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) return;
  // Only a binary glTF or JSON is read on: a model of another format costs a look at its start.
  const std::string start = file_bytes(path, 0, 4096);
  const bool binary = start.rfind("glTF", 0) == 0;
  const auto first = start.find_first_not_of(" \t\r\n");
  if (!binary && (first == std::string::npos || (start[first] != '{' && start[first] != '[')))
    return;
  const std::string text = binary ? glb_json(path, size) : file_bytes(path, 0, size);
  NodeReader reader;
  const bool parsed = json::sax_parse(text, &reader);
  if (reader.too_deep) fail(path, fmt::format("JSON nested deeper than {} levels", kMaxJsonDepth));
  if (!parsed) return;
  check_depth(path, reader.nodes, parents(path, reader.nodes, reader.by_index), reader.by_index);
}

}  // namespace l2::detail
