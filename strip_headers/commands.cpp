#include "commands.hpp"

#include <fmt/format.h>

#include <charconv>

#include "image/png_io.hpp"
#include "strip_headers/extension_word.hpp"
#include "strip_headers/scanline_parser.hpp"
#include "strip_headers/strip_header.hpp"

namespace l2::strip_headers_cli {

std::optional<std::uint64_t> exact_hex(const std::string& text, std::size_t digits) {
  if (text.size() != digits || text.find_first_not_of("0123456789abcdefABCDEF") != text.npos) {
    return std::nullopt;
  }
  std::uint64_t value = 0;
  std::from_chars(text.data(), text.data() + text.size(), value, 16);
  return value;
}

int encode_header(const std::string& op, bool frame, int display, int x, int y, int width) {
  StripHeader h;
  if (op == "end") {
    h = StripHeader::end();
  } else if (op == "copy") {
    h = StripHeader::copy(frame, display, x, y, width);
  } else if (op == "skip") {
    h = StripHeader::skip(frame, width);
  } else {
    // The fields checked as for COPY: narrowed to their types, 300 would become display 44.
    h = StripHeader::copy(frame, display, x, y, width);
    h.op = StripOp::Ext;
  }
  h.frame = frame;
  fmt::print("{:012x}\n", encode(h));
  return 0;
}

int encode_extension(const std::string& kind, std::uint32_t key) {
  std::uint64_t word = 0;
  if (kind == "key") {
    word = encode(Extension::key_colour(key));
  } else if (kind == "depth") {
    word = encode(Extension::depth());
  } else {
    word = with_extension_check(std::stoull(kind) << extension_bits::kKindShift |
                                std::uint64_t{key} << extension_bits::kKeyShift);
  }
  fmt::print("{:012x}\n", word);
  return 0;
}

int decode_header(std::uint64_t value) {
  const auto h = decode(value);
  if (!h) {
    fmt::print("{:012x}: check error (expected check {}, got {})\n", value, crc3(value >> 3),
               value & 7);
    return 1;
  }
  fmt::print("{:012x}: {}\n", value, to_string(*h));
  return 0;
}

namespace {

// Why a word whose check matched is refused, in the order decode_extension() looks.
std::string unsupported_because(std::uint64_t word) {
  using namespace extension_bits;
  const auto kind = word >> kKindShift & 0xF;
  if (kind != 1 && kind != 2) return fmt::format("kind {} (KEY is 1, DEPTH 2)", kind);
  if ((word & kZeroMask) != 0) return "bits 43..40 or 15..8, which must be 0, are not";
  return fmt::format("DEPTH with key {:06x} (must be 0)", word >> kKeyShift & kKeyMask);
}

}  // namespace

int decode_extension_word(std::uint64_t value) {
  const DecodedExtension d = decode_extension(value);
  switch (d.status) {
    case ExtensionStatus::CheckError:
      fmt::print("{:012x}: check error (expected check {:02x}, got {:02x})\n", value,
                 extension_check(value), value & 0xFF);
      return 1;
    case ExtensionStatus::Unsupported:
      fmt::print("{:012x}: EXT unsupported: {}\n", value, unsupported_because(value));
      return 1;
    case ExtensionStatus::Ok:
      break;
  }
  fmt::print("{:012x}: {}\n", value, to_string(d.extension));
  return 0;
}

namespace {

struct StripTally {
  long copy = 0, skip = 0, key = 0, depth = 0;
  long total() const { return copy + skip + key + depth; }
  void add(const ParsedStrip& s) {
    if (s.header.op == StripOp::Copy) ++copy;
    if (s.header.op == StripOp::Skip) ++skip;
    if (s.is(ExtKind::Key)) ++key;
    if (s.is(ExtKind::Depth)) ++depth;
  }
};

std::string describe(const ParsedStrip& s) {
  std::string text = fmt::format("  [{}] {}", s.header_x(), to_string(s.header));
  if (s.header.op == StripOp::Ext) text += " " + to_string(s.extension);
  return text;
}

}  // namespace

int dump(const std::string& path, bool quiet) {
  // Checked on the file's header: a picture no board would take is never allocated.
  const RgbImage frame = read_scanned_frame(path, [&](int width, int height) {
    if (width > kMaxFrameSide || height > kMaxFrameSide)
      throw std::runtime_error(fmt::format(
          "{}: a {}x{} picture is no scanned-out frame: a board takes at most {}x{} (spec §5)",
          path, width, height, kMaxFrameSide, kMaxFrameSide));
  });
  StripErrorCounts total;
  StripTally strips;
  for (int y = 0; y < frame.height(); ++y) {
    StripErrorCounts row_errors;
    std::string line;
    parse_scanline(frame.row(y).data(), frame.width(), 3, row_errors, [&](const ParsedStrip& s) {
      line += describe(s);
      strips.add(s);
    });
    if (!quiet && (!line.empty() || row_errors.total() > 0)) {
      fmt::print("row {}:{}{}\n", y, line,
                 row_errors.total() ? fmt::format("  errors={}", row_errors.total()) : "");
    }
    total += row_errors;
  }
  fmt::print(
      "{}: {}x{}, {} strips (COPY {}, SKIP {}, KEY {}, DEPTH {}); check errors {}, EXT "
      "unsupported {}, zero width {}, truncations {}\n",
      path, frame.width(), frame.height(), strips.total(), strips.copy, strips.skip, strips.key,
      strips.depth, total.check_errors, total.ext_unsupported, total.zero_width, total.truncations);
  return total.total() == 0 ? 0 : 1;
}

}  // namespace l2::strip_headers_cli
