// strip_headers: look at routing words by hand. Encode a header or an extension word from
// fields, decode a hex value, or dump every strip of a scanned-out frame with the parser's
// error counts.
#include <fmt/format.h>

#include <cstdio>
#include <string>

#include "command_line/parse.hpp"
#include "commands.hpp"

namespace {

using l2::strip_headers_cli::exact_hex;

// --kind: a name, or a raw kind number for words no encoder makes (test frames).
CLI::Validator extension_kind() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (text == "key" || text == "depth") return {};
        const bool number = text.size() <= 2 && text.find_first_not_of("0123456789") == text.npos;
        if (number && !text.empty() && std::stoi(text) <= 15) return {};
        return "'" + text + "' is not key, depth or a kind number 0..15";
      },
      "KIND");
}

CLI::Validator key_colour() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return exact_hex(text, 6) ? "" : "'" + text + "' is not a colour RRGGBB (6 hex digits)";
      },
      "RRGGBB");
}

}  // namespace

int main(int argc, char** argv) {
  namespace cli = l2::strip_headers_cli;
  CLI::App app{
      "strip_headers: encode, decode and dump Lightning-2 strip headers and extension words "
      "(docs/strip-header.md)"};
  app.require_subcommand(1);

  std::string op = "copy";
  bool frame = false;
  int display = 0, x = 0, y = 0, width = 0;
  auto* enc = app.add_subcommand("encode", "Print the 48-bit value (hex) of a header");
  enc->add_option("--op", op, "end, copy, skip or ext (an EXT's word: the ext subcommand)")
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

  std::string kind, key_text = "000000";
  auto* ext = app.add_subcommand(
      "ext", "Print the 48-bit extension word (hex) that follows an EXT header (spec §7)");
  ext->add_option("--kind", kind,
                  "key (colour-keyed strip), depth (depth-composited strip), or a kind number "
                  "0..15 for a word a decoder must refuse (test frames)")
      ->required()
      ->check(extension_kind());
  ext->add_option("--key", key_text,
                  "KEY: the key colour, 6 hex digits RRGGBB (payload pixels of this colour are "
                  "transparent); with a kind number it fills the key field as given")
      ->check(key_colour());
  ext->callback([&] {
    if (kind == "key" && ext->count("--key") == 0)
      throw CLI::ValidationError("--kind key needs --key RRGGBB, the key colour");
    if (kind == "depth" && ext->count("--key") > 0)
      throw CLI::ValidationError("--kind depth: DEPTH carries no key (its key field must be 0)");
  });

  std::string hex;
  bool extension_word = false;
  auto* dec = app.add_subcommand(
      "decode", "Decode a 48-bit hex value; exit 1 on a check error or an unsupported word");
  dec->add_option("value", hex, "12 hex digits, e.g. 629400f00a01")->required();
  dec->add_flag("--ext", extension_word,
                "The value is an extension word (the two pixels after an EXT header), e.g. "
                "1000ff000019");

  std::string path;
  bool quiet = false;
  auto* dump = app.add_subcommand(
      "dump",
      "List every strip of a scanned-out frame (PNG): COPY, SKIP, KEY and DEPTH, each at its "
      "header's column, and count the parser's errors; exit 1 on any");
  dump->add_option("frame", path, "Scanned-out frame, 24-bit RGB PNG")
      ->required()
      ->check(CLI::ExistingFile);
  dump->add_flag("-q,--quiet", quiet, "Only print the totals");

  if (const std::optional<int> status = l2::parse_command_line(app, argc, argv)) return *status;
  try {
    if (*enc) return cli::encode_header(op, frame, display, x, y, width);
    if (*ext) {
      return cli::encode_extension(kind, static_cast<std::uint32_t>(*exact_hex(key_text, 6)));
    }
    if (*dec) {
      // Exactly 12 hex digits, a word's 48 bits. std::stoull also took a sign, spaces and 0x,
      // and -1 as ffffffffffffffff; a shorter value was read with leading zeros, so a header
      // with a digit left out (4180500a00f) decoded as another one, a check error.
      const std::optional<std::uint64_t> value = exact_hex(hex, 12);
      if (!value) {
        const bool digits =
            !hex.empty() && hex.find_first_not_of("0123456789abcdefABCDEF") == hex.npos;
        fmt::print(stderr, "strip_headers: '{}' is not a 48-bit hex value (12 hex digits{})\n", hex,
                   digits ? fmt::format(", not {}", hex.size()) : "");
        return 2;
      }
      return extension_word ? cli::decode_extension_word(*value) : cli::decode_header(*value);
    }
    return cli::dump(path, quiet);
  } catch (const std::runtime_error& e) {
    // A frame that cannot be read or holds no headers (grey, JPEG): an unusable file, exit 1
    // as in the other programs.
    fmt::print(stderr, "strip_headers: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "strip_headers: {}\n", e.what());
    return 2;
  }
}
