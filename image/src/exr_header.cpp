#include "image/exr_header.hpp"

#include <string>

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

}  // namespace

Status check_exr(const ReadAt& read, std::uintmax_t file_size) {
  const std::string start = read(0, 8);
  if (start.size() < 8 || start.substr(0, 4) != "\x76\x2f\x31\x01") return {};
  // Version flags: bit 12, several parts, each header ended by an empty name, and the list of
  // headers by one more.
  const bool multipart = (static_cast<unsigned char>(start[5]) & 0x10) != 0;
  // Bit 10: names of up to 255 characters; else 31.
  const std::size_t longest = (static_cast<unsigned char>(start[5]) & 0x04) != 0 ? 255 : 31;
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
    if (static_cast<std::int32_t>(size) < 0 || size > left) {
      return Failure{"cannot read: an OpenEXR attribute '" + printable(name) + "' of type '" +
                     printable(type) + "' declaring " +
                     std::to_string(static_cast<std::int32_t>(size)) + " bytes, more than the " +
                     std::to_string(left) + " the file has left"};
    }
    if (++attributes > kMaxExrAttributes) {
      return Failure{"cannot read: an OpenEXR file of more than " +
                     std::to_string(kMaxExrAttributes) + " header attributes"};
    }
    at += size;
  }
}

}  // namespace l2::png_codec
