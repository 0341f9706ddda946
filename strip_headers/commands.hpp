// The subcommands of strip_headers, each printing to stdout and returning the exit status.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace l2::strip_headers_cli {

// `text` as an unsigned hex number of exactly `digits` digits (either case), else nullopt: no
// sign, no 0x, no spaces, and no digit left out (a short value would read as another one).
std::optional<std::uint64_t> exact_hex(const std::string& text, std::size_t digits);

int encode_header(const std::string& op, bool frame, int display, int x, int y, int width);
// kind: "key", "depth" or a raw kind 0..15 (for test frames: the key goes in unchecked).
int encode_extension(const std::string& kind, std::uint32_t key);
int decode_header(std::uint64_t value);
int decode_extension_word(std::uint64_t value);
int dump(const std::string& path, bool quiet);

}  // namespace l2::strip_headers_cli
