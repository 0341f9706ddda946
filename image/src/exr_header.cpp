#include "image/exr_header.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <utility>

#include "byte_fields.hpp"
#include "command_line/printable.hpp"
#include "image/declared_size.hpp"

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
    return 8 + std::uint64_t{le(sides, 0, 4)} * le(sides, 4, 4) * 4;
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

std::int64_t signed32_at(const std::string& b, std::size_t at) {
  return static_cast<std::int32_t>(le(b, at, 4));
}

// What one part's header declares of its pixels: the data window's sides, for a tiled part its
// tiles' sides (zero: scanlines), the bytes of a pixel of all its channels and the lines its
// compression puts in one chunk.
struct PartShape {
  std::int64_t width = 0, height = 0;
  std::int64_t tile_width = 0, tile_height = 0;
  std::int64_t pixel_bytes = 0;
  std::int64_t chunk_lines = 1;
};

// A channel list's bytes a pixel: 4 for UINT and FLOAT, 2 for HALF, each channel as if sampled
// at every pixel (the most it may take); a channel list ends at an empty name.
std::int64_t pixel_bytes(const ReadAt& read, std::uint64_t at, std::uint64_t end) {
  std::int64_t bytes = 0;
  for (int channel = 0; channel < kMaxExrAttributes && at < end; ++channel) {
    std::string name;
    if (!text_at(read, at, 255, name) || name.empty()) break;
    bytes += le(read(at, 4), 0, 4) == 1 ? 2 : 4;
    at += 16;
  }
  return bytes;
}

// The lines of one chunk of a scanline part by its compression (OpenEXR's table: none, RLE and
// ZIPS 1, ZIP and PXR24 16, PIZ, B44, B44A and DWAA 32, DWAB 256); one it does not know, the most.
std::int64_t chunk_lines(unsigned compression) {
  static const std::int64_t kLines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
  return compression < std::size(kLines) ? kLines[compression] : 256;
}

// The fewest chunks a part's offset table lists, eight bytes each: a tiled part's tiles of its
// largest level, a scanline part's blocks of its compression's lines.
std::int64_t fewest_chunks(const PartShape& p) {
  if (p.tile_width > 0 && p.tile_height > 0) {
    return ((p.width + p.tile_width - 1) / p.tile_width) *
           ((p.height + p.tile_height - 1) / p.tile_height);
  }
  return (p.height + p.chunk_lines - 1) / p.chunk_lines;
}

std::string window_text(const PartShape& p) {
  return "an OpenEXR data window of " + std::to_string(p.width) + "x" + std::to_string(p.height) +
         " pixels";
}

// A part's data window against what any wall could use; the buffer of one chunk, which OpenEXR
// allocates as it opens the file (1.6 GB for a 300-byte file of 26 channels a million pixels
// wide, found by fuzz_picture_file), against what a reader may hold; the offset tables of the
// parts so far (`chunks`, totalled) against the file's size.
Status check_part(const PartShape& p, std::int64_t& chunks, std::uintmax_t file_size) {
  if (p.width < 1 || p.height < 1) return {};  // none, or empty or inverted: the reader's error
  if (p.width > kMaxDeclaredSide || p.height > kMaxDeclaredSide) {
    return Failure{"cannot read: " + window_text(p) + ", more than " +
                   std::to_string(kMaxDeclaredSide) + " a side"};
  }
  const bool tiled = p.tile_width > 0 && p.tile_height > 0;
  const std::int64_t chunk_width = tiled ? p.tile_width : p.width;
  const std::int64_t chunk_height = tiled ? p.tile_height : p.chunk_lines;
  const double chunk_mib = static_cast<double>(chunk_width) * static_cast<double>(chunk_height) *
                           static_cast<double>(p.pixel_bytes) / (1 << 20);
  if (chunk_mib > kMaxWholeMegabytes) {
    return Failure{"cannot read: " + window_text(p) + " of " + std::to_string(p.pixel_bytes) +
                   " bytes each, in chunks of " + std::to_string(chunk_width) + "x" +
                   std::to_string(chunk_height) + " (" + std::to_string(std::llround(chunk_mib)) +
                   " MiB decoded), more than a reader may hold (" +
                   std::to_string(std::llround(kMaxWholeMegabytes)) + " MiB)"};
  }
  chunks += fewest_chunks(p);
  if (static_cast<std::uintmax_t>(chunks) * 8 > file_size) {
    return Failure{"cannot read: " + window_text(p) + " in at least " + std::to_string(chunks) +
                   " chunks, whose offsets alone are more than the file's " +
                   std::to_string(file_size) + " bytes"};
  }
  return {};
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
  PartShape part;
  std::int64_t chunks = 0;
  for (;;) {
    std::string name, type;
    if (!text_at(read, at, longest, name)) return {};
    if (name.empty()) {
      // A header ended: the file's one, or the list of parts' at an empty header.
      if (const Status s = check_part(part, chunks, file_size); !s.ok()) return s;
      part = {};
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
    if (name == "dataWindow" && type == "box2i") {
      const std::string box = read(at, 16);
      part.width = signed32_at(box, 8) - signed32_at(box, 0) + 1;
      part.height = signed32_at(box, 12) - signed32_at(box, 4) + 1;
    } else if (name == "channels" && type == "chlist") {
      part.pixel_bytes = pixel_bytes(read, at, at + value);
    } else if (name == "compression" && type == "compression") {
      const std::string code = read(at, 1);
      if (!code.empty()) part.chunk_lines = chunk_lines(static_cast<unsigned char>(code[0]));
    } else if (name == "tiles" && type == "tiledesc") {
      const std::string tiles = read(at, 8);
      part.tile_width = le(tiles, 0, 4);
      part.tile_height = le(tiles, 4, 4);
    }
    if (++attributes > kMaxExrAttributes) {
      return Failure{"cannot read: an OpenEXR file of more than " +
                     std::to_string(kMaxExrAttributes) + " header attributes"};
    }
    at += value;
  }
}

}  // namespace l2::png_codec
