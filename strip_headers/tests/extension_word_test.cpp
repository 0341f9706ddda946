#include "strip_headers/extension_word.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace l2 {
namespace {

// The extension-word vectors of spec §7, copied by hand from ../shared/spec/strip-header.md.
struct ExtensionVector {
  Extension extension;
  std::uint64_t value;
};
const ExtensionVector kExtensionVectors[] = {
    {{ExtKind::Key, 0x000000}, 0x100000000032},
    {{ExtKind::Key, 0x00FF00}, 0x1000FF000019},
    {{ExtKind::Key, 0xFF00FF}, 0x10FF00FF0034},
    {{ExtKind::Depth, 0}, 0x200000000064},
};
constexpr std::uint64_t kUnsupportedKind3 = 0x300000000056;  // the table's last row

TEST(ExtensionWord, Crc8CheckValueIsF4) {
  const char* text = "123456789";
  EXPECT_EQ(crc8(reinterpret_cast<const std::uint8_t*>(text), 9), 0xF4);
}

TEST(ExtensionWord, CheckMatchesBitwiseLongDivision) {
  // Independent reference: the remainder of M(x)·x^8 divided by x^8 + x^2 + x + 1, on 48 bits.
  std::mt19937_64 rng(11);
  for (int i = 0; i < 10000; ++i) {
    const std::uint64_t message = rng() & ((std::uint64_t{1} << 40) - 1);
    std::uint64_t reg = message << 8;
    for (int bit = 47; bit >= 8; --bit) {
      if ((reg >> bit) & 1) reg ^= std::uint64_t{0x107} << (bit - 8);
    }
    ASSERT_EQ(extension_check(message << 8), reg & 0xFF) << std::hex << message;
  }
}

TEST(ExtensionWord, EncodesSpecVectors) {
  for (const auto& v : kExtensionVectors) {
    EXPECT_EQ(encode(v.extension), v.value) << to_string(v.extension);
  }
  EXPECT_EQ(with_extension_check(std::uint64_t{3} << 44), kUnsupportedKind3);
}

TEST(ExtensionWord, DecodesSpecVectors) {
  for (const auto& v : kExtensionVectors) {
    const DecodedExtension d = decode_extension(v.value);
    ASSERT_EQ(d.status, ExtensionStatus::Ok) << std::hex << v.value;
    EXPECT_EQ(d.extension, v.extension) << std::hex << v.value;
  }
  EXPECT_EQ(decode_extension(kUnsupportedKind3).status, ExtensionStatus::Unsupported);
}

TEST(ExtensionWord, EverySingleBitFlipIsACheckError) {
  std::mt19937_64 rng(5);
  for (int i = 0; i < 2000; ++i) {
    const std::uint64_t value = encode(Extension::key_colour(rng() & 0xFFFFFF));
    for (int bit = 0; bit < 48; ++bit) {
      ASSERT_EQ(decode_extension(value ^ (std::uint64_t{1} << bit)).status,
                ExtensionStatus::CheckError)
          << std::hex << value << " bit " << std::dec << bit;
    }
  }
}

TEST(ExtensionWord, KindsOtherThanKeyAndDepthAreUnsupported) {
  for (std::uint64_t kind = 0; kind < 16; ++kind) {
    const DecodedExtension d = decode_extension(with_extension_check(kind << 44));
    if (kind == 1 || kind == 2) {
      EXPECT_EQ(d.status, ExtensionStatus::Ok) << kind;
    } else {
      EXPECT_EQ(d.status, ExtensionStatus::Unsupported) << kind;
    }
  }
}

TEST(ExtensionWord, EveryMustBeZeroBitSetIsUnsupported) {
  for (std::uint64_t kind : {1, 2}) {
    for (int bit : {40, 41, 42, 43, 8, 9, 10, 11, 12, 13, 14, 15}) {
      const std::uint64_t word = with_extension_check(kind << 44 | std::uint64_t{1} << bit);
      EXPECT_EQ(decode_extension(word).status, ExtensionStatus::Unsupported)
          << "kind " << kind << " bit " << bit;
    }
  }
}

TEST(ExtensionWord, DepthWithAKeyIsUnsupported) {
  for (int bit = 16; bit < 40; ++bit) {
    const std::uint64_t word =
        with_extension_check(std::uint64_t{2} << 44 | std::uint64_t{1} << bit);
    EXPECT_EQ(decode_extension(word).status, ExtensionStatus::Unsupported) << bit;
  }
}

TEST(ExtensionWord, BitsAbove47AreIgnored) {
  const DecodedExtension d = decode_extension(0xABCD'1000FF000019);
  ASSERT_EQ(d.status, ExtensionStatus::Ok);
  EXPECT_EQ(d.extension, Extension::key_colour(0x00FF00));
}

TEST(ExtensionWord, WordsNoDecoderAcceptsAreRefused) {
  try {
    Extension::key_colour(0x1000000);
    ADD_FAILURE() << "a 25-bit key was accepted";
  } catch (const std::out_of_range& e) {
    EXPECT_STREQ(e.what(), "extension word key 1000000 is not a colour (0..ffffff)");
  }
  try {
    encode(Extension{ExtKind::Depth, 0x10});
    ADD_FAILURE() << "a DEPTH with a key was encoded";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "extension word: DEPTH carries no key (key 000010 given)");
  }
  EXPECT_THROW(encode(Extension{ExtKind::Key, 0x1000000}), std::out_of_range);
}

TEST(ExtensionWord, TextFormIsReadable) {
  EXPECT_EQ(to_string(Extension::key_colour(0x00FF00)), "KEY key=00ff00");
  EXPECT_EQ(to_string(Extension::depth()), "DEPTH");
}

}  // namespace
}  // namespace l2
