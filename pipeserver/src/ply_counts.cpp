#include "ply_counts.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "ply_lists.hpp"

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

struct PlyHeader {
  bool ascii = false, big_endian = false;
  bool counts = true;  // every element's count read (a malformed one: Assimp's error names it)
  std::vector<PlyElement> elements;
  std::size_t body = 0;  // where the body starts
};

// "property [list COUNT_TYPE] TYPE NAME" of the element read last.
void add_property(std::istringstream& words, PlyHeader& h) {
  PlyProperty p;
  std::string type;
  words >> type;
  if (type == "list") {
    p.list = true;
    words >> type;
    p.count_size = binary_size(type);
    p.count_type = type;
    words >> type;
  }
  p.size = binary_size(type);
  p.type = type;
  words >> p.name;
  PlyElement& e = h.elements.back();
  // In ASCII each value takes a character and a separator (the last one none, so that is one
  // byte of slack per file); a list takes at least its length.
  e.min_bytes += h.ascii ? 2 : (p.list ? p.count_size : p.size);
  e.properties.push_back(p);
}

// The header up to end_header. Assimp reads a header cut short on and on, waiting for
// end_header: refused here.
PlyHeader read_header(const std::filesystem::path& path, const std::string& text) {
  PlyHeader h;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // "ply"
  // A header is short: past 10000 lines it is not one, and Assimp will say so.
  for (int number = 2; number < 10000; ++number) {
    if (!std::getline(in, line)) {
      throw std::runtime_error(
          fmt::format("{}: the PLY header ends without end_header (cut short?)", path.string()));
    }
    std::istringstream words(line);
    std::string word, type;
    words >> word;
    if (word == "end_header") {
      const std::streamoff after = in.tellg();
      h.body = after < 0 ? text.size() : static_cast<std::size_t>(after);
      break;
    }
    if (word == "format") {
      words >> type;
      h.ascii = type == "ascii";
      h.big_endian = type == "binary_big_endian";
    } else if (word == "element") {
      PlyElement e;
      e.line = number;
      words >> e.name >> e.count;
      h.counts = h.counts && words;
      h.elements.push_back(e);
    } else if (word == "property" && !h.elements.empty()) {
      add_property(words, h);
    }
  }
  return h;
}

}  // namespace

PlyFormat check_ply_counts(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text(3, '\0');
  in.read(text.data(), 3);
  if (text != "ply") return PlyFormat::none;  // another format costs a look at its start
  text.append(std::istreambuf_iterator<char>(in), {});
  const PlyHeader h = read_header(path, text);
  const PlyFormat format = h.ascii ? PlyFormat::ascii : PlyFormat::binary;
  if (h.body == 0 || !h.counts) return format;
  std::uintmax_t left = text.size() - h.body + 1;
  for (const PlyElement& e : h.elements) {
    if (e.min_bytes == 0) continue;  // takes no bytes, whatever its count
    if (e.count > left / e.min_bytes) {
      throw std::runtime_error(fmt::format(
          "{}:{}: element '{}' declares {} entries, more than the rest of the file can hold",
          path.string(), e.line, e.name, e.count));
    }
    left -= e.count * e.min_bytes;
  }
  const PlyBody body{path, text, h.body, h.big_endian};
  if (h.ascii) {
    check_ascii_lists(body, h.elements);
  } else {
    check_binary_lists(body, h.elements);
  }
  return format;
}

}  // namespace l2::detail
