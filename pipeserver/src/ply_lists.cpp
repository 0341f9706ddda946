#include "ply_lists.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace l2::detail {

namespace {

constexpr std::uint64_t kNoLength = 0xFFFFFFFFu;  // what a length no unsigned int holds becomes

bool is(const std::string& type, const char* a, const char* b) {
  return type == a || type == b;
}

// A length as Assimp converts it to unsigned int: a negative one wraps to near 2^32.
std::uint64_t as_length(double v) {
  return v >= 0 && v < 4294967296.0 ? static_cast<std::uint64_t>(v) : kNoLength;
}
std::uint64_t as_length(std::int64_t v) {
  return static_cast<std::uint32_t>(static_cast<std::int32_t>(v));
}

// A binary length of `type` at `p`.
std::uint64_t binary_length(const std::string& type, const char* p, std::size_t size,
                            bool big_endian) {
  unsigned char b[8] = {};
  std::memcpy(b, p, size);
  if (big_endian) std::reverse(b, b + size);
  std::uint64_t u = 0;
  for (std::size_t i = size; i-- > 0;) u = u << 8 | b[i];
  if (is(type, "float", "float32")) {
    float f;
    std::memcpy(&f, b, 4);
    return as_length(static_cast<double>(f));
  }
  if (is(type, "double", "float64")) {
    double d;
    std::memcpy(&d, b, 8);
    return as_length(d);
  }
  if (is(type, "char", "int8"))
    return as_length(static_cast<std::int64_t>(static_cast<std::int8_t>(u)));
  if (is(type, "short", "int16"))
    return as_length(static_cast<std::int64_t>(static_cast<std::int16_t>(u)));
  if (is(type, "int", "int32"))
    return as_length(static_cast<std::int64_t>(static_cast<std::int32_t>(u)));
  return u;  // unsigned
}

[[noreturn]] void too_long(const PlyBody& body, const PlyElement& e, std::uintmax_t entry,
                           const PlyProperty& p, std::uint64_t length) {
  throw std::runtime_error(fmt::format(
      "{}: {} {}: list '{}' declares {} values, more than the rest of the file can hold",
      body.path.string(), e.name, entry, p.name, length));
}

bool has_lists(const PlyElement& e) {
  return std::any_of(e.properties.begin(), e.properties.end(),
                     [](const PlyProperty& p) { return p.list; });
}

// An ASCII length at `p` (a number as Assimp parses it for the type; what follows is left).
std::uint64_t ascii_length(const std::string& type, const char* p) {
  if (is(type, "float", "float32") || is(type, "double", "float64"))
    return as_length(std::strtod(p, nullptr));
  const long long v = std::strtoll(p, nullptr, 10);
  if (type.starts_with('u')) return v < 0 ? kNoLength : static_cast<std::uint64_t>(v);
  return as_length(static_cast<std::int64_t>(v));
}

}  // namespace

void check_binary_lists(const PlyBody& body, const std::vector<PlyElement>& elements) {
  std::size_t at = body.start;
  const std::size_t end = body.text.size();
  for (const PlyElement& e : elements) {
    if (!has_lists(e)) {  // its count was checked against the file's size
      if (e.count * e.min_bytes > end - at) return;
      at += e.count * e.min_bytes;
      continue;
    }
    for (std::uintmax_t i = 0; i < e.count; ++i) {
      for (const PlyProperty& p : e.properties) {
        if (p.size == 0 || (p.list && p.count_size == 0)) return;  // Assimp refuses the type
        const std::size_t first = p.list ? p.count_size : p.size;
        if (first > end - at) return;  // cut short: Assimp says so
        if (!p.list) {
          at += first;
          continue;
        }
        const std::uint64_t n =
            binary_length(p.count_type, body.text.data() + at, p.count_size, body.big_endian);
        at += first;
        if (n > (end - at) / p.size) too_long(body, e, i, p, n);
        at += n * p.size;
      }
    }
  }
}

void check_ascii_lists(const PlyBody& body, const std::vector<PlyElement>& elements) {
  const std::string& t = body.text;
  std::size_t at = t.find_first_not_of(" \t\r\n", body.start);
  const auto token = [&](std::size_t& from, std::size_t line_end) {
    from = t.find_first_not_of(" \t", from);
    return from < line_end;
  };
  for (const PlyElement& e : elements) {
    for (std::uintmax_t i = 0; i < e.count && at < t.size(); ++i) {
      // One entry a line, as Assimp reads it.
      const std::size_t line_end = std::min(t.find('\n', at), t.size());
      std::size_t from = at;
      for (const PlyProperty& p : e.properties) {
        if (!token(from, line_end)) break;
        std::uint64_t n = 1;  // a value
        if (p.list) {
          n = ascii_length(p.count_type, t.c_str() + from);
          from = std::min(t.find_first_of(" \t\r\n", from), t.size());
          if (n > (t.size() - from + 1) / 2) too_long(body, e, i, p, n);
        }
        for (std::uint64_t v = 0; v < n && token(from, line_end); ++v)
          from = std::min(t.find_first_of(" \t\r\n", from), t.size());
      }
      at = line_end + 1;
    }
  }
}

}  // namespace l2::detail
