#include "strip_headers/strip_header.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace l2 {
namespace {

struct Vector {
  StripHeader header;
  std::uint64_t value;
};

// The test vectors of spec §2 and the header vectors of §7, copied by hand from
// ../shared/spec/strip-header.md.
const Vector kSpecVectors[] = {
    {{StripOp::End, false, 0, 0, 0, 0}, 0x000000000000},
    {{StripOp::End, true, 0, 0, 0, 0}, 0x200000000003},
    {{StripOp::Copy, false, 0, 0, 0, 256}, 0x400000000800},
    {{StripOp::Copy, true, 5, 640, 480, 320}, 0x629400f00a01},
    {{StripOp::Copy, false, 63, 4095, 4095, 4095}, 0x5ffffffffffe},
    {{StripOp::Skip, true, 0, 0, 0, 100}, 0xa00000000325},
    {{StripOp::Copy, false, 12, 1598, 1199, 2}, 0x4631f2578012},
    // §7: EXT headers, and the SKIP below a DEPTH tile of width 320 (payload 640, plus 2).
    {{StripOp::Ext, true, 3, 100, 200, 50}, 0xE18320640190},
    {{StripOp::Ext, false, 0, 0, 0, 640}, 0xC00000001405},
    {{StripOp::Skip, false, 0, 0, 0, 642}, 0x800000001415},
};

TEST(StripHeader, EncodesSpecVectors) {
  for (const auto& v : kSpecVectors) {
    EXPECT_EQ(encode(v.header), v.value) << to_string(v.header);
  }
}

TEST(StripHeader, DecodesSpecVectors) {
  for (const auto& v : kSpecVectors) {
    const auto decoded = decode(v.value);
    ASSERT_TRUE(decoded.has_value()) << std::hex << v.value;
    EXPECT_EQ(*decoded, v.header) << std::hex << v.value;
  }
}

TEST(StripHeader, AllBlackIsAValidEnd) {
  const auto h = decode(0);
  ASSERT_TRUE(h);
  EXPECT_EQ(h->op, StripOp::End);
}

StripHeader random_header(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> op(0, 3), bit(0, 1), display(0, 63), coord(0, 4095);
  return {static_cast<StripOp>(op(rng)),           bit(rng) == 1,
          static_cast<std::uint8_t>(display(rng)), static_cast<std::uint16_t>(coord(rng)),
          static_cast<std::uint16_t>(coord(rng)),  static_cast<std::uint16_t>(coord(rng))};
}

TEST(StripHeader, RandomHeadersRoundTrip) {
  std::mt19937_64 rng(42);
  for (int i = 0; i < 100000; ++i) {
    const StripHeader h = random_header(rng);
    const auto back = decode(encode(h));
    ASSERT_TRUE(back) << to_string(h);
    ASSERT_EQ(*back, h);
  }
}

TEST(StripHeader, EverySingleBitFlipIsRejected) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 2000; ++i) {
    const std::uint64_t value = encode(random_header(rng));
    for (int bit = 0; bit < 48; ++bit) {
      ASSERT_FALSE(decode(value ^ (std::uint64_t{1} << bit)))
          << std::hex << value << " bit " << std::dec << bit;
    }
  }
}

TEST(StripHeader, CheckMatchesBitwiseLongDivision) {
  // Independent reference: polynomial long division written out on a 48-bit value.
  std::mt19937_64 rng(3);
  for (int i = 0; i < 10000; ++i) {
    const std::uint64_t message = rng() & ((std::uint64_t{1} << 45) - 1);
    std::uint64_t reg = message << 3;
    for (int bit = 47; bit >= 3; --bit) {
      if ((reg >> bit) & 1) reg ^= std::uint64_t{0b1011} << (bit - 3);
    }
    ASSERT_EQ(crc3(message), reg & 7) << std::hex << message;
  }
}

TEST(StripHeader, FieldsOutOfRangeAreRefusedNotMasked) {
  EXPECT_THROW(StripHeader::copy(false, 64, 0, 0, 1), std::out_of_range);
  EXPECT_THROW(StripHeader::copy(false, 0, 4096, 0, 1), std::out_of_range);
  EXPECT_THROW(StripHeader::copy(false, 0, 0, 4096, 1), std::out_of_range);
  EXPECT_THROW(StripHeader::copy(false, 0, 0, 0, 4096), std::out_of_range);
  EXPECT_THROW(StripHeader::skip(false, -1), std::out_of_range);
  try {
    StripHeader::copy(false, 70, 0, 0, 1);
  } catch (const std::out_of_range& e) {
    EXPECT_STREQ(e.what(), "strip header field 'display' = 70 is outside 0..63");
  }
}

TEST(StripHeader, PixelsCarryTheValueMostSignificantByteFirst) {
  std::uint8_t rgb[6] = {};
  write_header_pixels(0x629400f00a01, rgb, 3);
  const std::uint8_t expected[6] = {0x62, 0x94, 0x00, 0xf0, 0x0a, 0x01};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(rgb[i], expected[i]) << i;
  EXPECT_EQ(header_value(rgb, rgb + 3), 0x629400f00a01u);

  std::uint8_t rgba[8] = {};
  write_header_pixels(0x629400f00a01, rgba, 4);
  const std::uint8_t expected_rgba[8] = {0x62, 0x94, 0x00, 255, 0xf0, 0x0a, 0x01, 255};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(rgba[i], expected_rgba[i]) << i;
  EXPECT_EQ(header_value(rgba, rgba + 4), 0x629400f00a01u);
}

TEST(StripHeader, TextFormIsReadable) {
  EXPECT_EQ(to_string(*decode(0x629400f00a01)), "COPY f=1 d=5 x=640 y=480 w=320");
}

}  // namespace
}  // namespace l2
