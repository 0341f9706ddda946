#include "off_counts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace l2::detail {

namespace {

// The header as Assimp's OFF reader walks it (OFFLoader.cpp): tokens apart by blanks and line
// ends, a line starting with '#' a comment.
struct OffHeader {
  const std::string& text;
  std::size_t at = 0;

  void next_token() {
    while (at < text.size()) {
      const char c = text[at];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
        ++at;
      } else if (c == '#') {
        at = std::min(text.find('\n', at), text.size());
      } else {
        break;
      }
    }
  }
  bool take(const char* word) {
    if (text.compare(at, std::char_traits<char>::length(word), word) != 0) return false;
    at += std::char_traits<char>::length(word);
    return true;
  }
  bool digit() const {
    return at < text.size() && std::isdigit(static_cast<unsigned char>(text[at]));
  }
  // A count, as large as it is written (Assimp reads it into 32 bits, which wraps).
  std::uint64_t count() {
    std::uint64_t n = 0;
    for (; digit(); ++at) n = std::min<std::uint64_t>(n * 10 + (text[at] - '0'), UINT64_MAX / 20);
    return n;
  }
};

bool read_as_off(const std::filesystem::path& path) {
  std::string head(3, '\0');
  std::ifstream(path, std::ios::binary).read(head.data(), 3);
  std::string ext = path.extension().string();
  for (std::string* s : {&ext, &head})
    std::transform(s->begin(), s->end(), s->begin(),
                   [](unsigned char c) { return std::tolower(c); });
  return ext == ".off" || head == "off";
}

}  // namespace

void check_off_counts(const std::filesystem::path& path) {
  if (!read_as_off(path)) return;  // a model of another format costs a look at its start
  std::ifstream in(path, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  OffHeader h{text};
  h.next_token();
  h.take("ST");
  h.take("C");
  h.take("N");
  h.take("4");
  const bool dimension = h.take("n");
  h.take("OFF");
  h.next_token();
  if (!h.digit()) return;  // Assimp: "OFF: OffHeader is invalid"
  if (dimension) {
    h.count();
    h.next_token();
  }
  const std::uint64_t vertices = h.count();
  h.next_token();
  const std::uint64_t faces = h.count();
  h.next_token();
  h.count();  // edges, unused
  // Each vertex and face is a line: a character and a line end at least (the last, no end).
  const std::uint64_t lines = (text.size() - h.at + 1) / 2;
  if (vertices + faces > lines) {
    throw std::runtime_error(
        fmt::format("{}: declares {} vertices and {} faces, more than the rest of the file can "
                    "hold (a line each)",
                    path.string(), vertices, faces));
  }
}

}  // namespace l2::detail
