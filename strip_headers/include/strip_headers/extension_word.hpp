// The 48-bit extension word of spec §7: the two pixels after an EXT header that say how its
// strip is composited, colour key (KEY) or depth (DEPTH), guarded by a CRC-8 of its own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace l2 {

inline constexpr int kExtensionPixels = 2;  // the word follows its header on the same scanline

enum class ExtKind : std::uint8_t { Key = 1, Depth = 2 };

struct Extension {
  ExtKind kind = ExtKind::Key;
  std::uint32_t key = 0;  // KEY: the key colour, R<<16 | G<<8 | B; DEPTH: 0

  friend bool operator==(const Extension&, const Extension&) = default;

  static Extension key_colour(std::uint32_t rgb);  // std::out_of_range above FFFFFF
  static Extension depth() { return {ExtKind::Depth, 0}; }
};

namespace extension_bits {
inline constexpr int kKindShift = 44;
inline constexpr int kKeyShift = 16;
inline constexpr std::uint64_t kKeyMask = 0xFFFFFF;
// Bits 43..40 and 15..8: must be 0.
inline constexpr std::uint64_t kZeroMask = std::uint64_t{0xF} << 40 | std::uint64_t{0xFF} << 8;

// CRC-8/SMBUS, one byte of the message at a time through a table built at compile time.
struct Crc8Table {
  std::uint8_t next[256]{};
  constexpr Crc8Table() {
    constexpr std::uint8_t kGenerator = 0x07;  // x^8 + x^2 + x + 1, the x^8 term implied
    for (int b = 0; b < 256; ++b) {
      std::uint8_t reg = static_cast<std::uint8_t>(b);
      for (int bit = 0; bit < 8; ++bit) {
        reg = static_cast<std::uint8_t>(reg & 0x80 ? reg << 1 ^ kGenerator : reg << 1);
      }
      next[b] = reg;
    }
  }
};
inline constexpr Crc8Table kCrc8;
}  // namespace extension_bits

// CRC-8 with generator 0x07, most significant bit first, initial register 0, no reflection, no
// final XOR (CRC-8/SMBUS).
inline std::uint8_t crc8(const std::uint8_t* bytes, std::size_t count) {
  std::uint8_t reg = 0;
  for (std::size_t i = 0; i < count; ++i) reg = extension_bits::kCrc8.next[reg ^ bytes[i]];
  return reg;
}

// The check of a word: CRC-8 of its bits 47..8, most significant byte first.
inline std::uint8_t extension_check(std::uint64_t word) {
  const std::uint8_t message[5] = {
      static_cast<std::uint8_t>(word >> 40), static_cast<std::uint8_t>(word >> 32),
      static_cast<std::uint8_t>(word >> 24), static_cast<std::uint8_t>(word >> 16),
      static_cast<std::uint8_t>(word >> 8)};
  return crc8(message, sizeof message);
}

// `word` with its low byte replaced by its check: any bit pattern, also ones no encoder makes
// (unsupported kinds, must-be-0 fields set), for test frames.
inline std::uint64_t with_extension_check(std::uint64_t word) {
  word &= ~std::uint64_t{0xFF} & ((std::uint64_t{1} << 48) - 1);
  return word | extension_check(word);
}

// X for a KEY or DEPTH word. std::invalid_argument for a DEPTH with a key (the word would be
// refused as unsupported) and std::out_of_range for a key above FFFFFF.
std::uint64_t encode(const Extension& extension);

enum class ExtensionStatus : std::uint8_t {
  Ok,
  CheckError,   // the check byte does not match bits 47..8
  Unsupported,  // kind not KEY or DEPTH, a must-be-0 field not 0, or a DEPTH with a key
};

struct DecodedExtension {
  ExtensionStatus status = ExtensionStatus::Ok;
  Extension extension;  // meaningful when status is Ok
};

// Decodes X in the order of spec §7's error table: the check first, then the fields. Bits above
// 47 are ignored.
inline DecodedExtension decode_extension(std::uint64_t word) {
  using namespace extension_bits;
  word &= (std::uint64_t{1} << 48) - 1;
  if (extension_check(word) != (word & 0xFF)) return {ExtensionStatus::CheckError, {}};
  const auto kind = static_cast<std::uint8_t>(word >> kKindShift);
  const auto key = static_cast<std::uint32_t>(word >> kKeyShift & kKeyMask);
  const bool key_kind = kind == static_cast<std::uint8_t>(ExtKind::Key);
  const bool depth_kind = kind == static_cast<std::uint8_t>(ExtKind::Depth);
  if ((word & kZeroMask) != 0 || !(key_kind || (depth_kind && key == 0))) {
    return {ExtensionStatus::Unsupported, {}};
  }
  return {ExtensionStatus::Ok, {static_cast<ExtKind>(kind), key}};
}

// "KEY key=00ff00" or "DEPTH" — for reports and error messages.
std::string to_string(const Extension& extension);

}  // namespace l2
