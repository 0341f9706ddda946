#include "viz_link/wire.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
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
  EXPECT_EQ(back.pipeserver_id, 3u);
  EXPECT_EQ(back.token, token);
}

TEST(Wire, TileHeaderRoundTripsIncludingNegativeOffsets) {
  const TileHeader t{7, 2, -5, 1200, 640, 3};
  const auto bytes = encode(t);
  const auto h = decode_header(head_of(bytes.data()));
  ASSERT_TRUE(h.ok());
  EXPECT_EQ(h->kind, Kind::Tile);
  EXPECT_EQ(h->payload_bytes, 24u + 640u * 3u * 3u);
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
  ASSERT_TRUE(h.ok());
  EXPECT_EQ(h->kind, Kind::TileExt);
  const TileHeader back = decode_tile_ext(std::span(bytes).subspan(kHeaderBytes));
  EXPECT_EQ(back.how, TileKind::Key);
  EXPECT_EQ(back.key, 0x00FF01u);
  EXPECT_EQ(back.dy, 4);
  EXPECT_TRUE(validate(back, 62).ok());
  // A DEPTH tile's rows are colour then depth: twice the bytes.
  const TileHeader depth{0, 0, 0, 0, 2, 5, TileKind::Depth, 0};
  EXPECT_EQ(depth.pixel_bytes(), 60u);
  EXPECT_TRUE(validate(depth, 92).ok());
  EXPECT_EQ(validate(depth, 62).reason(),
            "TILE_EXT 2x5 needs a payload of 92 bytes, header says 62");
}

TEST(Wire, TileExtOfAnotherKindOrWithABadKeyIsRefused) {
  EXPECT_EQ(validate(TileHeader{0, 0, 0, 0, 1, 1, TileKind{3}, 0}, 35).reason(),
            "TILE_EXT of kind 3, expected 1 (KEY) or 2 (DEPTH)");
  EXPECT_EQ(validate(TileHeader{0, 0, 0, 0, 1, 1, TileKind::Depth, 5}, 38).reason(),
            "TILE_EXT DEPTH with key 5, allowed 0 only");
  EXPECT_EQ(validate(TileHeader{0, 0, 0, 0, 1, 1, TileKind::Key, 0x1000000}, 35).reason(),
            "TILE_EXT KEY with key 1000000, allowed 0..ffffff");
}

TEST(Wire, FrameDoneAndSwappedRoundTrip) {
  const auto done = encode(FrameDone{1, 99, 12});
  const FrameDone d = decode_frame_done(std::span(done).subspan(kHeaderBytes));
  EXPECT_EQ(d.pipeserver_id, 1u);
  EXPECT_EQ(d.frame, 99u);
  EXPECT_EQ(d.tile_count, 12u);
  const auto sw = encode(Swapped{42});
  EXPECT_EQ(decode_swapped(std::span(sw).subspan(kHeaderBytes)).frame, 42u);
  const auto w = encode(Welcome{2, 4, 3});
  const Welcome back = decode_welcome(std::span(w).subspan(kHeaderBytes));
  EXPECT_EQ(back.pipeserver_count, 3u);
}

TEST(Wire, BadMagicIsNamed) {
  const std::uint8_t http[kHeaderBytes] = {'G', 'E', 'T', ' ', '/', ' ',
                                           'H', 'T', 'T', 'P', '/', '1'};
  const auto h = decode_header(head_of(http));
  ASSERT_FALSE(h.ok());
  EXPECT_EQ(h.reason(), "bad magic 0x20544547, expected 0x5a56324c (not a vizserver peer?)");
}

TEST(Wire, WrongVersionAndUnknownKindAreRefused) {
  auto bytes = encode(Swapped{1});
  bytes[4] = 1;  // a build from before HELLO carried the run token
  EXPECT_THAT(decode_header(head_of(bytes.data())).reason(),
              HasSubstr("protocol version 1, this build speaks 2"));
  bytes = encode(Swapped{1});
  bytes[6] = 9;
  EXPECT_THAT(decode_header(head_of(bytes.data())).reason(), HasSubstr("unknown message kind 9"));
}

TEST(Wire, LengthsAreBoundedPerKindBeforeAnyAllocation) {
  auto bytes = encode(FrameDone{0, 0, 0});
  put_u32(bytes.data() + 8, 13);  // FRAME_DONE is exactly 12
  EXPECT_THAT(decode_header(head_of(bytes.data())).reason(),
              HasSubstr("FRAME_DONE payload of 13 bytes, allowed 12..12"));
  auto tile = encode(TileHeader{0, 0, 0, 0, 1, 1});
  put_u32(tile.data() + 8, 0xFFFFFFFF);
  EXPECT_THAT(decode_header(head_of(tile.data())).reason(),
              HasSubstr("TILE payload of 4294967295 bytes, allowed 24..50307099"));
  put_u32(tile.data() + 8, 50307099);  // 24 + 4095*4095*3: the largest tile is allowed
  EXPECT_TRUE(decode_header(head_of(tile.data())).ok());
  const auto err = encode_error_header(5000);
  EXPECT_EQ(get_u32(err.data() + 8), kMaxErrorText);
}

TEST(Wire, MessageHeadTakesHeaderThenFixedPartByteByByte) {
  const auto bytes = encode(FrameDone{1, 99, 12});
  MessageHead head(Protocol::Tiles);
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    ASSERT_FALSE(head.complete()) << "complete after " << i << " bytes";
    ASSERT_EQ(head.space().size(), (i < kHeaderBytes ? kHeaderBytes : bytes.size()) - i);
    head.space()[0] = bytes[i];
    ASSERT_TRUE(head.received(1).ok());
    EXPECT_EQ(head.has_header(), i + 1 >= kHeaderBytes);
  }
  ASSERT_TRUE(head.complete());
  EXPECT_EQ(head.header().kind, Kind::FrameDone);
  EXPECT_EQ(decode_frame_done(head.fixed()).frame, 99u);
  head.clear();
  EXPECT_FALSE(head.has_header());
  EXPECT_EQ(head.space().size(), kHeaderBytes);
}

TEST(Wire, MessageHeadRefusesTheOtherProtocolsKindsOnceTheHeaderIsIn) {
  const auto swapped = encode(Swapped{3});
  MessageHead head(Protocol::DisplayStream);
  std::copy(swapped.begin(), swapped.begin() + kHeaderBytes, head.space().begin());
  const Status status = head.received(kHeaderBytes);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.reason(), "message kind 5 is not one of the display stream");
}

TEST(Wire, TilePayloadMustMatchItsSides) {
  EXPECT_TRUE(validate(TileHeader{0, 0, 0, 0, 2, 3}, 24 + 18).ok());
  EXPECT_THAT(validate(TileHeader{0, 0, 0, 0, 2, 3}, 24 + 17).reason(),
              HasSubstr("TILE 2x3 needs a payload of 42 bytes, header says 41"));
  EXPECT_THAT(validate(TileHeader{0, 0, 0, 0, 0, 3}, 24).reason(),
              HasSubstr("each side must be 1..4095"));
  EXPECT_THAT(validate(TileHeader{0, 0, 0, 0, 4096, 1}, 24 + 4096 * 3).reason(),
              HasSubstr("4096x1"));
}

}  // namespace
}  // namespace l2::viz
