#include "vizserver/wire.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

namespace l2::viz {
namespace {

using ::testing::HasSubstr;

std::span<const std::uint8_t, kHeaderBytes> head_of(const std::uint8_t* p) {
  return std::span<const std::uint8_t, kHeaderBytes>(p, kHeaderBytes);
}

TEST(Wire, HelloBytesAreLittleEndianWithMagicVersionKindLengthAndToken) {
  RunToken token{};
  for (std::size_t i = 0; i < token.size(); ++i) token[i] = static_cast<std::uint8_t>(0xA0 + i);
  const auto bytes = encode(Hello{3, 0x01020304, token});
  std::vector<std::uint8_t> expected = {'L', '2', 'V', 'Z', 2, 0, 1,    0,    24,   0,
                                        0,   0,   3,   0,   0, 0, 0x04, 0x03, 0x02, 0x01};
  for (int i = 0; i < 16; ++i) expected.push_back(static_cast<std::uint8_t>(0xA0 + i));
  EXPECT_EQ(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), expected);
  const Hello back = decode_hello(std::span<const std::uint8_t>(bytes).subspan(kHeaderBytes));
  EXPECT_EQ(back.server_id, 3u);
  EXPECT_EQ(back.token, token);
}

TEST(Wire, TileHeaderRoundTripsIncludingNegativeOffsets) {
  const TileHeader t{7, 2, -5, 1200, 640, 3};
  const auto bytes = encode(t);
  const auto h = decode_header(head_of(bytes.data()));
  ASSERT_TRUE(std::holds_alternative<Header>(h));
  EXPECT_EQ(std::get<Header>(h).kind, Kind::Tile);
  EXPECT_EQ(std::get<Header>(h).payload_bytes, 24u + 640u * 3u * 3u);
  const TileHeader back = decode_tile(std::span(bytes).subspan(kHeaderBytes));
  EXPECT_EQ(back.frame, 7u);
  EXPECT_EQ(back.display, 2u);
  EXPECT_EQ(back.dx, -5);
  EXPECT_EQ(back.dy, 1200);
  EXPECT_EQ(back.w, 640u);
  EXPECT_EQ(back.h, 3u);
  // dx = -5 is 0xFFFFFFFB little-endian at payload offset 8.
  EXPECT_EQ(bytes[kHeaderBytes + 8], 0xFB);
  EXPECT_EQ(bytes[kHeaderBytes + 11], 0xFF);
}

TEST(Wire, TileExtCarriesKindAndKeyAfterTheTileFields) {
  const TileHeader t{7, 2, 3, 4, 2, 5, TileKind::Key, 0x00FF01};
  const auto bytes = encode_ext(t);
  // Kind 7, payload 32 + 2·5·3, then the TILE fields and kind 1, key 0x00ff01, little-endian.
  EXPECT_EQ(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + 12),
            (std::vector<std::uint8_t>{'L', '2', 'V', 'Z', 2, 0, 7, 0, 62, 0, 0, 0}));
  EXPECT_EQ(std::vector<std::uint8_t>(bytes.begin() + 36, bytes.end()),
            (std::vector<std::uint8_t>{1, 0, 0, 0, 0x01, 0xFF, 0x00, 0x00}));
  const auto h = decode_header(head_of(bytes.data()));
  ASSERT_TRUE(std::holds_alternative<Header>(h));
  EXPECT_EQ(std::get<Header>(h).kind, Kind::TileExt);
  const TileHeader back = decode_tile_ext(std::span(bytes).subspan(kHeaderBytes));
  EXPECT_EQ(back.how, TileKind::Key);
  EXPECT_EQ(back.key, 0x00FF01u);
  EXPECT_EQ(back.dy, 4);
  EXPECT_FALSE(validate(back, 62).has_value());
  // A DEPTH tile's rows are colour then depth: twice the bytes.
  const TileHeader depth{0, 0, 0, 0, 2, 5, TileKind::Depth, 0};
  EXPECT_EQ(depth.pixel_bytes(), 60u);
  EXPECT_FALSE(validate(depth, 92).has_value());
  EXPECT_EQ(validate(depth, 62).value_or(""),
            "TILE_EXT 2x5 needs a payload of 92 bytes, header says 62");
}

TEST(Wire, TileExtOfAnotherKindOrWithABadKeyIsRefused) {
  EXPECT_EQ(validate(TileHeader{0, 0, 0, 0, 1, 1, TileKind{3}, 0}, 35).value_or(""),
            "TILE_EXT of kind 3, expected 1 (KEY) or 2 (DEPTH)");
  EXPECT_EQ(validate(TileHeader{0, 0, 0, 0, 1, 1, TileKind::Depth, 5}, 38).value_or(""),
            "TILE_EXT DEPTH with key 5, allowed 0 only");
  EXPECT_EQ(validate(TileHeader{0, 0, 0, 0, 1, 1, TileKind::Key, 0x1000000}, 35).value_or(""),
            "TILE_EXT KEY with key 1000000, allowed 0..ffffff");
}

TEST(Wire, FrameDoneAndSwappedRoundTrip) {
  const auto done = encode(FrameDone{1, 99, 12});
  const FrameDone d = decode_frame_done(std::span(done).subspan(kHeaderBytes));
  EXPECT_EQ(d.server_id, 1u);
  EXPECT_EQ(d.frame, 99u);
  EXPECT_EQ(d.tile_count, 12u);
  const auto sw = encode(Swapped{42});
  EXPECT_EQ(decode_swapped(std::span(sw).subspan(kHeaderBytes)).frame, 42u);
  const auto w = encode(Welcome{2, 4, 3});
  const Welcome back = decode_welcome(std::span(w).subspan(kHeaderBytes));
  EXPECT_EQ(back.server_count, 3u);
}

TEST(Wire, BadMagicIsNamed) {
  const std::uint8_t http[kHeaderBytes] = {'G', 'E', 'T', ' ', '/', ' ',
                                           'H', 'T', 'T', 'P', '/', '1'};
  const auto h = decode_header(head_of(http));
  ASSERT_TRUE(std::holds_alternative<std::string>(h));
  EXPECT_THAT(std::get<std::string>(h), HasSubstr("bad magic 0x20544547"));
}

TEST(Wire, WrongVersionAndUnknownKindAreRefused) {
  auto bytes = encode(Swapped{1});
  bytes[4] = 1;  // a build from before HELLO carried the run token
  EXPECT_THAT(std::get<std::string>(decode_header(head_of(bytes.data()))),
              HasSubstr("protocol version 1, this build speaks 2"));
  bytes = encode(Swapped{1});
  bytes[6] = 9;
  EXPECT_THAT(std::get<std::string>(decode_header(head_of(bytes.data()))),
              HasSubstr("unknown message kind 9"));
}

TEST(Wire, LengthsAreBoundedPerKindBeforeAnyAllocation) {
  auto bytes = encode(FrameDone{0, 0, 0});
  put_u32(bytes.data() + 8, 13);  // FRAME_DONE is exactly 12
  EXPECT_THAT(std::get<std::string>(decode_header(head_of(bytes.data()))),
              HasSubstr("FRAME_DONE payload of 13 bytes, allowed 12..12"));
  auto tile = encode(TileHeader{0, 0, 0, 0, 1, 1});
  put_u32(tile.data() + 8, 0xFFFFFFFF);
  EXPECT_THAT(std::get<std::string>(decode_header(head_of(tile.data()))),
              HasSubstr("TILE payload of 4294967295 bytes, allowed 24..50307099"));
  put_u32(tile.data() + 8, 50307099);  // 24 + 4095*4095*3: the largest tile is allowed
  EXPECT_TRUE(std::holds_alternative<Header>(decode_header(head_of(tile.data()))));
  const auto err = encode_error_header(5000);
  EXPECT_EQ(get_u32(err.data() + 8), kMaxErrorText);
}

TEST(Wire, TilePayloadMustMatchItsSides) {
  EXPECT_FALSE(validate(TileHeader{0, 0, 0, 0, 2, 3}, 24 + 18).has_value());
  EXPECT_THAT(validate(TileHeader{0, 0, 0, 0, 2, 3}, 24 + 17).value_or(""),
              HasSubstr("TILE 2x3 needs a payload of 42 bytes, header says 41"));
  EXPECT_THAT(validate(TileHeader{0, 0, 0, 0, 0, 3}, 24).value_or(""),
              HasSubstr("each side must be 1..4095"));
  EXPECT_THAT(validate(TileHeader{0, 0, 0, 0, 4096, 1}, 24 + 4096 * 3).value_or(""),
              HasSubstr("4096x1"));
}

}  // namespace
}  // namespace l2::viz
