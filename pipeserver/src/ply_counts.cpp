#include "ply_counts.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace l2::detail {

namespace {

// Bytes a binary value of the type takes; 0 for an unknown type (Assimp refuses those).
std::uintmax_t binary_size(const std::string& type) {
  static const std::map<std::string, std::uintmax_t> sizes{
      {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

struct Element {
  std::string name;
  std::uintmax_t count = 0, min_bytes = 0;  // the fewest bytes one entry can take
  int line = 0;
};

}  // namespace

PlyFormat check_ply_counts(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) return PlyFormat::none;
  bool ascii = false;
  const auto format = [&] { return ascii ? PlyFormat::ascii : PlyFormat::binary; };
  std::vector<Element> elements;
  int number = 1;
  // A header is short: past 10000 lines it is not one, and Assimp will say so.
  while (std::getline(in, line) && ++number < 10000) {
    std::istringstream words(line);
    std::string word, type;
    words >> word;
    if (word == "end_header") break;
    if (word == "format") {
      words >> type;
      ascii = type == "ascii";
    } else if (word == "element") {
      Element e;
      e.line = number;
      words >> e.name >> e.count;
      if (!words) return format();  // a malformed count: Assimp's error names it
      elements.push_back(e);
    } else if (word == "property" && !elements.empty()) {
      words >> type;
      if (type == "list") words >> type;  // a list takes at least its length
      // In ASCII each value takes a character and a separator (the last one none, so that is
      // one byte of slack per file).
      elements.back().min_bytes += ascii ? 2 : binary_size(type);
    }
  }
  const std::streamoff header = in.tellg();
  if (header < 0) return format();
  std::uintmax_t left = std::filesystem::file_size(path) - static_cast<std::uintmax_t>(header) + 1;
  for (const Element& e : elements) {
    if (e.min_bytes == 0) continue;  // takes no bytes, whatever its count
    if (e.count > left / e.min_bytes) {
      throw std::runtime_error(fmt::format(
          "{}:{}: element '{}' declares {} entries, more than the rest of the file can hold",
          path.string(), e.line, e.name, e.count));
    }
    left -= e.count * e.min_bytes;
  }
  return format();
}

}  // namespace l2::detail
