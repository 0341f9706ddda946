// strip_headers: look at routing words by hand. Encode a header from fields, decode a hex value,
// or dump every header of a scanned-out frame with the §3 error counts.
#include <fmt/format.h>

#include <charconv>
#include <cstdio>
#include <string>

#include "command_line/parse.hpp"
#include "image/png_io.hpp"
#include "strip_headers/scanline_parser.hpp"
#include "strip_headers/strip_header.hpp"

namespace {

int encode_command(const std::string& op, bool frame, int display, int x, int y, int width) {
  l2::StripHeader h;
  if (op == "end") {
    h = l2::StripHeader::end();
  } else if (op == "copy") {
    h = l2::StripHeader::copy(frame, display, x, y, width);
  } else if (op == "skip") {
    h = l2::StripHeader::skip(frame, width);
  } else {
    // The fields checked as for COPY: narrowed to their types, 300 would become display 44.
    h = l2::StripHeader::copy(frame, display, x, y, width);
    h.op = l2::StripOp::Ext;
  }
  h.frame = frame;
  fmt::print("{:012x}\n", l2::encode(h));
  return 0;
}

int decode_command(const std::string& hex) {
  // Exactly 12 hex digits, a header's 48 bits. std::stoull also took a sign, spaces and 0x, and
  // -1 as ffffffffffffffff; a shorter value was read with leading zeros, so a header with a digit
  // left out (4180500a00f) decoded as another one and was reported as a check error.
  const bool digits = !hex.empty() && hex.find_first_not_of("0123456789abcdefABCDEF") == hex.npos;
  if (!digits || hex.size() != 12) {
    fmt::print(stderr, "strip_headers: '{}' is not a 48-bit hex value (12 hex digits{})\n", hex,
               digits ? fmt::format(", not {}", hex.size()) : "");
    return 2;
  }
  std::uint64_t value = 0;
  std::from_chars(hex.data(), hex.data() + hex.size(), value, 16);
  const auto h = l2::decode(value);
  if (!h) {
    fmt::print("{:012x}: check error (expected check {}, got {})\n", value, l2::crc3(value >> 3),
               value & 7);
    return 1;
  }
  fmt::print("{:012x}: {}\n", value, l2::to_string(*h));
  return 0;
}

int dump_command(const std::string& path, bool quiet) {
  const l2::RgbImage frame = l2::read_scanned_frame(path);
  l2::StripErrorCounts total;
  long strips = 0;
  for (int y = 0; y < frame.height(); ++y) {
    l2::StripErrorCounts row_errors;
    std::string line;
    strips += l2::parse_scanline(
        frame.row(y).data(), frame.width(), 3, row_errors, [&](const l2::ParsedStrip& s) {
          line += fmt::format("  [{}] {}", s.source_x - 2, l2::to_string(s.header));
        });
    if (!quiet && (!line.empty() || row_errors.total() > 0)) {
      fmt::print("row {}:{}{}\n", y, line,
                 row_errors.total() ? fmt::format("  errors={}", row_errors.total()) : "");
    }
    total += row_errors;
  }
  fmt::print("{}: {}x{}, {} strips; check errors {}, EXT {}, zero width {}, truncations {}\n", path,
             frame.width(), frame.height(), strips, total.check_errors, total.ext_unsupported,
             total.zero_width, total.truncations);
  return total.total() == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"strip_headers: encode, decode and dump Lightning-2 strip headers (spec §2, §3)"};
  app.require_subcommand(1);

  std::string op = "copy";
  bool frame = false;
  int display = 0, x = 0, y = 0, width = 0;
  auto* enc = app.add_subcommand("encode", "Print the 48-bit value (hex) of a header");
  enc->add_option("--op", op, "end, copy, skip or ext")
      ->check(CLI::IsMember({"end", "copy", "skip", "ext"}));
  enc->add_flag("--frame", frame, "Set the frame parity bit");
  enc->add_option("--display", display, "Destination display 0..63");
  enc->add_option("--x", x, "Destination column 0..4095");
  enc->add_option("--y", y, "Destination row 0..4095");
  enc->add_option("--width", width,
                  "Strip width 0..4095 (0: a zero-width strip, which the parser counts as an "
                  "error; for making test frames)");
  // END carries no field and SKIP only a width: a field given for them would be dropped.
  enc->callback([&] {
    const bool placed = enc->count("--display") + enc->count("--x") + enc->count("--y") > 0;
    if (op == "end" && (placed || enc->count("--width") > 0))
      throw CLI::ValidationError("--op end: END has no fields (--display, --x, --y, --width)");
    if (op == "skip" && placed) throw CLI::ValidationError("--op skip: SKIP has only a --width");
  });

  std::string hex;
  auto* dec = app.add_subcommand("decode", "Decode a 48-bit hex value; exit 1 on a check error");
  dec->add_option("value", hex, "12 hex digits, e.g. 629400f00a01")->required();

  std::string path;
  bool quiet = false;
  auto* dump = app.add_subcommand(
      "dump", "List every header of a scanned-out frame (PNG) and count §3 errors; exit 1 on any");
  dump->add_option("frame", path, "Scanned-out frame, 24-bit RGB PNG")
      ->required()
      ->check(CLI::ExistingFile);
  dump->add_flag("-q,--quiet", quiet, "Only print the totals");

  if (const std::optional<int> status = l2::parse_command_line(app, argc, argv)) return *status;
  try {
    if (*enc) return encode_command(op, frame, display, x, y, width);
    if (*dec) return decode_command(hex);
    return dump_command(path, quiet);
  } catch (const std::runtime_error& e) {
    // A frame that cannot be read or holds no headers (grey, JPEG): an unusable file, exit 1
    // as in the other programs (it was 2, a usage error).
    fmt::print(stderr, "strip_headers: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "strip_headers: {}\n", e.what());
    return 2;
  }
}
