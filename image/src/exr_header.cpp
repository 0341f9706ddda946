#include "image/exr_header.hpp"

#include <string>
#include <utility>

#include "command_line/printable.hpp"

namespace l2::png_codec {

namespace {

// A name as OpenEXR reads it: up to a zero byte, or `longest` + 1 bytes when none comes first
// (the next field then starts right after them: a longer name runs into what follows, as it
// does for the reader). The text, and where the next field starts; false when the bytes end.
bool text_at(const ReadAt& read, std::uint64_t& at, std::size_t longest, std::string& text) {
  const std::string b = read(at, longest + 1);
  const std::size_t end = b.find('\0');
  if (end == std::string::npos) {
    if (b.size() < longest + 1) return false;
    text = b;
    at += b.size();
    return true;
  }
  text = b.substr(0, end);
  at += end + 1;
  return true;
}

std::uint32_t le32_at(const std::string& b, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) {
    v = v << 8 | (at + i < b.size() ? static_cast<unsigned char>(b[at + i]) : 0u);
  }
  return v;
}

// The bytes OpenEXR reads for a value of `type` at `at`, which for a type it knows is not the
// size the attribute declares: a fixed size, a channel list up to its empty name, a preview's
// pixels by its own width and height. `declared` for the rest (text, vectors, a type it does
// not know, which it allocates at that size).
std::uint64_t value_bytes(const std::string& type, std::uint32_t declared, const ReadAt& read,
                          std::uint64_t at) {
  static const std::pair<const char*, int> kFixed[] = {
      {"box2i", 16},    {"box2f", 16},   {"compression", 1},
      {"lineOrder", 1}, {"envmap", 1},   {"deepImageState", 1},
      {"float", 4},     {"double", 8},   {"int", 4},
      {"v2i", 8},       {"v2f", 8},      {"v2d", 16},
      {"v3i", 12},      {"v3f", 12},     {"v3d", 24},
      {"m33f", 36},     {"m33d", 72},    {"m44f", 64},
      {"m44d", 128},    {"rational", 8}, {"timecode", 8},
      {"keycode", 28},  {"tiledesc", 9}, {"chromaticities", 32}};
  for (const auto& [name, bytes] : kFixed) {
    if (type == name) return static_cast<std::uint64_t>(bytes);
  }
  if (type == "preview") {
    const std::string sides = read(at, 8);
    return 8 + std::uint64_t{le32_at(sides, 0)} * le32_at(sides, 4) * 4;
  }
  if (type == "chlist") {
    // Channels: a name of up to 255 characters, then 16 bytes, until an empty name.
    std::uint64_t end = at;
    for (int channel = 0; channel < kMaxExrAttributes; ++channel) {
      std::string name;
      if (!text_at(read, end, 255, name) || name.empty()) break;
      end += 16;
    }
    return end - at;
  }
  return declared;
}

}  // namespace

Status check_exr(const ReadAt& read, std::uintmax_t file_size) {
  const std::string start = read(0, 8);
  if (start.size() < 8 || start.substr(0, 4) != "\x76\x2f\x31\x01") return {};
  // Version flags: bit 12, several parts, each header ended by an empty name, and the list of
  // headers by one more.
  const bool multipart = (static_cast<unsigned char>(start[5]) & 0x10) != 0;
  // Names of up to 255 characters, whatever the long-names flag (bit 10) says: OpenEXR reads
  // them so, and a walk that stopped at 31 missed its 1.6 GB attributes behind a longer one.
  const std::size_t longest = 255;
  std::uint64_t at = 8;
  int attributes = 0;
  for (;;) {
    std::string name, type;
    if (!text_at(read, at, longest, name)) return {};
    if (name.empty()) {
      // A header ended: the file's one, or the list of parts' at an empty header.
      if (!multipart) return {};
      const std::string next = read(at, 1);
      if (next.empty() || next[0] == '\0') return {};
      continue;
    }
    if (!text_at(read, at, longest, type)) return {};
    const std::string size_bytes = read(at, 4);
    if (size_bytes.size() < 4) return {};
    std::uint32_t size = 0;
    for (int i = 3; i >= 0; --i) size = size << 8 | static_cast<unsigned char>(size_bytes[i]);
    at += 4;
    const std::uint64_t left = at <= file_size ? file_size - at : 0;
    const std::uint64_t value = value_bytes(type, size, read, at);
    if (static_cast<std::int32_t>(size) < 0 || value > left) {
      return Failure{"cannot read: an OpenEXR attribute '" + printable(name) + "' of type '" +
                     printable(type) + "' declaring " +
                     (value == size ? std::to_string(static_cast<std::int32_t>(size))
                                    : std::to_string(value)) +
                     " bytes, more than the " + std::to_string(left) + " the file has left"};
    }
    if (++attributes > kMaxExrAttributes) {
      return Failure{"cannot read: an OpenEXR file of more than " +
                     std::to_string(kMaxExrAttributes) + " header attributes"};
    }
    at += value;
  }
}

}  // namespace l2::png_codec
